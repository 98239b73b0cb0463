#pragma once
// The bonl model file: one JSON format, read and written by C++ and (through the bindings) Python,
// so that a model identified in one loads in the other and simulates the same output.
//
// Format, version 2 (keys written in this order; readers are strict: no missing or unknown keys):
//   {"format": "bonl-model", "version": 2,
//    "model": the model's name (kDescription.name: "ARX", "Hammerstein", ...),
//    "orders": {one integer per order of kDescription.orders: "na": .., "nb": .., ...; an order with a
//               default (the integrators ni, 0) is written only where it differs from it, and a file
//               without it reads as the default, so files written before it existed still load},
//    "params": {one entry per block of kDescription.parameters: an array ("b": [b_0..b_nb], ...), or a
//               number for a one-number block ("c"); every block is written, and a file may leave out
//               one with no entries at its orders (files from before the block existed)},
//    "operating_point": {"u0": .., "y0": ..},
//    "input_range": [min, max] (the inputs the model was identified on; null for an unbounded end)}
// Version 1 is version 2 without "operating_point" and "input_range"; it is still read (as the
// operating point 0, 0 and the whole line).
// Everything model-specific comes from the model's description (models/model_description.hpp): the
// keys, their order, the ranges of the orders, which first entries are fixed to 1 (b_0 of the block
// models, q_1), which values must be >= 0 (c). Version 1 files written before the descriptions existed
// have the same keys in the same order.
// Numbers are written so that they read back bit for bit (nlohmann_json prints the shortest decimal
// that round-trips a double).
//
// Needs nlohmann_json: link bonl::io (not part of bonl::bonl, nor of bonl/bonl.hpp).

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "../detail/validate.hpp"
#include "../models.hpp"
#include "../version.hpp"

