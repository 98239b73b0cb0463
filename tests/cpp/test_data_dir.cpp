// The one place the absolute path of tests/data is compiled in (tests/CMakeLists.txt defines
// BONL_TEST_DATA_DIR for this file only): in a definition on every test's command line it would
// make each object differ from one clone of the repository to another, and miss the compiler cache.
#include "test_data_dir.hpp"

#ifndef BONL_TEST_DATA_DIR
#error "BONL_TEST_DATA_DIR must name tests/data (tests/CMakeLists.txt defines it)"
#endif

namespace bonl_test {
const char* data_dir() { return BONL_TEST_DATA_DIR; }
}  // namespace bonl_test
