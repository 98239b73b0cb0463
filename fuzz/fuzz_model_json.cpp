// libFuzzer target: arbitrary bytes -> the JSON model reader (bonl/io/model_json.hpp).
//
// Contract checked (besides ASan/UBSan/LSan and no hang):
// - load_model either returns a model or throws std::invalid_argument whose message starts with
//   "bonl: model JSON: "; any other exception is a finding.
// - What it accepts is a model file by the format's rules, checked on a separate plain parse:
//   exactly the keys of the kind, format "bonl-model", version 1 or 2 (with the operating point and
//   the input range, held bit for bit), integer orders in range,
//   arrays of finite numbers of the right lengths, b_0 = 1, q_1 = 1, c >= 0, knots strictly
//   increasing and not 0; and the loaded model's numbers are those of the file, bit for bit.
// - The typed readers agree with load_model: model_from_json<K> (run-time orders) succeeds exactly
//   when load_model returned kind K, with bit-identical parameters; the kind's fixed-order type (at
//   bonl::PaperOrders) succeeds exactly when the orders match too, its float type exactly when every
//   number fits in a float, giving the parameters rounded to float; another kind always fails.
//   The format's rules come from each model's description (bonl/models/model_description.hpp), so
//   every model of bonl::Models is covered.
// - A loaded model round-trips: to_json (compact and indented) reads back to the same kind, orders
//   and bit-identical parameters, and writing that again gives the same text.

#include <bonl/io/model_json.hpp>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#include "fuzz_common.hpp"

namespace {

using bonl::io::AnyModel;
using bonl_fuzz::same_bits;

constexpr const char* kPrefix = "bonl: model JSON: ";

bool has_prefix(const char* message) { return std::string(message).rfind(kPrefix, 0) == 0; }

/// Every model of bonl::Models at the paper's fixed orders, and in float (at run-time orders): their
/// typed readers must agree with load_model too.
using PaperModels = bonl::PaperOrderModels;
using FloatModels = bonl::ModelsWithScalar<bonl::Models, float>::type;

/// Same kind and orders.
template <class A, class B>
bool same_orders(const A& a, const B& b) {
  if (std::string(A::kName) != B::kName) return false;
  const auto x = a.orders();
  const auto y = b.orders();
  return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin());
}

template <class A, class B>
bool same_model(const A& a, const B& b) {
  return same_orders(a, b) && a.theta().size() == b.theta().size() &&
         same_bits(a.theta().data(), b.theta().data(), static_cast<long>(a.theta().size()));
}

/// Calls model_from_json<Target>(text): the model, or nullopt after a proper invalid_argument.
template <class Target>
std::optional<Target> typed_read(const std::string& text) {
  try {
    return bonl::io::model_from_json<Target>(text);
  } catch (const std::invalid_argument& e) {
    if (!has_prefix(e.what())) {
      std::fprintf(stderr, "invalid_argument without the reader's prefix: %s\n", e.what());
      FUZZ_CHECK(false);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "model_from_json threw something other than std::invalid_argument: %s\n", e.what());
    FUZZ_CHECK(false);
  }
  return std::nullopt;
}

/// Whether model_from_json<Model>(text) loads, for the model of the list at `index`.
template <class List>
bool typed_read_at(List models, unsigned index, const std::string& text) {
  unsigned i = 0;
  bool loaded = false;
  bonl::for_each_model(models, [&](auto tag) {
    if (i++ == index) loaded = typed_read<typename decltype(tag)::type>(text).has_value();
  });
  return loaded;
}

/// One of the typed readers (every model of bonl::Models at run-time orders, then at the paper's
/// orders, then in float); must fail.
void typed_read_must_fail(const std::string& text, unsigned which) {
  constexpr unsigned kModels = bonl::Models::size;
  const unsigned kind = which % (3 * kModels);
  const bool loaded = kind < kModels       ? typed_read_at(bonl::Models{}, kind, text)
                      : kind < 2 * kModels ? typed_read_at(PaperModels{}, kind - kModels, text)
                                           : typed_read_at(FloatModels{}, kind - 2 * kModels, text);
  FUZZ_CHECK(!loaded);
}

/// The orders match Fixed's compile-time orders (where Fixed fixes them).
template <class Fixed, class M>
bool fits_fixed_orders(const M& m) {
  const auto orders = m.orders();
  for (std::size_t i = 0; i < orders.size(); ++i) {
    const int fixed = Fixed::kDescription.orders[i].fixed;
    if (fixed != Eigen::Dynamic && orders[i] != fixed) return false;
  }
  return true;
}

/// The format's rules, checked independently of the reader on a plain nlohmann parse of the same
/// text: what load_model accepted must be a bonl model file, and hold exactly the model's numbers.
bool exact_keys(const nlohmann::json& object, std::initializer_list<const char*> keys) {
  if (!object.is_object() || object.size() != keys.size()) return false;
  for (const char* key : keys) {
    if (!object.contains(key)) return false;
  }
  return true;
}

