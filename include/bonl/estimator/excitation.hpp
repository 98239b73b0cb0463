#pragma once
// Whether records can excite a structure at all. identify() returns a model from any valid record,
// so a record whose input cannot determine the structure's parameters (a constant input, or a
// binary one for a polynomial of degree 2) would give a model without a word. The check here is a
// necessary condition on the number of distinct input values, not a sufficient one: enough levels
// do not promise a well-conditioned estimate, too few guarantee that some parameters are set by the
// estimator's start and forgetting rather than by the data.

#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "record_view.hpp"

namespace bonl {

/// The number of distinct values the records' inputs take, together (a constant input: 1).
/// \param records the records whose inputs are counted, checked (finite: a NaN would not sort)
/// \return the number of distinct values of u over all records
template <typename Scalar>
Eigen::Index input_levels(const CheckedRecords<Scalar>& records) {
  std::vector<Scalar> values;
  for (const auto& record : records) values.insert(values.end(), record.u.data(), record.u.data() + record.u.size());
  std::sort(values.begin(), values.end());
  return static_cast<Eigen::Index>(std::unique(values.begin(), values.end()) - values.begin());
}

namespace detail {

/// Does Model say how many input levels its structure needs (the customisation point below)?
template <class Model, class = void>
struct HasInputLevelsNeeded : std::false_type {};
template <class Model>
struct HasInputLevelsNeeded<Model, std::void_t<decltype(std::declval<const Model&>().input_levels_needed())>>
    : std::true_type {};

}  // namespace detail

/// The fewest distinct input values from which the parameters of `structure` can be determined.
/// Two for every model: a constant input (from rest at the operating point, one step) leaves the
/// dynamics' numerator and any input nonlinearity undetermined. A model whose input passes through
/// a static map of its own says more by a member `Eigen::Index input_levels_needed() const` (a
/// polynomial of degree r is fixed by r + 1 points and no fewer; a two-segment one needs that on
/// each side).
/// \param structure the model whose structure (orders) counts; its parameter values do not
/// \return the number of distinct input values it needs, >= 2
template <class Model>
Eigen::Index input_levels_needed(const Model& structure) {
  if constexpr (detail::HasInputLevelsNeeded<Model>::value) {
    return std::max<Eigen::Index>(2, structure.input_levels_needed());
  } else {
    static_cast<void>(structure);
    return 2;
  }
}

/// Why the records cannot excite `structure` (their inputs take fewer distinct values than
/// input_levels_needed()), as a sentence for a warning; empty where they can. identify() does not
/// refuse such records (the model it returns is still the best fit to them), so the caller decides:
/// the Python binding turns the sentence into a bonl.ExcitationWarning.
/// \param structure the model to identify: its orders count, its parameter values do not
/// \param records the records it is identified on, checked
/// \return the reason, or "" where the inputs have enough distinct values
template <class Model>
std::string excitation_shortfall(const Model& structure, const CheckedRecords<typename Model::Scalar>& records) {
  const Eigen::Index needed = input_levels_needed(structure);
  const Eigen::Index levels = input_levels(records);
  if (levels >= needed) return "";
  return std::string("the input takes ") + std::to_string(levels) +
         (levels == 1 ? " value (it is constant)" : " distinct values") + " but a " + Model::kName +
         " model needs at least " + std::to_string(needed) +
         " to be determined: it cannot excite the structure, and the identified parameters are not fixed by "
         "the data";
}

}  // namespace bonl
