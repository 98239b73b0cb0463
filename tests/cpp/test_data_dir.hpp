#pragma once
// Where the test data are: tests/data (test_data_dir.cpp).

namespace bonl_test {
/// The absolute path of tests/data, without a trailing slash.
const char* data_dir();
}  // namespace bonl_test
