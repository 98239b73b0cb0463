#pragma once
// Build time only: the heavy function templates every property suite calls for every model
// (identify, select, the refinement, the recursive estimate, the known systems) are compiled once,
// in compiled_once.cpp, and declared `extern template` here so that the suites that include
// test_support.hpp do not compile them again. They were compiled in up to 20 suites each, which
// cost the CI's two builds about a quarter of their time (docs/performance.md, "The CI's time").
//
// A model missing from BONL_TEST_COMPILED_ONCE_MODELS is still tested the same way; its templates are
// only compiled in every suite that uses them.

#include "known_systems.hpp"

#include <vector>

#define BONL_TEST_COMPILED_ONCE_MODELS(X) \
  X(bonl::ARXd)                           \
  X(bonl::Hammersteind)                   \
  X(bonl::HammersteinWienerd)             \
  X(bonl::PseudoHammersteinWienerd)       \
  X(bonl::Wienerd)                        \
  X(bonl::WienerHammersteind)             \
  X(bonl::NonlinearFeedbackd)

#define BONL_TEST_PAPER_MODELS(X)     \
  X(bonl::PaperARX)                     \
  X(bonl::PaperHammerstein)             \
  X(bonl::PaperHammersteinWiener)       \
  X(bonl::PaperPseudoHammersteinWiener) \
  X(bonl::PaperWiener)

// compiled_once.cpp defines BONL_TEST_EXTERN as empty, which turns these declarations into the
// definitions.
#ifndef BONL_TEST_EXTERN
#define BONL_TEST_EXTERN extern
#endif

#define BONL_TEST_KNOWN_SYSTEM(M) BONL_TEST_EXTERN template M bonl_test::known_system<M>(const char*);

#define BONL_TEST_IDENTIFICATION(M)                                                                              \
  BONL_TEST_EXTERN template M bonl::identify(const M&, const bonl::Records<double>&, const bonl::IdentifyOptions&); \
  BONL_TEST_EXTERN template bonl::Selection<M> bonl::select(const std::vector<M>&, const bonl::Records<double>&,   \
                                                            const bonl::SelectOptions&);                          \
  BONL_TEST_EXTERN template M bonl::refine_output_error(const std::vector<M>&, const bonl::Records<double>&, int,   \
                                                        bonl::RefinementReport*);                                  \
  BONL_TEST_EXTERN template M bonl::estimate_recursively(const M&, const bonl::Records<double>&,                    \
                                                         const bonl::IdentifyOptions&);                            \
  BONL_TEST_KNOWN_SYSTEM(M)

BONL_TEST_COMPILED_ONCE_MODELS(BONL_TEST_IDENTIFICATION)
BONL_TEST_PAPER_MODELS(BONL_TEST_KNOWN_SYSTEM)
