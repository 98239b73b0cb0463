// The definitions of compiled_once.hpp's explicit instantiations for the models at the paper's
// orders (compiled_once.cpp has those at run-time orders): this file is compiled once and linked
// into every test executable (tests/CMakeLists.txt).
#define BONL_TEST_EXTERN_PAPER_ORDERS
#include "compiled_once.hpp"
