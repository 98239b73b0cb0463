// The definitions of compiled_once.hpp's explicit instantiations: this file is compiled once and
// linked into every test executable (tests/CMakeLists.txt).
#define BONL_TEST_EXTERN
#include "compiled_once.hpp"
