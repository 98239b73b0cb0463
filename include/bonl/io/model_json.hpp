#pragma once
// The bonl model file: one JSON format, read and written by C++ and (through the bindings) Python,
// so that a model identified in one loads in the other and simulates the same output.
//
// Format, version 1 (keys written in this order; readers are strict: no missing or unknown keys):
//   {"format": "bonl-model", "version": 1,
//    "model": "ARX" | "Hammerstein" | "HammersteinWiener" | "PseudoHammersteinWiener",
//    "orders": {"na": .., "nb": .., "nk": .., "r": .. (block models), "r1": .. (H-W only)},
//    "params": {"b": [b_0..b_nb], "a": [a_1..a_na], "f": [f_0..f_r], "p": [p_0..p_r] (block models),
//               "q": [q_1..q_r1] (H-W), "c": number (P-H-W)}}
// Parameters follow README.md's conventions: b_0 = 1 for the block models, q_1 = 1 for H-W, c >= 0.
// Numbers are written so that they read back bit for bit (nlohmann_json prints the shortest decimal
// that round-trips a double).
//
// Needs nlohmann_json: link bonl::io (not part of bonl::bonl, nor of bonl/bonl.hpp).

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "../detail/validate.hpp"
#include "../models.hpp"
#include "../version.hpp"

namespace bonl::io {

/// The model file format version this bonl reads and writes.
inline constexpr int kModelFormatVersion = 1;
/// Largest order (na, nb, nk, r) a model file may give, the models' own limit (bonl::detail::kMaxOrder);
/// r1 is further limited to 32 by the model.
inline constexpr std::int64_t kMaxModelOrder = bonl::detail::kMaxOrder;

/// Any model a file can hold, at run-time orders (what load_model returns).
using AnyModel = std::variant<ARXd, Hammersteind, HammersteinWienerd, PseudoHammersteinWienerd>;

namespace detail {

enum class ModelKind { ARX, Hammerstein, HammersteinWiener, PseudoHammersteinWiener };

/// Which of the four model templates a type is, its name in the file, and its compile-time orders.
template <class Model>
struct ModelTraits {
  static constexpr bool kSupported = false;
};
template <typename Scalar, int Na, int Nb>
struct ModelTraits<ARX<Scalar, Na, Nb>> {
  static constexpr bool kSupported = true;
  static constexpr ModelKind kKind = ModelKind::ARX;
  static constexpr const char* kFormatName = "ARX";
  static constexpr int kNa = Na, kNb = Nb, kR = Eigen::Dynamic, kR1 = Eigen::Dynamic;
};
template <typename Scalar, int Na, int Nb, int R>
struct ModelTraits<Hammerstein<Scalar, Na, Nb, R>> {
  static constexpr bool kSupported = true;
  static constexpr ModelKind kKind = ModelKind::Hammerstein;
  static constexpr const char* kFormatName = "Hammerstein";
  static constexpr int kNa = Na, kNb = Nb, kR = R, kR1 = Eigen::Dynamic;
};
template <typename Scalar, int Na, int Nb, int R, int R1>
struct ModelTraits<HammersteinWiener<Scalar, Na, Nb, R, R1>> {
  static constexpr bool kSupported = true;
  static constexpr ModelKind kKind = ModelKind::HammersteinWiener;
  static constexpr const char* kFormatName = "HammersteinWiener";
  static constexpr int kNa = Na, kNb = Nb, kR = R, kR1 = R1;
};
template <typename Scalar, int Na, int Nb, int R>
struct ModelTraits<PseudoHammersteinWiener<Scalar, Na, Nb, R>> {
  static constexpr bool kSupported = true;
  static constexpr ModelKind kKind = ModelKind::PseudoHammersteinWiener;
  static constexpr const char* kFormatName = "PseudoHammersteinWiener";
  static constexpr int kNa = Na, kNb = Nb, kR = R, kR1 = Eigen::Dynamic;
};

/// The file's name of a model is its kName without the hyphens ("Hammerstein-Wiener" ->
/// "HammersteinWiener"); checked at compile time so that the two cannot drift apart.
constexpr bool same_without_hyphens(const char* name, const char* format_name) {
  while (true) {
    while (*name == '-') ++name;
    if (*name != *format_name) return false;
    if (*name == '\0') return true;
    ++name;
    ++format_name;
  }
}

template <class Model>
constexpr void check_model_type() {
  static_assert(ModelTraits<Model>::kSupported,
                "bonl::io reads and writes bonl::ARX, Hammerstein, HammersteinWiener and "
                "PseudoHammersteinWiener (any Scalar, fixed or Eigen::Dynamic orders) only");
  static_assert(same_without_hyphens(Model::kName, ModelTraits<Model>::kFormatName),
                "bonl::io: the model file name must be the model's kName without hyphens");
}

inline constexpr const char* kPrefix = "bonl: model JSON: ";

[[noreturn]] inline void fail(const std::string& message) { throw std::invalid_argument(kPrefix + message); }

/// Runs f, re-reporting a bonl::invalid_argument (from a model constructor or setter) as a model
/// JSON error, so that every failure of the reader carries the same prefix.
template <typename F>
auto rethrow_as_json_error(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    std::string message = e.what();
    if (message.rfind(kPrefix, 0) == 0) throw;
    if (message.rfind("bonl: ", 0) == 0) message.erase(0, 6);
    fail(message);
  }
}

using Json = nlohmann::ordered_json;

/// A short rendering of a JSON value for messages ("got ...").
inline std::string show(const Json& value) {
  std::string text = value.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

inline std::string show_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return Json(value).dump();
}

/// The text with every byte outside printable ASCII written as \xNN: a parser's message quotes the
/// bytes it stopped at, which need not be valid UTF-8 (and Python could not even decode the message).
inline std::string printable(const std::string& text) {
  static const char* const digits = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      out += c;
    } else {
      out += "\\x";
      out += digits[byte >> 4];
      out += digits[byte & 0xf];
    }
  }
  return out;
}

