#pragma once
// The table-driven check shared by bad_input.test.cpp and plant_bad_input.test.cpp: a row's call
// must throw the expected exception type, with a message that names what was wrong.

#include <catch2/catch.hpp>
#include <functional>
#include <string>
#include <vector>

namespace bonl_test {

/// One row's call and the fragment its message must contain.
struct Case {
  std::string what;
  std::function<void()> call;
  std::string message;
};

/// Each call must throw `Exception` (an exception of another type escapes and fails the test case)
/// with a message that contains the case's fragment.
template <class Exception>
void check_cases(const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    INFO(c.what);
    bool thrown = false;
    try {
      c.call();
    } catch (const Exception& e) {
      thrown = true;
      CHECK_THAT(std::string(e.what()), Catch::Matchers::Contains(c.message));
    }
    CHECK(thrown);
  }
}

}  // namespace bonl_test