bool order_ok(const nlohmann::json& value, std::int64_t minimum, std::int64_t maximum, Eigen::Index expected) {
  if (!value.is_number_integer()) return false;
  if (value.is_number_unsigned() && value.get<std::uint64_t>() > static_cast<std::uint64_t>(maximum)) return false;
  const auto order = value.get<std::int64_t>();
  return order >= minimum && order <= maximum && order == static_cast<std::int64_t>(expected);
}

/// A finite number with the bits of `expected`.
bool number_ok(const nlohmann::json& value, double expected) {
  if (!value.is_number()) return false;
  const double x = value.get<double>();
  return std::isfinite(x) && same_bits(&x, &expected, 1);
}

template <typename Vector>
bool numbers_ok(const nlohmann::json& value, const Vector& expected) {
  if (!value.is_array() || value.size() != static_cast<std::size_t>(expected.size())) return false;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (!number_ok(value[i], expected[static_cast<Eigen::Index>(i)])) return false;
  }
  return true;
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Version 2's "operating_point" ({"u0": .., "y0": ..}) and "input_range" ([min, max], null for an
/// unbounded end, min <= max), and the model holds them bit for bit.
template <class M>
void check_operating_point_and_input_range(const nlohmann::json& point, const nlohmann::json& range, const M& model) {
  FUZZ_CHECK(exact_keys(point, {"u0", "y0"}));
  FUZZ_CHECK(number_ok(point["u0"], model.u0()) && number_ok(point["y0"], model.y0()));
  FUZZ_CHECK(range.is_array() && range.size() == 2);
  FUZZ_CHECK(range[0].is_null() ? model.input_min() == -kInfinity : number_ok(range[0], model.input_min()));
  FUZZ_CHECK(range[1].is_null() ? model.input_max() == kInfinity : number_ok(range[1], model.input_max()));
  FUZZ_CHECK(model.input_min() <= model.input_max());
}

/// "params" has a key for every block of M's description and no other, but may leave out a block
/// with no entries at the model's orders (files from before the block existed).
template <class M>
bool params_keys_ok(const nlohmann::json& params, const M& model) {
  if (!params.is_object()) return false;
  std::size_t present = 0;
  for (std::size_t i = 0; i < M::kDescription.parameters.size(); ++i) {
    if (params.contains(M::kDescription.parameters[i].name)) {
      ++present;
    } else if (model.parameter(i).size() != 0) {
      return false;
    }
  }
  return present == params.size();
}

/// The format's rules for M's description, on the plain parse of the text.
template <class M>
void check_format(const std::string& text, const M& model) {
  constexpr auto& description = M::kDescription;
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  FUZZ_CHECK(!document.is_discarded());
  FUZZ_CHECK(document.is_object() && document.contains("version") && document["version"].is_number_integer());
  // Version 2 adds the operating point and the input range; version 1 reads as 0, 0 and the whole line.
  const bool version_two = document["version"] == 2;
  FUZZ_CHECK(version_two || document["version"] == 1);
  if (version_two) {
    FUZZ_CHECK(
        exact_keys(document, {"format", "version", "model", "orders", "params", "operating_point", "input_range"}));
    check_operating_point_and_input_range(document["operating_point"], document["input_range"], model);
  } else {
    FUZZ_CHECK(exact_keys(document, {"format", "version", "model", "orders", "params"}));
    FUZZ_CHECK(model.u0() == 0.0 && model.y0() == 0.0);
    FUZZ_CHECK(model.input_min() == -kInfinity && model.input_max() == kInfinity);
  }
  FUZZ_CHECK(document["format"] == "bonl-model");
  FUZZ_CHECK(document["model"] == description.name);
  const nlohmann::json& orders = document["orders"];
  const nlohmann::json& params = document["params"];
  // The keys first (operator[] on a const json needs them). An order with a default (the integrators
  // ni) may be left out, and then the model holds its default.
  FUZZ_CHECK(orders.is_object() && params_keys_ok(params, model));
  std::size_t present = 0;
  const auto order_values = model.orders();
  for (std::size_t i = 0; i < description.orders.size(); ++i) {
    const bonl::OrderDescription& order = description.orders[i];
    if (!orders.contains(order.name)) {
      FUZZ_CHECK(order.default_value != bonl::OrderDescription::kRequired && order_values[i] == order.default_value);
      continue;
    }
    ++present;
    FUZZ_CHECK(order_ok(orders[order.name], order.minimum, order.maximum, order_values[i]));
  }
  FUZZ_CHECK(orders.size() == present);  // no key but the description's orders
  for (std::size_t i = 0; i < description.parameters.size(); ++i) {
    const bonl::ParameterDescription& parameter = description.parameters[i];
    if (!params.contains(parameter.name)) continue;  // a block with no entries (params_keys_ok)
    const nlohmann::json& value = params[parameter.name];
    const Eigen::VectorXd expected = model.parameter(i);
    if (parameter.shape == bonl::ParameterShape::Number) {
      FUZZ_CHECK(value.is_number() && std::isfinite(value.get<double>()));
      const double x = value.get<double>();
      FUZZ_CHECK(same_bits(&x, &expected[0], 1));
      if (parameter.non_negative) FUZZ_CHECK(x >= 0.0);  // c >= 0
    } else {
      FUZZ_CHECK(numbers_ok(value, expected));
      if (parameter.normalised != nullptr) FUZZ_CHECK(value[0] == 1.0);             // b_0 = 1, q_1 = 1
      for (Eigen::Index j = 0; parameter.increasing && j < expected.size(); ++j) {  // the knots
        FUZZ_CHECK(expected[j] != 0.0 && (j == 0 || expected[j - 1] < expected[j]));
      }
    }
  }
}