/// Parses text strictly: no comments, no trailing content, no key given twice in an object.
inline Json parse(const std::string& text) {
  std::vector<std::vector<std::string>> keys;  // the keys seen so far in each open object
  std::string duplicate;
  const Json::parser_callback_t check_keys = [&keys, &duplicate](int /*depth*/, Json::parse_event_t event,
                                                                 Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
        keys.emplace_back();
        break;
      case Json::parse_event_t::object_end:
        if (!keys.empty()) keys.pop_back();
        break;
      case Json::parse_event_t::key:
        if (!keys.empty() && duplicate.empty()) {
          const std::string& key = parsed.get_ref<const std::string&>();
          for (const std::string& seen : keys.back()) {
            if (seen == key) duplicate = key;
          }
          keys.back().push_back(key);
        }
        break;
      default:
        break;
    }
    return true;
  };
  Json document;
  try {
    document = Json::parse(text, check_keys);
  } catch (const nlohmann::json::parse_error& e) {
    fail("not valid JSON: " + printable(e.what()));
  } catch (const nlohmann::json::out_of_range& e) {  // a number beyond double's range, e.g. 1e400
    fail("a number is out of double's range: " + printable(e.what()));
  }
  if (!duplicate.empty()) fail("key \"" + duplicate + "\" appears more than once in an object");
  return document;
}

/// Fails on a key that is missing from, or not allowed in, the object at `where` ("" = top level).
inline void require_keys(const Json& object, const std::string& where, std::initializer_list<const char*> allowed) {
  const std::string path = where.empty() ? "" : where + ".";
  std::string listed;
  for (const char* key : allowed) listed += (listed.empty() ? "" : ", ") + std::string(key);
  for (const char* key : allowed) {
    if (!object.contains(key)) fail("missing key " + path + key);
  }
  for (const auto& item : object.items()) {
    bool known = false;
    for (const char* key : allowed) known = known || item.key() == key;
    if (!known) {
      fail("unknown key " + path + item.key() + " (expected " + (where.empty() ? "" : where + " ") + "keys: " +
           listed + ")");
    }
  }
}

