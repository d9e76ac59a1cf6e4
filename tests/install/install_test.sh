#!/usr/bin/env bash
# ctest install.consumers: installs the build into a temporary prefix, MOVES the prefix (the installed files
# must not depend on where they were installed, nor on the build tree), then builds two out-of-tree consumers
# against the moved tree only and runs them:
#   - a C++ project with find_package(tomc CONFIG REQUIRED COMPONENTS core dds)
#   - a C program compiled with `cc -std=c11 -Wall -Wextra -Werror $(pkg-config --cflags --libs tomc)`
# Both run a positioning move and check Done and the position.
#   install_test.sh <build dir> <source dir of tests/install> <source dir of the project>
set -euo pipefail
build=$1
here=$2
source=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/tomc-install-test.XXXXXX")
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/staging" > "$work/install.log"
mv "$work/staging" "$work/prefix"
prefix=$work/prefix

echo "== nothing of the build or source tree in the installed text files"
if grep -rIl -e "$build" -e "$source" -e "$work/staging" "$prefix"; then
  echo "FAIL: the files above name the build tree, the source tree or the install-time prefix"
  exit 1
fi

echo "== C++ consumer: find_package(tomc CONFIG REQUIRED COMPONENTS core dds)"
cmake -S "$here/cpp_consumer" -B "$work/cpp" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF > "$work/cpp-configure.log" \
  || { cat "$work/cpp-configure.log"; exit 1; }
cmake --build "$work/cpp" > "$work/cpp-build.log" || { cat "$work/cpp-build.log"; exit 1; }
"$work/cpp/cpp_consumer"

echo "== C consumer: cc -std=c11 -Wall -Wextra -Werror \$(pkg-config --cflags --libs tomc)"
flags=$(PKG_CONFIG_PATH= PKG_CONFIG_LIBDIR="$(dirname "$(find "$prefix" -name tomc.pc)")" \
        pkg-config --cflags --libs tomc)
echo "pkg-config: $flags"
libdir=$(dirname "$(find "$prefix" -name 'libtomc.so' | head -1)")
cc -std=c11 -Wall -Wextra -Werror -pedantic "$here/c_consumer/main.c" $flags -lm -Wl,-rpath,"$libdir" \
  -o "$work/c_consumer"
"$work/c_consumer"
echo "install.consumers: passed"
