// libFuzzer target: arbitrary bytes -> the JSON model reader (bonl/io/model_json.hpp).
//
// Contract checked (besides ASan/UBSan/LSan and no hang):
// - load_model either returns a model or throws std::invalid_argument whose message starts with
//   "bonl: model JSON: "; any other exception is a finding.
// - What it accepts is a model file by the format's rules, checked on a separate plain parse:
//   exactly the keys of the kind, format "bonl-model", version 1, integer orders in range,
//   arrays of finite numbers of the right lengths, b_0 = 1, q_1 = 1, c >= 0; and the loaded
//   model's numbers are those of the file, bit for bit.
// - The typed readers agree with load_model: model_from_json<K> (run-time orders) succeeds exactly
//   when load_model returned kind K, with bit-identical parameters; the fixed-order (paper) type
//   succeeds exactly when the orders match too; the float type exactly when every number fits in
//   a float, giving the parameters rounded to float; another kind always fails.
// - A loaded model round-trips: to_json (compact and indented) reads back to the same kind, orders
//   and bit-identical parameters, and writing that again gives the same text.

#include <bonl/io/model_json.hpp>

#include <cfloat>
#include <cmath>
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

template <class M>
struct Kinds;
template <typename S, int A, int B>
struct Kinds<bonl::ARX<S, A, B>> {
  using Dynamic = bonl::ARXd;
  using Paper = bonl::PaperARX;
  using Float = bonl::ARX<float>;
};
template <typename S, int A, int B, int R>
struct Kinds<bonl::Hammerstein<S, A, B, R>> {
  using Dynamic = bonl::Hammersteind;
  using Paper = bonl::PaperHammerstein;
  using Float = bonl::Hammerstein<float>;
};
template <typename S, int A, int B, int R, int R1>
struct Kinds<bonl::HammersteinWiener<S, A, B, R, R1>> {
  using Dynamic = bonl::HammersteinWienerd;
  using Paper = bonl::PaperHammersteinWiener;
  using Float = bonl::HammersteinWiener<float>;
};
template <typename S, int A, int B, int R>
struct Kinds<bonl::PseudoHammersteinWiener<S, A, B, R>> {
  using Dynamic = bonl::PseudoHammersteinWienerd;
  using Paper = bonl::PaperPseudoHammersteinWiener;
  using Float = bonl::PseudoHammersteinWiener<float>;
};

template <class M>
constexpr bool kBlock = !std::is_same_v<M, bonl::ARXd>;
/// The index of a run-time-order model type in AnyModel.
template <class M>
constexpr int kIndex = std::is_same_v<M, bonl::ARXd>                 ? 0
                       : std::is_same_v<M, bonl::Hammersteind>       ? 1
                       : std::is_same_v<M, bonl::HammersteinWienerd> ? 2
                                                                     : 3;
template <class M>
constexpr bool kHw = std::is_same_v<M, bonl::HammersteinWienerd>;

