// The translation unit that compiles the test executables' shared precompiled header (tests/CMakeLists.txt).
