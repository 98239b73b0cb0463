// The definitions of compiled_once.hpp's explicit instantiations for the models at run-time orders
// (compiled_once_paper_orders.cpp has those at the paper's): this file is compiled once and
// linked into every test executable (tests/CMakeLists.txt).
#define BONL_TEST_EXTERN
#include "compiled_once.hpp"
