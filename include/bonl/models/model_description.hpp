#pragma once
// What a model says about itself, once, next to its code: its name, its orders (the constructor's
// arguments) and its parameter blocks (what its setters, the JSON file and Python call them).
// The JSON format, the Python classes, the fuzz harness and the tests are loops over these
// descriptions and over bonl::Models (models.hpp), so a new model is one header and one list entry.
//
// A model type M provides, besides what the estimator needs (models.hpp):
//   static constexpr ModelDescription<N, K> kDescription;
//   M(order_0, ..., order_{N-1});                  // in kDescription.orders' order
//   std::array<Eigen::Index, N> orders() const;
//   VectorX parameter(std::size_t i) const;        // kDescription.parameters[i]; a number is 1 entry
//   void set_parameter(std::size_t i, const VectorX& value);

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>

#include "../detail/validate.hpp"

namespace bonl {

/// One order of a model: an integer argument of its constructor.
struct OrderDescription {
  const char* name;      ///< "na"
  Eigen::Index minimum;  ///< smallest value the model accepts
  Eigen::Index maximum;  ///< largest value the model accepts
  int fixed;             ///< the compile-time value of this model type, or Eigen::Dynamic
  const char* meaning;   ///< one line for documentation: "poles of the linear block"
  /// The value where a model file or a constructor call leaves the order out (an order added after
  /// files were written: ni); kRequired where it must be given.
  Eigen::Index default_value = kRequired;
  static constexpr Eigen::Index kRequired = -1;  ///< default_value of an order that must be given
};

/// How a parameter block is stored in files and shown in Python.
enum class ParameterShape {
  Vector,  ///< an array of numbers
  Number,  ///< a single number (stored as one entry by parameter())
};

/// How a parameter block's entries carry the units of u and y. The model of y = sy * M(u / su), M a
/// model of this type, is M with the entry of index i (first_index + its position) multiplied by
///   sy^(y_power + y_power_per_index * i) * su^(u_power + u_power_per_index * i)
/// (rescaled(), models/rescale.hpp). The input polynomial's f_l: sy su^-l; an output polynomial's q_m:
/// sy^(1 - m); a backlash width: sy; the linear block's a: 1.
struct ParameterUnits {
  int y_power = 0;            ///< the power of sy in every entry
  int y_power_per_index = 0;  ///< the power of sy added per index
  int u_power = 0;            ///< the power of su in every entry
  int u_power_per_index = 0;  ///< the power of su added per index
};

/// One block of parameters, named as the model's setter (set_b) and accessor (b()) name it.
struct ParameterDescription {
  const char* name;         ///< "b"
  ParameterShape shape;     ///< a vector or a single number
  int first_index;          ///< the index of the first entry: 0 for b_0..b_nb, 1 for a_1..a_na
  const char* meaning;      ///< one line for documentation: "b_0..b_nb"
  const char* normalised;   ///< not null: the first entry is fixed to 1, for this reason
  bool non_negative;        ///< the value must be >= 0 (the backlash half-width)
  ParameterUnits units;     ///< how its entries change with the units of u and y
  bool increasing = false;  ///< the entries must be strictly increasing and not 0 (the W-H model's knots)
};

/// What a model is, stated once (its kDescription): its name, a summary, its NumOrders orders in the
/// constructor's order and its NumParameters parameter blocks in theta's order. Model files, the
/// bindings, selection and the tests read models through it.
template <std::size_t NumOrders, std::size_t NumParameters>
struct ModelDescription {
  const char* name;     ///< the model's one spelling: C++ kName, Python class, JSON "model", command line
  const char* summary;  ///< its equations in one or two sentences
  std::array<OrderDescription, NumOrders> orders;  ///< the orders, in the constructor's and orders()'s order
  std::array<ParameterDescription, NumParameters>
      parameters;  ///< the parameter blocks, in theta's order (parameter(i), set_parameter(i, value))
};

/// A list of model types (bonl::Models); Catch2's TEMPLATE_LIST_TEST_CASE accepts it as it is.
template <class... Models>
struct ModelList {
  static constexpr std::size_t size = sizeof...(Models);  ///< the number of models in the list
};

/// Stands for the type T where a value is needed: for_each_model hands one to its function.
template <class T>
struct TypeTag {
  using type = T;  ///< the type it stands for
};

/// f(TypeTag<Model>{}) for every Model of the list, in order:
/// \code
/// for_each_model(Models{}, [](auto tag) { using Model = typename decltype(tag)::type; ... });
/// \endcode
/// \param f called once per model with its TypeTag; what it returns is discarded
template <class... Models, class F>
void for_each_model(ModelList<Models...>, F&& f) {
  (f(TypeTag<Models>{}), ...);
}

/// `ApplyModels<ModelList<A, B>, T>::type` is `T<A, B>` (e.g. a std::variant of the models).
template <class List, template <class...> class T>
struct ApplyModels;
/// The specialisation that does the work: `T<Models...>`.
template <class... Models, template <class...> class T>
struct ApplyModels<ModelList<Models...>, T> {
  using type = T<Models...>;  ///< `T<Models...>`
};

/// `MapModels<ModelList<A, B>, F>::type` is `ModelList<F<A>, F<B>>` (e.g. the estimators of the models).
template <class List, template <class> class F>
struct MapModels;
/// The specialisation that does the work: `ModelList<F<Models>...>`.
template <class... Models, template <class> class F>
struct MapModels<ModelList<Models...>, F> {
  using type = ModelList<F<Models>...>;  ///< `ModelList<F<Models>...>`
};

/// `FilterModels<ModelList<A, B>, P>::type`: the models M of the list with `P<M>::value`, in order
/// (e.g. the models that have an inverse).
template <class List, template <class> class P>
struct FilterModels;
/// The end of the recursion: nothing left to filter.
template <template <class> class P>
struct FilterModels<ModelList<>, P> {
  using type = ModelList<>;  ///< the empty list
};
/// One step of the recursion: First, kept if `P<First>::value`, before the filtered rest.
template <class First, class... Rest, template <class> class P>
struct FilterModels<ModelList<First, Rest...>, P> {
 private:
  template <class List>
  struct Prepend;
  template <class... Kept>
  struct Prepend<ModelList<Kept...>> {
    using type = ModelList<First, Kept...>;
  };
  using Tail = typename FilterModels<ModelList<Rest...>, P>::type;

