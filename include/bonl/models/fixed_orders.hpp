#pragma once
// A model type of bonl::Models with another scalar or with its orders fixed at compile time, made
// from the model's type and a table of orders by name. The fixed-order and float variants that the
// tests, the fuzz targets and the benchmarks run over are made so from bonl::Models (models.hpp),
// which is why a new model needs no entry in any of their lists.
//
// Every model is a class template `template <typename Scalar, int... Orders> class M` whose int
// template parameters are some of its orders: each is the `fixed` of one entry of its description's
// orders (model_description.hpp). Which one is read off a probe type, M<Scalar, 2, 3, 4, ...>: the
// order whose `fixed` is 2 is the first template parameter, the one whose `fixed` is 3 the second,
// and so on. The models need to say nothing more, and an order that is never a template parameter
// (the delay nk, ...) stays a run-time order.

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <utility>

#include "model_description.hpp"

namespace bonl {

/// The value of one order, by the name the model's description gives it: an entry of a table of
/// orders (PaperOrders, models.hpp), a type with `static constexpr std::array<OrderValue, N> kOrders`.
struct OrderValue {
  const char* name;  ///< the order's name, as the model's description spells it ("na")
  int value;         ///< its value
};

namespace detail {

constexpr bool same_name(const char* a, const char* b) {
  while (*a != '\0' && *a == *b) {
    ++a;
    ++b;
  }
  return *a == *b;
}

/// The value Table gives the order `name`, or `otherwise` where it does not name it.
template <class Table>
constexpr int order_value(const char* name, int otherwise) {
  for (const OrderValue& order : Table::kOrders) {
    if (same_name(order.name, name)) return order.value;
  }
  return otherwise;
}

/// The class template of a model type and which of its orders its int template parameters are.
template <class Model>
struct ModelTemplate;

template <template <typename, int...> class M, typename Scalar, int... Orders>
struct ModelTemplate<M<Scalar, Orders...>> {
  template <typename S>
  using WithScalar = M<S, Orders...>;
  static constexpr std::size_t kTemplateOrders = sizeof...(Orders);

  /// M with template parameter k at k + 2: small values that every order accepts, all distinct.
  template <std::size_t... K>
  static M<Scalar, static_cast<int>(K + 2)...> probe(std::index_sequence<K...>);
  using Probe = decltype(probe(std::make_index_sequence<kTemplateOrders>{}));

  /// The index in the description's orders of template parameter k; the number of orders if no
  /// order, or more than one, is that parameter.
  static constexpr std::size_t order_of(std::size_t k) {
    const auto& orders = Probe::kDescription.orders;
    std::size_t found = orders.size(), matches = 0;
    for (std::size_t i = 0; i < orders.size(); ++i) {
      if (orders[i].fixed == static_cast<int>(k + 2)) {
        found = i;
        ++matches;
      }
    }
    return matches == 1 ? found : orders.size();
  }

  template <std::size_t... K>
  static constexpr bool every_parameter_is_an_order(std::index_sequence<K...>) {
    return ((order_of(K) < Probe::kDescription.orders.size()) && ...);
  }
  static_assert(every_parameter_is_an_order(std::make_index_sequence<kTemplateOrders>{}),
                "bonl: each int template parameter of a model must be one of its orders, given as `fixed` in "
                "exactly one entry of its description's orders (models/model_description.hpp)");

  /// Template parameter k's value from Table, by its order's name; the order's minimum where Table
  /// does not name it.
  template <class Table>
  static constexpr int fixed_value(std::size_t k) {
    const OrderDescription& order = Probe::kDescription.orders[order_of(k)];
    return order_value<Table>(order.name, static_cast<int>(order.minimum));
  }

  template <class Table, std::size_t... K>
  static M<Scalar, fixed_value<Table>(K)...> with_orders(std::index_sequence<K...>);
};

}  // namespace detail

/// Model in scalar type S, at the same orders: ARX<float> from ARXd, ARX<float, 3, 2> from PaperARX.
template <class Model, typename S>
using WithScalar = typename detail::ModelTemplate<Model>::template WithScalar<S>;

/// Model with every order that is a template parameter fixed at Table's value for it (or its
/// minimum where Table does not name it), in the same scalar type: ARX<double, 3, 2> from ARXd and
/// PaperOrders. The run-time orders (nk, ...) stay run-time; the constructor still takes all.
template <class Model, class Table>
using WithOrders = decltype(detail::ModelTemplate<Model>::template with_orders<Table>(
    std::make_index_sequence<detail::ModelTemplate<Model>::kTemplateOrders>{}));

/// A model of type Model at the orders Table gives, its run-time orders too (nk = 8 from PaperOrders),
/// each order Table does not name at its minimum: the structure of WithOrders<M, Table>, or of M.
/// \return the model, all parameters at its constructor's values
template <class Model, class Table>
Model make_model_at() {
  constexpr auto& orders = Model::kDescription.orders;
  std::array<Eigen::Index, orders.size()> values{};
  for (std::size_t i = 0; i < orders.size(); ++i) {
    values[i] = detail::order_value<Table>(orders[i].name, static_cast<int>(orders[i].minimum));
  }
  return make_model<Model>(values);
}

/// Every model of a list (ModelList) in scalar type S, or with the orders of Table.
template <class List, typename S>
struct ModelsWithScalar;
/// The specialisation that does the work: every model of the list in scalar type S.
template <class... Models, typename S>
struct ModelsWithScalar<ModelList<Models...>, S> {
  using type = ModelList<WithScalar<Models, S>...>;  ///< `ModelList<WithScalar<Models, S>...>`
};
template <class List, class Table>
struct ModelsWithOrders;
/// The specialisation that does the work: every model of the list at the orders of Table.
template <class... Models, class Table>
struct ModelsWithOrders<ModelList<Models...>, Table> {
  using type = ModelList<WithOrders<Models, Table>...>;  ///< `ModelList<WithOrders<Models, Table>...>`
};

}  // namespace bonl
