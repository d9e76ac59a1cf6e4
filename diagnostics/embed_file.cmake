# Turns a file into a C++ source with one function returning its bytes (cmake -P, at build time):
#   -DINPUT=<file> -DOUTPUT=<.cpp> -DFUNCTION=<qualified name, e.g. tomc::diagnostics::web_page>
#   -DHEADER=<include line content, e.g. tomc/diagnostics/server.hpp>
# Bytes as hex numbers: no raw-string delimiter can clash with the file's content.
file(READ "${INPUT}" content HEX)
string(LENGTH "${content}" hex_length)
math(EXPR size "${hex_length} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${content}")
string(REGEX REPLACE "(0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,)" "\\1\n" bytes "${bytes}")
string(REGEX MATCH "^(.*)::([^:]+)$" _ "${FUNCTION}")
set(namespace "${CMAKE_MATCH_1}")
set(name "${CMAKE_MATCH_2}")
file(WRITE "${OUTPUT}.tmp"
"// Generated from ${INPUT} by embed_file.cmake; do not edit.
#include <string_view>
#include \"${HEADER}\"
namespace ${namespace} {
namespace {
constexpr unsigned char kBytes[${size} + 1] = {
${bytes}0};
}  // namespace
std::string_view ${name}() noexcept { return std::string_view(reinterpret_cast<const char*>(kBytes), ${size}); }
}  // namespace ${namespace}
")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