/// The paper-order and float typed readers of the model agree with load_model.
template <class M>
void check_variants(const std::string& text, const M& model) {
  using Paper = bonl::WithOrders<M, bonl::PaperOrders>;
  using Float = bonl::WithScalar<M, float>;
  // Paper (fixed) orders: loads exactly when the file has them.
  const auto paper = typed_read<Paper>(text);
  FUZZ_CHECK(paper.has_value() == fits_fixed_orders<Paper>(model));
  if (paper) FUZZ_CHECK(same_model(*paper, model));

  // float: loads exactly when every parameter fits in a float; then the parameters are rounded.
  bool fits = true;
  for (Eigen::Index i = 0; i < model.theta().size(); ++i) fits = fits && std::abs(model.theta()[i]) <= FLT_MAX;
  // A structure block that must be strictly increasing without a 0 (knots, thresholds) must stay so in
  // float: two close values may round to one, a tiny one to 0.
  for (std::size_t i = 0; i < M::kDescription.parameters.size(); ++i) {
    if (!M::kDescription.parameters[i].increasing) continue;
    const Eigen::VectorXf rounded_block = model.parameter(i).template cast<float>();
    fits = fits && rounded_block.allFinite() && bonl::detail::first_not_increasing_or_zero(rounded_block) < 0;
  }
  const auto single = typed_read<Float>(text);
  FUZZ_CHECK(single.has_value() == fits);
  if (single) {
    FUZZ_CHECK(same_orders(*single, model));
    const Eigen::VectorXf rounded = model.theta().template cast<float>();
    FUZZ_CHECK(same_bits(single->theta().data(), rounded.data(), static_cast<long>(rounded.size())));
    const auto single_again = typed_read<Float>(bonl::io::to_json(*single));
    FUZZ_CHECK(single_again.has_value() && same_model(*single_again, *single));
  }
}

template <class M>
void check_loaded(const std::string& text, const M& model, std::size_t index, unsigned salt) {
  check_format(text, model);

  // Run-time orders: the same model, bit for bit.
  const auto dynamic = typed_read<M>(text);
  FUZZ_CHECK(dynamic.has_value() && same_model(*dynamic, model));
  check_variants(text, model);

  // Another kind never loads it.
  constexpr unsigned kRunTime = bonl::Models::size;
  typed_read_must_fail(text, static_cast<unsigned>((index + 1 + salt % (kRunTime - 1)) % kRunTime));

  // Round trip, compact and indented.
  for (const int indent : {-1, 2}) {
    const std::string written = bonl::io::to_json(model, indent);
    std::optional<AnyModel> loaded_again;
    try {
      loaded_again = bonl::io::load_model(written);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "a written model does not read back: %s\n%s\n", e.what(), written.c_str());
      FUZZ_CHECK(false);
    }
    const AnyModel& again = *loaded_again;
    FUZZ_CHECK(again.index() == index);
    const M& back = std::get<M>(again);
    FUZZ_CHECK(same_model(back, model));
    FUZZ_CHECK(bonl::io::to_json(back, indent) == written);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  unsigned salt = 0;
  for (std::size_t i = 0; i < size; ++i) salt = salt * 31u + data[i];

  std::optional<AnyModel> loaded;
  try {
    loaded = bonl::io::load_model(text);
  } catch (const std::invalid_argument& e) {
    if (!has_prefix(e.what())) {
      std::fprintf(stderr, "invalid_argument without the reader's prefix: %s\n", e.what());
      FUZZ_CHECK(false);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "load_model threw something other than std::invalid_argument: %s\n", e.what());
    FUZZ_CHECK(false);
  }

  if (!loaded) {
    typed_read_must_fail(text, salt);  // every typed reader is at least as strict as load_model
    return 0;
  }
  std::visit([&](const auto& model) { check_loaded(text, model, loaded->index(), salt); }, *loaded);
  return 0;
}