/// Checks everything before "orders" and "params": a JSON object, format, version, the top-level
/// keys and the model name. Returns the model's kind.
inline ModelKind read_header(const Json& document) {
  if (!document.is_object()) fail(std::string("the document must be a JSON object, got ") + document.type_name());
  if (!document.contains("format")) fail("missing key format");
  const Json& format = document["format"];
  if (!format.is_string() || format.get_ref<const std::string&>() != "bonl-model") {
    fail("format must be \"bonl-model\", got " + show(format));
  }
  if (!document.contains("version")) fail("missing key version");
  const Json& version = document["version"];
  if (!version.is_number_integer()) fail("version must be an integer, got " + show(version));
  if (version.is_number_unsigned() ? version.get<std::uint64_t>() > std::uint64_t(kModelFormatVersion)
                                   : version.get<std::int64_t>() > kModelFormatVersion) {
    fail("version " + show(version) + " is newer than this bonl reads: it reads version " +
         std::to_string(kModelFormatVersion) + " (bonl " + std::to_string(version_major) + "." +
         std::to_string(version_minor) + "." + std::to_string(version_patch) + ")");
  }
  if (version.get<std::int64_t>() != kModelFormatVersion) {
    fail("version must be " + std::to_string(kModelFormatVersion) + ", got " + show(version));
  }
  require_keys(document, "", {"format", "version", "model", "orders", "params"});
  const Json& model = document["model"];
  if (model.is_string()) {
    const std::string& name = model.get_ref<const std::string&>();
    if (name == "ARX") return ModelKind::ARX;
    if (name == "Hammerstein") return ModelKind::Hammerstein;
    if (name == "HammersteinWiener") return ModelKind::HammersteinWiener;
    if (name == "PseudoHammersteinWiener") return ModelKind::PseudoHammersteinWiener;
  }
  fail("model must be one of \"ARX\", \"Hammerstein\", \"HammersteinWiener\", \"PseudoHammersteinWiener\", got " +
       show(model));
}

/// orders.<name>: an integer in [minimum, maximum] that matches the compile-time order when fixed.
inline Eigen::Index read_order(const Json& orders, const char* name, std::int64_t minimum, std::int64_t maximum,
                               int fixed) {
  const Json& value = orders[name];
  const std::string key = std::string("orders.") + name;
  const std::string range = key + " must be between " + std::to_string(minimum) + " and " + std::to_string(maximum);
  // An integer beyond 64 bits (e.g. 18446744073709551616) reaches here as a floating-point number.
  if (value.is_number_float() && std::abs(value.get<double>()) >= 9.2e18) fail(range + ", got " + show(value));
  if (!value.is_number_integer()) fail(key + " must be an integer, got " + show(value));
  const bool too_big = value.is_number_unsigned() && value.get<std::uint64_t>() > std::uint64_t(maximum);
  if (too_big || value.get<std::int64_t>() < minimum || value.get<std::int64_t>() > maximum) {
    fail(range + ", got " + show(value));
  }
  const auto order = static_cast<Eigen::Index>(value.get<std::int64_t>());
  if (fixed != Eigen::Dynamic && order != fixed) {
    fail(key + " = " + std::to_string(order) + " does not match the model type's compile-time order " +
         std::to_string(fixed));
  }
  return order;
}

/// A finite number that the model's Scalar can hold; `key` names it in messages.
template <typename Scalar>
double read_number(const Json& value, const std::string& key) {
  if (!value.is_number()) fail(key + " must be a number, got " + show(value));
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(key + " must be finite, got " + show_number(x));
  if constexpr (std::numeric_limits<Scalar>::is_specialized) {
    if (std::abs(x) > static_cast<double>(std::numeric_limits<Scalar>::max())) {
      fail(key + " = " + show_number(x) + " is out of the model's Scalar range");
    }
  }
  return x;
}

