#pragma once
// Build time only: the heavy templates every property suite uses for every model (identify, select,
// the refinement, the recursive estimate, the known systems, the estimators) are compiled once, in
// compiled_once.cpp and compiled_once_estimators.cpp, and declared `extern template` here so that
// the suites that include test_support.hpp do not compile them again (docs/lab/performance.md,
// "The CI's build time").
//
// They are instantiated for every model of bonl::Models, and known_system for every model at the
// paper's fixed orders (bonl::PaperOrders) too, by the model's index: an explicit instantiation names
// one type, and the preprocessor, which repeats it, cannot count the models of a type list. So
// BONL_TEST_EACH_MODEL(X), X(i) for every index i of bonl::Models, is written at build time by
// tests/tools/model_indices.cpp into model_indices.hpp, and a new model needs no entry here.

#include "known_systems.hpp"
#include "model_indices.hpp"

#include <cstddef>
#include <tuple>
#include <vector>

namespace bonl_test {

/// The model of bonl::Models at index I, and the same model at the paper's fixed orders (another type:
/// every model has orders that are template parameters).
template <std::size_t I>
using ModelAt = std::tuple_element_t<I, bonl::ApplyModels<bonl::Models, std::tuple>::type>;
template <std::size_t I>
using PaperModelAt = bonl::WithOrders<ModelAt<I>, bonl::PaperOrders>;

}  // namespace bonl_test

// compiled_once.cpp defines BONL_TEST_EXTERN as empty, which turns the declarations for the models at
// run-time orders into the definitions, and compiled_once_paper_orders.cpp BONL_TEST_EXTERN_PAPER_ORDERS,
// those at the paper's orders (two compiler jobs).
#ifndef BONL_TEST_EXTERN
#define BONL_TEST_EXTERN extern
#endif
#ifndef BONL_TEST_EXTERN_PAPER_ORDERS
#define BONL_TEST_EXTERN_PAPER_ORDERS extern
#endif

#define BONL_TEST_KNOWN_SYSTEM(EXTERN, M) EXTERN template M bonl_test::known_system<M>(const char*);

// The public entry points the suites call, and the checked-records overloads they forward to, which
// do the work: an explicit instantiation of a wrapper alone still instantiates its callee in every
// suite that calls the callee another way (one record's (u, y), a refinement's mask). The model
// file reader is here too: load_model, an inline function, reads every model.
#define BONL_TEST_IDENTIFICATION(EXTERN, M)                                                                          \
  EXTERN template M bonl::identify(const M&, const bonl::Records<double>&, const bonl::IdentifyOptions&,             \
                                   const bonl::ModelSettings<M>&);                                                   \
  EXTERN template M bonl::identify(const M&, const bonl::CheckedRecords<double>&, const bonl::IdentifyOptions&,      \
                                   const bonl::ModelSettings<M>&);                                                   \
  EXTERN template M bonl::refine_output_error(const std::vector<M>&, const bonl::Records<double>&, int,              \
                                              bonl::RefinementReport*, Eigen::Index);                                \
  EXTERN template M bonl::refine_output_error(const std::vector<M>&, const bonl::CheckedRecords<double>&, int,       \
                                              bonl::RefinementReport*, Eigen::Index, const M::VectorX&,              \
                                              bonl::InitialState);                                                   \
  EXTERN template M bonl::estimate_recursively(const M&, const bonl::Records<double>&, const bonl::IdentifyOptions&, \
                                               const bonl::ModelSettings<M>&);                                       \
  EXTERN template M bonl::estimate_recursively(const M&, const bonl::CheckedRecords<double>&,                        \
                                               const bonl::IdentifyOptions&, const bonl::ModelSettings<M>&);         \
  EXTERN template bool bonl::detail::simulate_record(const M&, const bonl::RecordView<double>&, Eigen::Index,        \
                                                     M::VectorX&, const M::VectorX*);                                \
  EXTERN template M bonl::rescaled(const M&, double, double);                                                        \
  EXTERN template M bonl::io::detail::model_from_document(const bonl::io::detail::Json&);                            \
  BONL_TEST_KNOWN_SYSTEM(EXTERN, M)

// Selection, for the models at run-time orders (the suites select among those alone).
#define BONL_TEST_SELECTION(EXTERN, M)                                                                        \
  EXTERN template bonl::Selection<M> bonl::select(const std::vector<M>&, const bonl::Records<double>&,        \
                                                  const bonl::SelectOptions&);                                \
  EXTERN template bonl::Selection<M> bonl::select(const std::vector<M>&, const bonl::SelectionData<double>&); \
  EXTERN template bonl::SelectionCandidate<M> bonl::score_candidate(const M&, const bonl::SelectionData<double>&);

#define BONL_TEST_COMPILED_ONCE(I)                                  \
  BONL_TEST_IDENTIFICATION(BONL_TEST_EXTERN, bonl_test::ModelAt<I>) \
  BONL_TEST_SELECTION(BONL_TEST_EXTERN, bonl_test::ModelAt<I>)      \
  BONL_TEST_IDENTIFICATION(BONL_TEST_EXTERN_PAPER_ORDERS, bonl_test::PaperModelAt<I>)

BONL_TEST_EACH_MODEL(BONL_TEST_COMPILED_ONCE)

// The estimators (their constructor and update, defined outside the class for this:
// bonl/estimator/recursive_estimator.hpp), for both orders of every model: most of a suite's
// compile time where it builds estimators. Compiled in compiled_once_estimators.cpp, which defines
// BONL_TEST_EXTERN_ESTIMATOR as empty (a third compiler job). A suite that must compile its own (one
// built with Eigen configured otherwise; none is today) defines BONL_TEST_OWN_ESTIMATORS before
// including this header. The suites that count allocations need not: they count at the C allocator
// (counting_allocator.hpp).
#ifndef BONL_TEST_EXTERN_ESTIMATOR
#define BONL_TEST_EXTERN_ESTIMATOR extern
#endif

#define BONL_TEST_ESTIMATORS(I)                                                     \
  BONL_TEST_EXTERN_ESTIMATOR template class bonl::Estimator<bonl_test::ModelAt<I>>; \
  BONL_TEST_EXTERN_ESTIMATOR template class bonl::Estimator<bonl_test::PaperModelAt<I>>;

#ifndef BONL_TEST_OWN_ESTIMATORS
BONL_TEST_EACH_MODEL(BONL_TEST_ESTIMATORS)
#endif
