// Build time only: writes the one list compiled_once.hpp cannot take from bonl::Models itself. An
// explicit instantiation names one type, and the preprocessor, which has to repeat it, cannot count
// the models of a type list; so this program, built against the same headers, writes
//   #define BONL_TEST_EACH_MODEL(X) X(0) X(1) ...
// with one X(i) per model of bonl::Models to the file its argument names (tests/CMakeLists.txt).

#include <bonl/models.hpp>

#include <cstddef>
#include <cstdio>
#include <fstream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: bonl_test_model_indices <header to write>\n");
    return 2;
  }
  std::ofstream out(argv[1]);
  out << "// Written by tests/tools/model_indices.cpp: one X(i) per model of bonl::Models.\n"
      << "#define BONL_TEST_EACH_MODEL(X)";
  for (std::size_t i = 0; i < bonl::Models::size; ++i) out << " X(" << i << ")";
  out << "\n";
  return out ? 0 : 1;
}