/// params.<name>: an array of `size` finite numbers.
template <typename Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, 1> read_vector(const Json& params, const char* name, Eigen::Index size) {
  const Json& value = params[name];
  const std::string key = std::string("params.") + name;
  if (!value.is_array()) fail(key + " must be an array of numbers, got " + show(value));
  if (static_cast<Eigen::Index>(value.size()) != size) {
    fail(key + " must have " + std::to_string(size) + " entries, got " + std::to_string(value.size()));
  }
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> v(size);
  for (Eigen::Index i = 0; i < size; ++i) {
    const std::string at = key + "[" + std::to_string(i) + "]";
    v[i] = static_cast<Scalar>(read_number<Scalar>(value[static_cast<std::size_t>(i)], at));
  }
  return v;
}

template <typename Vector>
void require_leading_one(const Vector& v, const char* key, const char* why) {
  if (!(v[0] == 1)) {
    fail(std::string(key) + "[0] must be 1 (" + why + "), got " + show_number(static_cast<double>(v[0])));
  }
}

template <typename Vector>
Json to_array(const Vector& v) {
  Json array = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) array.push_back(static_cast<double>(v[i]));
  return array;
}

/// Reads a parsed document into Model; read_header has not been run on it yet.
template <class Model>
Model model_from_document(const Json& document) {
  using Traits = ModelTraits<Model>;
  using Scalar = typename Model::Scalar;
  constexpr ModelKind kind = Traits::kKind;
  constexpr bool block = kind != ModelKind::ARX;
  constexpr bool hw = kind == ModelKind::HammersteinWiener;
  constexpr bool phw = kind == ModelKind::PseudoHammersteinWiener;

  if (read_header(document) != kind) {
    fail("model is " + show(document["model"]) + ", but the model type asked for is \"" + Traits::kFormatName + "\"");
  }

  const Json& orders = document["orders"];
  if (!orders.is_object()) fail("orders must be an object, got " + show(orders));
  if constexpr (hw) {
    require_keys(orders, "orders", {"na", "nb", "nk", "r", "r1"});
  } else if constexpr (block) {
    require_keys(orders, "orders", {"na", "nb", "nk", "r"});
  } else {
    require_keys(orders, "orders", {"na", "nb", "nk"});
  }
  const Eigen::Index na = read_order(orders, "na", 1, kMaxModelOrder, Traits::kNa);
  const Eigen::Index nb = read_order(orders, "nb", 0, kMaxModelOrder, Traits::kNb);
  const Eigen::Index nk = read_order(orders, "nk", 0, kMaxModelOrder, Eigen::Dynamic);
  [[maybe_unused]] const Eigen::Index r = block ? read_order(orders, "r", 1, kMaxModelOrder, Traits::kR) : 0;
  [[maybe_unused]] const Eigen::Index r1 = hw ? read_order(orders, "r1", 2, 32, Traits::kR1) : 0;

  const Json& params = document["params"];
  if (!params.is_object()) fail("params must be an object, got " + show(params));
  if constexpr (hw) {
    require_keys(params, "params", {"b", "a", "f", "p", "q"});
  } else if constexpr (phw) {
    require_keys(params, "params", {"b", "a", "f", "p", "c"});
  } else if constexpr (block) {
    require_keys(params, "params", {"b", "a", "f", "p"});
  } else {
    require_keys(params, "params", {"b", "a"});
  }
  const auto b = read_vector<Scalar>(params, "b", nb + 1);
  const auto a = read_vector<Scalar>(params, "a", na);
  if constexpr (block) require_leading_one(b, "params.b", "block models are normalised so that b_0 = 1");

  return rethrow_as_json_error([&]() {
    if constexpr (!block) {
      Model model(na, nb, nk);
      model.set_b(b);
      model.set_a(a);
      return model;
    } else {
      const auto f = read_vector<Scalar>(params, "f", r + 1);
      const auto p = read_vector<Scalar>(params, "p", r + 1);
      auto make = [&]() {
        if constexpr (hw) {
          return Model(na, nb, nk, r, r1);
        } else {
          return Model(na, nb, nk, r);
        }
      };
      Model model = make();
      model.set_f(f);
      model.set_p(p);
      model.set_b(b);
      model.set_a(a);
      if constexpr (hw) {
        const auto q = read_vector<Scalar>(params, "q", r1);
        require_leading_one(q, "params.q", "the H-W model is normalised so that q_1 = 1");
        model.set_q(q);
      }
      if constexpr (phw) {
        const double value = read_number<Scalar>(params["c"], "params.c");
        if (!(value >= 0)) fail("params.c (backlash half-width) must be >= 0, got " + show_number(value));
        model.set_c(static_cast<Scalar>(value));
      }
      return model;
    }
  });
}

