// The translation unit that owns the tests' precompiled headers (tests/CMakeLists.txt).
