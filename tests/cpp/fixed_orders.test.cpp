// The fixed-order and float variants of the models (models/fixed_orders.hpp), made from bonl::Models
// and a table of orders. Oracles: the types spelled out by hand; every model of bonl::Models in the
// lists, in order; a model written here whose template parameters come in another order than its
// description's orders, and whose description ends with a run-time order.

#include "test_support.hpp"

#include <string>
#include <type_traits>

using namespace bonl_test;

static_assert(std::is_same_v<bonl::PaperARX, bonl::ARX<double, 3, 2>>);
static_assert(std::is_same_v<bonl::PaperHammerstein, bonl::Hammerstein<double, 3, 2, 3>>);
static_assert(std::is_same_v<bonl::PaperHammersteinWiener, bonl::HammersteinWiener<double, 3, 2, 3, 3>>);
static_assert(std::is_same_v<bonl::PaperPseudoHammersteinWiener, bonl::PseudoHammersteinWiener<double, 3, 2, 3>>);
static_assert(std::is_same_v<bonl::PaperWiener, bonl::Wiener<double, 3, 2, 3>>);
static_assert(std::is_same_v<bonl::WithOrders<bonl::WienerHammersteind, bonl::PaperOrders>,
                             bonl::WienerHammerstein<double, 3, 2, 3, 0, 3, 2>>);
static_assert(std::is_same_v<bonl::WithOrders<bonl::NonlinearFeedbackd, bonl::PaperOrders>,
                             bonl::NonlinearFeedback<double, 3, 2, 3, 0, 2, 0>>);
static_assert(std::is_same_v<bonl::WithOrders<bonl::PrandtlIshlinskiiHammersteind, bonl::PaperOrders>,
                             bonl::PrandtlIshlinskiiHammerstein<double, 3, 2, 3, 1>>);
static_assert(std::is_same_v<bonl::WithScalar<bonl::ARXd, float>, bonl::ARX<float>>);
static_assert(std::is_same_v<bonl::WithScalar<bonl::PaperWiener, float>, bonl::Wiener<float, 3, 2, 3>>);
static_assert(bonl::PaperOrderModels::size == bonl::Models::size);

namespace {

/// A model's description and template parameters only: its template parameters are r, then na, and
/// its description's orders na, nk, r, then a run-time order at the end.
template <typename Scalar_ = double, int R_ = Eigen::Dynamic, int Na_ = Eigen::Dynamic>
struct Sketch {
  using Scalar = Scalar_;
  static constexpr bonl::ModelDescription<4, 0> kDescription{"Sketch",
                                                             "",
                                                             {{{"na", 1, 100, Na_, ""},
                                                               {"nk", 0, 100, Eigen::Dynamic, ""},
                                                               {"r", 2, 32, R_, ""},
                                                               {"nz", 0, 100, Eigen::Dynamic, ""}}},
                                                             {}};
};

struct SketchOrders {
  static constexpr std::array<bonl::OrderValue, 2> kOrders{{{"na", 4}, {"nz", 7}}};
};

}  // namespace

static_assert(std::is_same_v<bonl::WithOrders<Sketch<>, SketchOrders>, Sketch<double, 2, 4>>,
              "na from the table, r at its minimum where the table does not name it");
static_assert(std::is_same_v<bonl::WithOrders<Sketch<>, bonl::PaperOrders>, Sketch<double, 3, 3>>);
static_assert(std::is_same_v<bonl::WithScalar<bonl::WithOrders<Sketch<>, SketchOrders>, float>, Sketch<float, 2, 4>>);

TEST_CASE("the fixed-order and float lists hold every model of bonl::Models, in order", "[fixed_orders]") {
  using Float = bonl::ModelsWithScalar<bonl::Models, float>::type;
  using FixedFloat = bonl::ModelsWithScalar<bonl::PaperOrderModels, float>::type;
  static_assert(Float::size == bonl::Models::size && FixedFloat::size == bonl::Models::size);
  std::string names, fixed, floats, fixed_floats;
  const auto append = [](std::string& to) {
    return [&to](auto tag) { to += decltype(tag)::type::kName + std::string(" "); };
  };
  bonl::for_each_model(bonl::Models{}, append(names));
  bonl::for_each_model(bonl::PaperOrderModels{}, append(fixed));
  bonl::for_each_model(Float{}, append(floats));
  bonl::for_each_model(FixedFloat{}, append(fixed_floats));
  CHECK(fixed == names);
  CHECK(floats == names);
  CHECK(fixed_floats == names);
  bonl::for_each_model(FixedFloat{},
                       [](auto tag) { static_assert(std::is_same_v<typename decltype(tag)::type::Scalar, float>); });
}

TEMPLATE_LIST_TEST_CASE("a fixed-order model takes the table's orders, and its other orders stay run-time",
                        "[fixed_orders]", bonl::PaperOrderModels) {
  constexpr auto& orders = TestType::kDescription.orders;
  std::array<Eigen::Index, orders.size()> values{};
  for (std::size_t i = 0; i < orders.size(); ++i) {
    INFO(TestType::kName << " " << orders[i].name);
    // The table by hand: the paper's orders (both W-H blocks as its one), no hinges, two feedback taps;
    // the plays at their minimum (np is not in the table: none in the nonlinear-feedback model, one in
    // the Prandtl-Ishlinskii Hammerstein model).
    const std::string name = orders[i].name;
    const Eigen::Index expected = name == "na" || name == "na1" || name == "na2"   ? 3
                                  : name == "nb" || name == "nb1" || name == "nb2" ? 2
                                  : name == "r" || name == "r1"                    ? 3
                                  : name == "nh"                                   ? 0
                                  : name == "nd"                                   ? 2
                                  : name == "np"                                   ? orders[i].minimum
                                                                                   : -1;
    // The others (the delay nk, ...) never are template parameters.
    CHECK(orders[i].fixed == (expected < 0 ? Eigen::Dynamic : expected));
    values[i] = expected < 0 ? orders[i].minimum : expected;
  }
  CHECK(bonl::make_model<TestType>(values).orders() == values);
}