namespace bonl::io {

/// The model file format version this bonl writes; it reads this one and every older one.
inline constexpr int kModelFormatVersion = 2;
/// Largest order (na, nb, nk, r) a model file may give, the models' own limit (bonl::detail::kMaxOrder);
/// r1 is further limited to 32 by the model.
inline constexpr std::int64_t kMaxModelOrder = bonl::detail::kMaxOrder;

/// Any model a file can hold, at run-time orders (what load_model returns).
using AnyModel = ApplyModels<Models, std::variant>::type;

namespace detail {

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
      case Json::parse_event_t::object_start: keys.emplace_back(); break;
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
      default: break;
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
/// `may_be_missing(i)`: the key allowed[i] may be left out.
template <class Keys, class MayBeMissing>
void require_keys(const Json& object, const std::string& where, const Keys& allowed, MayBeMissing&& may_be_missing) {
  const std::string path = where.empty() ? "" : where + ".";
  std::string listed;
  for (const char* key : allowed) listed += (listed.empty() ? "" : ", ") + std::string(key);
  std::size_t index = 0;
  for (const char* key : allowed) {
    if (!object.contains(key) && !may_be_missing(index)) fail("missing key " + path + key);
    ++index;
  }
  for (const auto& item : object.items()) {
    bool known = false;
    for (const char* key : allowed) known = known || item.key() == key;
    if (!known) {
      fail("unknown key " + path + item.key() + " (expected " + (where.empty() ? "" : where + " ") + "keys: " + listed +
           ")");
    }
  }
}
template <class Keys>
void require_keys(const Json& object, const std::string& where, const Keys& allowed) {
  require_keys(object, where, allowed, [](std::size_t) { return false; });
}
inline void require_keys(const Json& object, const std::string& where, std::initializer_list<const char*> allowed) {
  require_keys<std::initializer_list<const char*>>(object, where, allowed);
}

/// The names of every model a file can hold, for messages: "\"ARX\", \"Hammerstein\", ...".
inline std::string model_names() {
  std::string names;
  for_each_model(Models{}, [&names](auto tag) {
    names += (names.empty() ? "\"" : ", \"") + std::string(decltype(tag)::type::kName) + "\"";
  });
  return names;
}

/// Checks everything before "orders" and "params": a JSON object, format, version, the top-level
/// keys and that the model name is one of bonl::Models. Returns the name.
inline std::string read_header(const Json& document) {
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
  if (version.get<std::int64_t>() < 1) {
    fail("version must be between 1 and " + std::to_string(kModelFormatVersion) + ", got " + show(version));
  }
  if (version.get<std::int64_t>() == 1) {
    require_keys(document, "", {"format", "version", "model", "orders", "params"});
  } else {
    require_keys(document, "", {"format", "version", "model", "orders", "params", "operating_point", "input_range"});
  }
  const Json& model = document["model"];
  bool known = false;
  if (model.is_string()) {
    for_each_model(Models{}, [&](auto tag) {
      known = known || model.get_ref<const std::string&>() == decltype(tag)::type::kName;
    });
  }
  if (!known) fail("model must be one of " + model_names() + ", got " + show(model));
  return model.get<std::string>();
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

/// The names of a description's orders or parameter blocks, in order.
template <class Entry, std::size_t N>
std::array<const char*, N> names_of(const std::array<Entry, N>& entries) {
  std::array<const char*, N> names{};
  for (std::size_t i = 0; i < N; ++i) names[i] = entries[i].name;
  return names;
}

/// Reads a parsed document into Model; read_header has not been run on it yet.
template <class Model>
Model model_from_document(const Json& document) {
  using Scalar = typename Model::Scalar;
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  constexpr auto& description = Model::kDescription;

  if (read_header(document) != description.name) {
    fail("model is " + show(document["model"]) + ", but the model type asked for is \"" + description.name + "\"");
  }

  const Json& orders = document["orders"];
  if (!orders.is_object()) fail("orders must be an object, got " + show(orders));
  const auto has_default = [&](std::size_t i) {
    return description.orders[i].default_value != OrderDescription::kRequired;
  };
  require_keys(orders, "orders", names_of(description.orders), has_default);
  std::array<Eigen::Index, description.orders.size()> order_values{};
  for (std::size_t i = 0; i < order_values.size(); ++i) {
    const OrderDescription& order = description.orders[i];
    order_values[i] = orders.contains(order.name)
                          ? read_order(orders, order.name, order.minimum, order.maximum, order.fixed)
                          : order.default_value;
  }

  const Json& params = document["params"];
  if (!params.is_object()) fail("params must be an object, got " + show(params));
  return rethrow_as_json_error([&]() {
    Model model = make_model<Model>(order_values);
    // A block with no entries at the file's orders may be left out: files written before the block
    // existed (the nonlinear-feedback model's plays) hold none.
    const auto empty = [&](std::size_t i) {
      return description.parameters[i].shape == ParameterShape::Vector && model.parameter(i).size() == 0;
    };
    require_keys(params, "params", names_of(description.parameters), empty);
    for (std::size_t i = 0; i < description.parameters.size(); ++i) {
      const ParameterDescription& parameter = description.parameters[i];
      const std::string key = std::string("params.") + parameter.name;
      if (!params.contains(parameter.name)) continue;
      Vector value;
      if (parameter.shape == ParameterShape::Number) {
        value = Vector::Constant(1, static_cast<Scalar>(read_number<Scalar>(params[parameter.name], key)));
      } else {
        value = read_vector<Scalar>(params, parameter.name, model.parameter(i).size());
      }
      if (parameter.normalised != nullptr) require_leading_one(value, key.c_str(), parameter.normalised);
      if (parameter.non_negative && !(value.minCoeff() >= 0)) {
        fail(key + " (" + parameter.meaning + ") must be >= 0, got " +
             show_number(static_cast<double>(value.minCoeff())));
      }
      const Eigen::Index bad = parameter.increasing ? bonl::detail::first_not_increasing_or_zero(value) : -1;
      if (bad >= 0) {
        fail(key + " (" + parameter.meaning + ") must be strictly increasing and hold no 0, got " +
             show_number(static_cast<double>(value[bad])) + " at index " + std::to_string(bad));
      }
      model.set_parameter(i, value);
    }
    if (document.contains("operating_point")) {
      const Json& point = document["operating_point"];
      if (!point.is_object()) fail("operating_point must be an object, got " + show(point));
      require_keys(point, "operating_point", {"u0", "y0"});
      model.set_operating_point(read_number<double>(point["u0"], "operating_point.u0"),
                                read_number<double>(point["y0"], "operating_point.y0"));
    }
    if (document.contains("input_range")) {
      const Json& range = document["input_range"];
      if (!range.is_array() || range.size() != 2) {
        fail("input_range must be an array [min, max] (null for an unbounded end), got " + show(range));
      }
      const double infinity = std::numeric_limits<double>::infinity();
      const double min = range[0].is_null() ? -infinity : read_number<double>(range[0], "input_range[0]");
      const double max = range[1].is_null() ? infinity : read_number<double>(range[1], "input_range[1]");
      if (!(min <= max)) fail("input_range must have min <= max, got " + show(range));
      model.set_input_range(min, max);
    }
    return model;
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

/// The model as a bonl model file (format version 2). indent < 0: one line; otherwise pretty-printed
/// with that many spaces per level. Works for every model of bonl::Models, any Scalar, fixed or
/// dynamic orders.
/// \param model the model to write
/// \param indent spaces per level; < 0: one line
/// \return the model file's text (JSON)
template <class Model>
std::string to_json(const Model& model, int indent = -1) {
  using detail::Json;
  constexpr auto& description = Model::kDescription;
  return detail::guard([&]() {
    Json orders = Json::object();
    const auto order_values = model.orders();
    for (std::size_t i = 0; i < description.orders.size(); ++i) {
      if (order_values[i] == description.orders[i].default_value) continue;  // files from before it stay as they were
      orders[description.orders[i].name] = static_cast<std::int64_t>(order_values[i]);
    }
    Json params = Json::object();
    for (std::size_t i = 0; i < description.parameters.size(); ++i) {
      const ParameterDescription& parameter = description.parameters[i];
      const auto value = model.parameter(i);
      if (parameter.shape == ParameterShape::Number) {
        params[parameter.name] = static_cast<double>(value[0]);
      } else {
        params[parameter.name] = detail::to_array(value);
      }
    }
    Json document = Json::object();
    document["format"] = "bonl-model";
    document["version"] = kModelFormatVersion;
    document["model"] = description.name;
    document["orders"] = std::move(orders);
    document["params"] = std::move(params);
    Json point = Json::object();
    point["u0"] = model.u0();
    point["y0"] = model.y0();
    document["operating_point"] = std::move(point);
    Json range = Json::array();
    range.push_back(std::isfinite(model.input_min()) ? Json(model.input_min()) : Json(nullptr));
    range.push_back(std::isfinite(model.input_max()) ? Json(model.input_max()) : Json(nullptr));
    document["input_range"] = std::move(range);
    return document.dump(indent);
  });
}

/// Reads a bonl model file into the given model type (e.g. bonl::PaperPseudoHammersteinWiener or
/// bonl::PseudoHammersteinWienerd). Throws std::invalid_argument, with a message that starts with
/// "bonl: model JSON: " and names the key at fault, for invalid JSON, another format, a newer
/// version, another model kind, missing or unknown keys, orders out of range or different from the
/// type's compile-time orders, arrays of the wrong length, non-finite numbers, b_0 or q_1 not 1, c < 0.
/// \param text the model file's text (JSON)
/// \return the model
template <class Model>
Model model_from_json(const std::string& text) {
  return detail::guard([&]() { return detail::model_from_document<Model>(detail::parse(text)); });
}

/// Reads a bonl model file of any kind, at run-time orders; the variant holds the kind the file
/// names. Throws as model_from_json does.
/// \param text the model file's text (JSON)
/// \return the model, of the kind the file names
inline AnyModel load_model(const std::string& text) {
  return detail::guard([&]() -> AnyModel {
    const detail::Json document = detail::parse(text);
    const std::string name = detail::read_header(document);
    std::optional<AnyModel> model;
    for_each_model(Models{}, [&](auto tag) {
      using Model = typename decltype(tag)::type;
      if (!model && name == Model::kName) model.emplace(detail::model_from_document<Model>(document));
    });
    return std::move(*model);  // read_header checked that the name is one of Models
  });
}

}  // namespace bonl::io