 public:
  using type = std::conditional_t<P<First>::value, typename Prepend<Tail>::type,
                                  Tail>;  ///< the models of the list with `P<M>::value`, in order
};

/// A model of type Model at the given orders (its constructor, called with them in order).
/// \param orders the orders in kDescription.orders' order
/// \return the model, all parameters at its constructor's values
template <class Model>
Model make_model(const std::array<Eigen::Index, Model::kDescription.orders.size()>& orders) {
  return std::make_from_tuple<Model>(orders);
}

namespace detail {

/// Every model's last order: the integrators of its linear block (of the second block where it has
/// two), poles fixed at 1 (detail/integrators.hpp); 0 where a file or a call does not give it.
inline constexpr OrderDescription kIntegratorsOrder{
    "ni", 0, 2, Eigen::Dynamic, "integrators: poles fixed at 1 in the linear block's denominator (0..2)", 0};

/// a followed by b, for descriptions that extend a shared part (the block models' front).
template <class T, std::size_t N, std::size_t M>
constexpr std::array<T, N + M> concat(const std::array<T, N>& a, const std::array<T, M>& b) {
  std::array<T, N + M> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = a[i];
  for (std::size_t i = 0; i < M; ++i) out[N + i] = b[i];
  return out;
}

[[noreturn]] inline void no_such_parameter(const char* model, std::size_t i) {
  throw std::invalid_argument("bonl: " + std::string(model) + " has no parameter block " + std::to_string(i));
}

}  // namespace detail
}  // namespace bonl
