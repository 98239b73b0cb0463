// The definitions of compiled_once.hpp's estimator instantiations (compiled_once.cpp has the
// others): this file is compiled once and linked into every test executable (tests/CMakeLists.txt).
#define BONL_TEST_EXTERN_ESTIMATOR
#include "compiled_once.hpp"