/// Never lets a nlohmann exception out: anything the checks above missed becomes invalid_argument.
template <typename F>
auto guard(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const nlohmann::json::exception& e) {
    fail(printable(e.what()));
  }
}

}  // namespace detail

/// The model as a bonl model file (format version 1). indent < 0: one line; otherwise pretty-printed
/// with that many spaces per level. Works for all four models, any Scalar, fixed or dynamic orders.
template <class Model>
std::string to_json(const Model& model, int indent = -1) {
  detail::check_model_type<Model>();
  using Traits = detail::ModelTraits<Model>;
  using detail::Json;
  constexpr detail::ModelKind kind = Traits::kKind;
  constexpr bool block = kind != detail::ModelKind::ARX;

  return detail::guard([&]() {
    Json orders = Json::object();
    orders["na"] = static_cast<std::int64_t>(model.na());
    orders["nb"] = static_cast<std::int64_t>(model.nb());
    orders["nk"] = static_cast<std::int64_t>(model.nk());
    Json params = Json::object();
    params["b"] = detail::to_array(model.b());
    params["a"] = detail::to_array(model.a());
    if constexpr (block) {
      orders["r"] = static_cast<std::int64_t>(model.r());
      params["f"] = detail::to_array(model.f());
      params["p"] = detail::to_array(model.p());
    }
    if constexpr (kind == detail::ModelKind::HammersteinWiener) {
      orders["r1"] = static_cast<std::int64_t>(model.r1());
      params["q"] = detail::to_array(model.q());
    }
    if constexpr (kind == detail::ModelKind::PseudoHammersteinWiener) {
      params["c"] = static_cast<double>(model.c());
    }
    Json document = Json::object();
    document["format"] = "bonl-model";
    document["version"] = kModelFormatVersion;
    document["model"] = Traits::kFormatName;
    document["orders"] = std::move(orders);
    document["params"] = std::move(params);
    return document.dump(indent);
  });
}

/// Reads a bonl model file into the given model type (e.g. bonl::PaperPseudoHammersteinWiener or
/// bonl::PseudoHammersteinWienerd). Throws std::invalid_argument, with a message that starts with
/// "bonl: model JSON: " and names the key at fault, for invalid JSON, another format, a newer
/// version, another model kind, missing or unknown keys, orders out of range or different from the
/// type's compile-time orders, arrays of the wrong length, non-finite numbers, b_0 or q_1 not 1, c < 0.
template <class Model>
Model model_from_json(const std::string& text) {
  detail::check_model_type<Model>();
  return detail::guard([&]() { return detail::model_from_document<Model>(detail::parse(text)); });
}

/// Reads a bonl model file of any kind, at run-time orders; the variant holds the kind the file
/// names. Throws as model_from_json does.
inline AnyModel load_model(const std::string& text) {
  return detail::guard([&]() -> AnyModel {
    const detail::Json document = detail::parse(text);
    switch (detail::read_header(document)) {
      case detail::ModelKind::ARX:
        return detail::model_from_document<ARXd>(document);
      case detail::ModelKind::Hammerstein:
        return detail::model_from_document<Hammersteind>(document);
      case detail::ModelKind::HammersteinWiener:
        return detail::model_from_document<HammersteinWienerd>(document);
      case detail::ModelKind::PseudoHammersteinWiener:
        return detail::model_from_document<PseudoHammersteinWienerd>(document);
    }
    detail::fail("unreachable model kind");
  });
}

}  // namespace bonl::io