/// Same orders (na, nb, nk, and r, r1 where the kind has them).
template <class A, class B>
bool same_orders(const A& a, const B& b) {
  if (a.na() != b.na() || a.nb() != b.nb() || a.nk() != b.nk()) return false;
  if constexpr (kBlock<typename Kinds<A>::Dynamic>) {
    if (a.r() != b.r()) return false;
  }
  if constexpr (kHw<typename Kinds<A>::Dynamic>) {
    if (a.r1() != b.r1()) return false;
  }
  return true;
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

/// One of the twelve typed readers (4 kinds x {run-time orders, paper orders, float}); must fail.
void typed_read_must_fail(const std::string& text, unsigned which) {
  bool loaded = false;
  switch (which % 12) {
    case 0: loaded = typed_read<bonl::ARXd>(text).has_value(); break;
    case 1: loaded = typed_read<bonl::Hammersteind>(text).has_value(); break;
    case 2: loaded = typed_read<bonl::HammersteinWienerd>(text).has_value(); break;
    case 3: loaded = typed_read<bonl::PseudoHammersteinWienerd>(text).has_value(); break;
    case 4: loaded = typed_read<bonl::PaperARX>(text).has_value(); break;
    case 5: loaded = typed_read<bonl::PaperHammerstein>(text).has_value(); break;
    case 6: loaded = typed_read<bonl::PaperHammersteinWiener>(text).has_value(); break;
    case 7: loaded = typed_read<bonl::PaperPseudoHammersteinWiener>(text).has_value(); break;
    case 8: loaded = typed_read<bonl::ARX<float>>(text).has_value(); break;
    case 9: loaded = typed_read<bonl::Hammerstein<float>>(text).has_value(); break;
    case 10: loaded = typed_read<bonl::HammersteinWiener<float>>(text).has_value(); break;
    default: loaded = typed_read<bonl::PseudoHammersteinWiener<float>>(text).has_value(); break;
  }
  FUZZ_CHECK(!loaded);
}

template <class M>
bool paper_orders(const M& m) {
  if (m.na() != 3 || m.nb() != 2) return false;
  if constexpr (kBlock<M>) {
    if (m.r() != 3) return false;
  }
  if constexpr (kHw<M>) {
    if (m.r1() != 3) return false;
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

template <typename Vector>
bool numbers_ok(const nlohmann::json& value, const Vector& expected) {
  if (!value.is_array() || value.size() != static_cast<std::size_t>(expected.size())) return false;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (!value[i].is_number()) return false;
    const double x = value[i].get<double>();
    if (!std::isfinite(x) || !same_bits(&x, &expected[static_cast<Eigen::Index>(i)], 1)) return false;
  }
  return true;
}

template <class M>
void check_format(const std::string& text, const M& model) {
  constexpr std::int64_t kMax = bonl::io::kMaxModelOrder;
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  FUZZ_CHECK(!document.is_discarded());
  FUZZ_CHECK(exact_keys(document, {"format", "version", "model", "orders", "params"}));
  FUZZ_CHECK(document["format"] == "bonl-model");
  FUZZ_CHECK(document["version"].is_number_integer() && document["version"] == 1);
  const char* names[] = {"ARX", "Hammerstein", "HammersteinWiener", "PseudoHammersteinWiener"};
  FUZZ_CHECK(document["model"] == names[kIndex<M>]);
  const nlohmann::json& orders = document["orders"];
  const nlohmann::json& params = document["params"];
  // The keys first (operator[] on a const json needs them).
  if constexpr (!kBlock<M>) {
    FUZZ_CHECK(exact_keys(orders, {"na", "nb", "nk"}) && exact_keys(params, {"b", "a"}));
  } else if constexpr (kHw<M>) {
    FUZZ_CHECK(exact_keys(orders, {"na", "nb", "nk", "r", "r1"}) && exact_keys(params, {"b", "a", "f", "p", "q"}));
  } else if constexpr (std::is_same_v<M, bonl::PseudoHammersteinWienerd>) {
    FUZZ_CHECK(exact_keys(orders, {"na", "nb", "nk", "r"}) && exact_keys(params, {"b", "a", "f", "p", "c"}));
  } else {
    FUZZ_CHECK(exact_keys(orders, {"na", "nb", "nk", "r"}) && exact_keys(params, {"b", "a", "f", "p"}));
  }
  FUZZ_CHECK(order_ok(orders["na"], 1, kMax, model.na()));
  FUZZ_CHECK(order_ok(orders["nb"], 0, kMax, model.nb()));
  FUZZ_CHECK(order_ok(orders["nk"], 0, kMax, model.nk()));
  FUZZ_CHECK(numbers_ok(params["b"], model.b()) && numbers_ok(params["a"], model.a()));
  if constexpr (kBlock<M>) {
    FUZZ_CHECK(order_ok(orders["r"], 1, kMax, model.r()));
    FUZZ_CHECK(params["b"][0] == 1.0);  // b_0 = 1
    FUZZ_CHECK(numbers_ok(params["f"], model.f()) && numbers_ok(params["p"], model.p()));
  }
  if constexpr (kHw<M>) {
    FUZZ_CHECK(order_ok(orders["r1"], 2, 32, model.r1()));
    FUZZ_CHECK(numbers_ok(params["q"], model.q()) && params["q"][0] == 1.0);  // q_1 = 1
  }
  if constexpr (std::is_same_v<M, bonl::PseudoHammersteinWienerd>) {
    const nlohmann::json& c = params["c"];
    FUZZ_CHECK(c.is_number() && std::isfinite(c.get<double>()) && c.get<double>() >= 0.0);
    const double value = c.get<double>(), expected = model.c();
    FUZZ_CHECK(same_bits(&value, &expected, 1));
  }
}

template <class M>
void check_loaded(const std::string& text, const M& model, unsigned salt) {
  using K = Kinds<M>;
  check_format(text, model);

  // Run-time orders: the same model, bit for bit.
  const auto dynamic = typed_read<typename K::Dynamic>(text);
  FUZZ_CHECK(dynamic.has_value() && same_model(*dynamic, model));

  // Paper (fixed) orders: loads exactly when the file has them.
  const auto paper = typed_read<typename K::Paper>(text);
  FUZZ_CHECK(paper.has_value() == paper_orders(model));
  if (paper) FUZZ_CHECK(same_model(*paper, model));

  // float: loads exactly when every parameter fits in a float; then the parameters are rounded.
  bool fits = true;
  for (Eigen::Index i = 0; i < model.theta().size(); ++i) fits = fits && std::abs(model.theta()[i]) <= FLT_MAX;
  const auto single = typed_read<typename K::Float>(text);
  FUZZ_CHECK(single.has_value() == fits);
  if (single) {
    FUZZ_CHECK(same_orders(*single, model));
    const Eigen::VectorXf rounded = model.theta().template cast<float>();
    FUZZ_CHECK(same_bits(single->theta().data(), rounded.data(), static_cast<long>(rounded.size())));
    const auto single_again = typed_read<typename K::Float>(bonl::io::to_json(*single));
    FUZZ_CHECK(single_again.has_value() && same_model(*single_again, *single));
  }

  // Another kind never loads it.
  typed_read_must_fail(text, static_cast<unsigned>((kIndex<M> + 1 + salt % 3) % 4 + 4 * (salt / 3 % 3)));

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
    FUZZ_CHECK(again.index() == static_cast<std::size_t>(kIndex<M>));
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
  std::visit([&](const auto& model) { check_loaded(text, model, salt); }, *loaded);
  return 0;
}
