// The JSON model file (io/model_json.hpp): bit-exact round trips for every model, fixed and dynamic
// orders, load_model's dispatch, the exact text of a small model (the format pinned), the shared
// fixture tests/data/phw_model.json, and every way a file can be rejected.

#include <bonl/io.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <variant>

#include "test_support.hpp"

using namespace bonl_test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using Json = nlohmann::ordered_json;

namespace {

/// theta with every entry nudged by up to 1e-3 (full-precision digits, stays stable), c kept >= 0.
template <class Model>
Model perturbed(Model model, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  typename Model::Params theta = model.theta();
  for (Eigen::Index i = 0; i < theta.size(); ++i) theta[i] += static_cast<typename Model::Scalar>(noise(rng));
  model.set_theta(theta);
  return model;
}

/// to_json -> model_from_json gives the same theta bit for bit and the same simulated output.
template <class Out, class In>
void check_round_trip(const In& model) {
  const std::string text = bonl::io::to_json(model);
  INFO(text);
  const Out back = bonl::io::model_from_json<Out>(text);
  REQUIRE(back.num_params() == model.num_params());
  CHECK(back.na() == model.na());
  CHECK(back.nb() == model.nb());
  CHECK(back.nk() == model.nk());
  for (Eigen::Index i = 0; i < model.num_params(); ++i) {
    INFO("theta[" << i << "]");
    CHECK(back.theta()[i] == model.theta()[i]);
  }
  const Eigen::VectorXd u = bonl::signals::random_levels(400, 3, 1.0, 11);
  const Eigen::VectorXd y_model = model.simulate(u.cast<typename In::Scalar>()).template cast<double>();
  const Eigen::VectorXd y_back = back.simulate(u.cast<typename Out::Scalar>()).template cast<double>();
  CHECK(y_back == y_model);
  CHECK(bonl::io::to_json(back) == text);
}

std::string edited(const std::string& text, const std::function<void(Json&)>& edit) {
  Json document = Json::parse(text);
  edit(document);
  return document.dump();
}

const std::string& phw_text() {
  static const std::string text = bonl::io::to_json(known_phw());
  return text;
}

/// model_from_json<Model> and load_model both reject text with a message naming the problem.
template <class Model = bonl::PseudoHammersteinWienerd>
void check_rejected(const std::string& text, const std::string& message, bool also_load_model = true) {
  INFO(text);
  CHECK_THROWS_AS(bonl::io::model_from_json<Model>(text), std::invalid_argument);
  CHECK_THROWS_WITH(bonl::io::model_from_json<Model>(text), StartsWith("bonl: model JSON: ") && Contains(message));
  if (also_load_model) {
    CHECK_THROWS_AS(bonl::io::load_model(text), std::invalid_argument);
    CHECK_THROWS_WITH(bonl::io::load_model(text), StartsWith("bonl: model JSON: ") && Contains(message));
  }
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("every model round-trips bit for bit and simulates the same", "[io]") {
  SECTION("the known systems") {
    check_round_trip<bonl::PaperARX>(known_arx());
    check_round_trip<bonl::PaperHammerstein>(known_hammerstein());
    check_round_trip<bonl::PaperHammersteinWiener>(known_hammerstein_wiener());
    check_round_trip<bonl::PaperPseudoHammersteinWiener>(known_phw());
  }
  SECTION("full-precision parameters") {
    check_round_trip<bonl::PaperARX>(perturbed(known_arx(), 1));
    check_round_trip<bonl::PaperHammerstein>(perturbed(known_hammerstein(), 2));
    check_round_trip<bonl::PaperHammersteinWiener>(perturbed(known_hammerstein_wiener(), 3));
    check_round_trip<bonl::PaperPseudoHammersteinWiener>(perturbed(known_phw(), 4));
  }
  SECTION("awkward doubles: subnormal, huge, negative zero, 0.1 + 0.2") {
    bonl::ARXd model(2, 3, 0);
    model.set_b(vec({4.9e-324, -1.7976931348623157e308, -0.0, 0.1 + 0.2}));
    model.set_a(vec({2.2250738585072014e-308, 1.0 / 3.0}));
    const bonl::ARXd back = bonl::io::model_from_json<bonl::ARXd>(bonl::io::to_json(model));
    CHECK(std::memcmp(back.theta().data(), model.theta().data(), sizeof(double) * 6) == 0);
  }
  SECTION("2000 doubles drawn from random bit patterns, every magnitude") {
    std::mt19937_64 rng(42);
    bonl::ARXd model(1000, 999, 0);
    Eigen::VectorXd theta(2000);
    for (Eigen::Index i = 0; i < theta.size(); ++i) {
      do {
        const std::uint64_t bits = rng();
        std::memcpy(&theta[i], &bits, sizeof(double));
      } while (!std::isfinite(theta[i]));
    }
    model.set_theta(theta);
    const bonl::ARXd back = bonl::io::model_from_json<bonl::ARXd>(bonl::io::to_json(model));
    CHECK(std::memcmp(back.theta().data(), theta.data(), sizeof(double) * 2000) == 0);
  }
  SECTION("float models") {
    bonl::PseudoHammersteinWiener<float> model(3, 2, kNk, 3);
    model.set_theta(known_phw().theta().cast<float>());
    check_round_trip<bonl::PseudoHammersteinWiener<float>>(perturbed(model, 5));
  }
}

TEST_CASE("fixed and run-time orders read each other's files", "[io]") {
  check_round_trip<bonl::ARXd>(known_arx());
  check_round_trip<bonl::Hammersteind>(known_hammerstein());
  check_round_trip<bonl::HammersteinWienerd>(known_hammerstein_wiener());
  check_round_trip<bonl::PseudoHammersteinWienerd>(known_phw());

  const bonl::PseudoHammersteinWienerd dynamic = bonl::io::model_from_json<bonl::PseudoHammersteinWienerd>(phw_text());
  CHECK(bonl::io::to_json(dynamic) == phw_text());
  check_round_trip<bonl::PaperPseudoHammersteinWiener>(dynamic);
  // Partly fixed orders too.
  check_round_trip<bonl::HammersteinWiener<double, Eigen::Dynamic, 2, Eigen::Dynamic, 3>>(known_hammerstein_wiener());
}

TEST_CASE("load_model holds the kind the file names", "[io]") {
  const bonl::io::AnyModel arx = bonl::io::load_model(bonl::io::to_json(known_arx()));
  const bonl::io::AnyModel h = bonl::io::load_model(bonl::io::to_json(known_hammerstein()));
  const bonl::io::AnyModel hw = bonl::io::load_model(bonl::io::to_json(known_hammerstein_wiener()));
  const bonl::io::AnyModel phw = bonl::io::load_model(phw_text());
  REQUIRE(std::holds_alternative<bonl::ARXd>(arx));
  REQUIRE(std::holds_alternative<bonl::Hammersteind>(h));
  REQUIRE(std::holds_alternative<bonl::HammersteinWienerd>(hw));
  REQUIRE(std::holds_alternative<bonl::PseudoHammersteinWienerd>(phw));
  CHECK(std::get<bonl::ARXd>(arx).theta() == known_arx().theta());
  CHECK(std::get<bonl::Hammersteind>(h).theta() == known_hammerstein().theta());
  CHECK(std::get<bonl::HammersteinWienerd>(hw).theta() == known_hammerstein_wiener().theta());
  CHECK(std::get<bonl::PseudoHammersteinWienerd>(phw).theta() == known_phw().theta());
  CHECK(std::get<bonl::PseudoHammersteinWienerd>(phw).nk() == kNk);
  // Visiting gives the same output as the model written.
  const Eigen::VectorXd u = bonl::signals::random_levels(300, 4, 1.0, 21);
  const Eigen::VectorXd y = std::visit([&u](const auto& model) { return Eigen::VectorXd(model.simulate(u)); }, phw);
  CHECK(y == known_phw().simulate(u));
}

TEST_CASE("the format, pinned: exact text of small models", "[io]") {
  bonl::HammersteinWienerd hw(1, 1, 0, 1, 2);
  hw.set_f(vec({0.5, -0.25}));
  hw.set_p(vec({0.0, 0.125}));
  hw.set_b(vec({1.0, 0.5}));
  hw.set_a(vec({-0.5}));
  hw.set_q(vec({1.0, 0.1}));
  CHECK(bonl::io::to_json(hw) == R"({"format":"bonl-model","version":2,"model":"HammersteinWiener",)"
                                 R"("orders":{"na":1,"nb":1,"nk":0,"r":1,"r1":2},)"
                                 R"("params":{"b":[1.0,0.5],"a":[-0.5],"f":[0.5,-0.25],"p":[0.0,0.125],"q":[1.0,0.1]},)"
                                 R"("operating_point":{"u0":0.0,"y0":0.0},"input_range":[null,null]})");

  bonl::ARX<double, 1, 0> arx(1, 0, 3);
  arx.set_b(vec({0.2}));
  arx.set_a(vec({-0.9}));
  arx.set_operating_point(2.5, -0.125);
  arx.set_input_range(-1.5, 4.0);
  CHECK(bonl::io::to_json(arx, 2) ==
        "{\n"
        "  \"format\": \"bonl-model\",\n"
        "  \"version\": 2,\n"
        "  \"model\": \"ARX\",\n"
        "  \"orders\": {\n"
        "    \"na\": 1,\n"
        "    \"nb\": 0,\n"
        "    \"nk\": 3\n"
        "  },\n"
        "  \"params\": {\n"
        "    \"b\": [\n"
        "      0.2\n"
        "    ],\n"
        "    \"a\": [\n"
        "      -0.9\n"
        "    ]\n"
        "  },\n"
        "  \"operating_point\": {\n"
        "    \"u0\": 2.5,\n"
        "    \"y0\": -0.125\n"
        "  },\n"
        "  \"input_range\": [\n"
        "    -1.5,\n"
        "    4.0\n"
        "  ]\n"
        "}");

  bonl::PseudoHammersteinWienerd phw(1, 0, 1, 1);
  phw.set_f(vec({0.0, 2.0}));
  phw.set_p(vec({0.0, -1.0}));
  phw.set_a(vec({-0.5}));
  phw.set_c(0.25);
  CHECK(bonl::io::to_json(phw) == R"({"format":"bonl-model","version":2,"model":"PseudoHammersteinWiener",)"
                                  R"("orders":{"na":1,"nb":0,"nk":1,"r":1},)"
                                  R"("params":{"b":[1.0],"a":[-0.5],"f":[0.0,2.0],"p":[0.0,-1.0],"c":0.25},)"
                                  R"("operating_point":{"u0":0.0,"y0":0.0},"input_range":[null,null]})");

  bonl::Hammersteind h(1, 0, 0, 1);
  h.set_f(vec({0.0, 1.0}));
  h.set_a(vec({0.5}));
  CHECK(bonl::io::to_json(h) ==
        R"({"format":"bonl-model","version":2,"model":"Hammerstein","orders":{"na":1,"nb":0,"nk":0,"r":1},)"
        R"("params":{"b":[1.0],"a":[0.5],"f":[0.0,1.0],"p":[0.0,0.0]},"operating_point":{"u0":0.0,"y0":0.0},)"
        R"("input_range":[null,null]})");
}

TEST_CASE("version 1 files, written before the operating point, still load, at the operating point (0, 0)", "[io]") {
  const std::string version_1 =
      R"({"format":"bonl-model","version":1,"model":"Hammerstein","orders":{"na":1,"nb":0,"nk":0,"r":1},)"
      R"("params":{"b":[1.0],"a":[0.5],"f":[0.0,1.0],"p":[0.0,0.0]}})";
  const auto model = bonl::io::model_from_json<bonl::Hammersteind>(version_1);
  CHECK(model.u0() == 0.0);
  CHECK(model.y0() == 0.0);
  CHECK(model.f() == vec({0.0, 1.0}));
  // A version 1 file with an operating point is not a version 1 file.
  CHECK_THROWS_WITH(bonl::io::model_from_json<bonl::Hammersteind>(version_1.substr(0, version_1.size() - 1) +
                                                                  R"(,"operating_point":{"u0":0.0,"y0":0.0}})"),
                    Catch::Matchers::Contains("unknown key operating_point"));
}

TEST_CASE("the operating point is written and read back bit for bit", "[io]") {
  bonl::Wienerd model = known_system<bonl::Wienerd>("small");
  model.set_operating_point(0.1 + 0.2, -1.0 / 3.0);
  const auto back = bonl::io::model_from_json<bonl::Wienerd>(bonl::io::to_json(model));
  CHECK(back.u0() == model.u0());
  CHECK(back.y0() == model.y0());
  const Eigen::VectorXd u = bonl::signals::random_levels(300, 5, 1.0, 3);
  CHECK(back.simulate(u) == model.simulate(u));
  CHECK_THROWS_WITH(
      bonl::io::model_from_json<bonl::Wienerd>(
          std::string(bonl::io::to_json(model)).replace(bonl::io::to_json(model).find("\"y0\""), 4, "\"y1\"")),
      Catch::Matchers::Contains("operating_point"));
}

TEST_CASE("the shared fixture tests/data/phw_model.json loads", "[io]") {
  const std::string text = read_file(std::string(bonl_test::data_dir()) + "/phw_model.json");
  bonl::PseudoHammersteinWienerd expected(2, 1, 2, 2);
  expected.set_b(vec({1.0, 0.5}));
  expected.set_a(vec({-1.2, 0.35}));
  expected.set_f(vec({0.01, 0.8, -0.1}));
  expected.set_p(vec({-0.02, 0.3, 0.15}));
  expected.set_c(0.05);

  const auto model = bonl::io::model_from_json<bonl::PseudoHammersteinWienerd>(text);
  CHECK(model.na() == 2);
  CHECK(model.nb() == 1);
  CHECK(model.nk() == 2);
  CHECK(model.r() == 2);
  CHECK(model.theta() == expected.theta());
  const auto fixed = bonl::io::model_from_json<bonl::PseudoHammersteinWiener<double, 2, 1, 2>>(text);
  CHECK(fixed.theta() == expected.theta());
  const bonl::io::AnyModel any = bonl::io::load_model(text);
  REQUIRE(std::holds_alternative<bonl::PseudoHammersteinWienerd>(any));

  const Eigen::VectorXd u = bonl::signals::random_levels(200, 5, 1.0, 7);
  CHECK(std::get<bonl::PseudoHammersteinWienerd>(any).simulate(u) == expected.simulate(u));
  // Its first samples by hand, from rest: w(0) = f(1) = 0.01 + 0.8 - 0.1 = 0.71, then u = 0 gives
  // w = f_0 = 0.01; x(k) = 1.2 x(k-1) - 0.35 x(k-2) + w(k-2) + 0.5 w(k-3); backlash c = 0.05 from 0.
  Eigen::VectorXd pulse = Eigen::VectorXd::Zero(4);
  pulse[0] = 1.0;
  const Eigen::VectorXd y = model.simulate(pulse);
  CHECK(y[0] == 0.0);
  CHECK(y[1] == 0.0);
  CHECK(y[2] == Approx(0.71 - 0.05).epsilon(1e-14));                            // x(2) = 0.71
  CHECK(y[3] == Approx(0.01 + 0.5 * 0.71 + 1.2 * 0.71 - 0.05).epsilon(1e-14));  // x(3) = 1.217
}

TEST_CASE("bad files are rejected with a message naming the problem", "[io]") {
  const std::string& good = phw_text();
  REQUIRE_NOTHROW(bonl::io::model_from_json<bonl::PseudoHammersteinWienerd>(good));

  SECTION("not JSON, not an object") {
    check_rejected("{\"format\": ", "not valid JSON: [json.exception.parse_error");
    check_rejected(good + " x", "not valid JSON");
    check_rejected("", "not valid JSON");
    check_rejected("{\"format\": \"bonl-model\", } ", "not valid JSON");
    check_rejected("/* c */ " + good, "not valid JSON");
    check_rejected("[1, 2]", "the document must be a JSON object, got array");
  }
  SECTION("format and version") {
    check_rejected(edited(good, [](Json& d) { d.erase("format"); }), "missing key format");
    check_rejected(edited(good, [](Json& d) { d["format"] = "bonl-modle"; }),
                   "format must be \"bonl-model\", got \"bonl-modle\"");
    check_rejected(edited(good, [](Json& d) { d.erase("version"); }), "missing key version");
    check_rejected(edited(good, [](Json& d) { d["version"] = 3; }),
                   "version 3 is newer than this bonl reads: it reads version 2");
    check_rejected(edited(good, [](Json& d) { d["version"] = 18446744073709551615u; }),
                   "is newer than this bonl reads: it reads version 2");
    check_rejected(edited(good, [](Json& d) { d["version"] = 0; }), "version must be between 1 and 2, got 0");
    check_rejected(edited(good, [](Json& d) { d["version"] = "1"; }), "version must be an integer, got \"1\"");
    check_rejected(edited(good, [](Json& d) { d["version"] = 1.0; }), "version must be an integer, got 1.0");
  }
  SECTION("top-level keys and the model name") {
    check_rejected(edited(good, [](Json& d) { d["comment"] = "hi"; }), "unknown key comment");
    check_rejected(edited(good, [](Json& d) { d.erase("params"); }), "missing key params");
    check_rejected(edited(good, [](Json& d) { d.erase("model"); }), "missing key model");
    check_rejected(edited(good, [](Json& d) { d["model"] = "Pseudo-Hammerstein-Wiener"; }),
                   "model must be one of " + quoted_model_names() + ", got \"Pseudo-Hammerstein-Wiener\"");
    check_rejected(edited(good, [](Json& d) { d["model"] = 3; }), "model must be one of");
    check_rejected<bonl::Hammersteind>(good,
                                       "model is \"PseudoHammersteinWiener\", but the model type asked for is "
                                       "\"Hammerstein\"",
                                       false);
    check_rejected<bonl::PaperARX>(bonl::io::to_json(known_hammerstein_wiener()),
                                   "but the model type asked for is \"ARX\"", false);
    check_rejected(R"({"format": "bonl-model", "version": 1, "version": 1})", "key \"version\" appears more than once");
    check_rejected(std::string(good).insert(1, "\"x\": {\"a\": 1, \"a\": 2}, "), "key \"a\" appears more than once");
  }
  SECTION("orders") {
    check_rejected(edited(good,
                          [](Json& d) {
                            d["orders"] = Json::array({3, 2, 8, 3});
                          }),
                   "orders must be an object, got [3,2,8,3]");
    check_rejected(edited(good, [](Json& d) { d["orders"].erase("r"); }), "missing key orders.r");
    check_rejected(edited(good, [](Json& d) { d["orders"]["r1"] = 3; }), "unknown key orders.r1");
    check_rejected<bonl::PaperHammersteinWiener>(
        edited(bonl::io::to_json(known_hammerstein_wiener()), [](Json& d) { d["orders"].erase("r1"); }),
        "missing key orders.r1");
    check_rejected(edited(good, [](Json& d) { d["orders"]["na"] = 2.5; }), "orders.na must be an integer, got 2.5");
    check_rejected(edited(good, [](Json& d) { d["orders"]["na"] = 3.0; }), "orders.na must be an integer, got 3.0");
    check_rejected(edited(good, [](Json& d) { d["orders"]["nk"] = "8"; }), "orders.nk must be an integer, got \"8\"");
    check_rejected(edited(good, [](Json& d) { d["orders"]["na"] = 0; }),
                   "orders.na must be between 1 and 1000000, got 0");
    check_rejected(edited(good, [](Json& d) { d["orders"]["nb"] = -1; }),
                   "orders.nb must be between 0 and 1000000, got -1");
    check_rejected(edited(good, [](Json& d) { d["orders"]["nk"] = 1000000000000; }),
                   "orders.nk must be between 0 and 1000000, got 1000000000000");
    check_rejected(edited(good, [](Json& d) { d["orders"]["r"] = 18446744073709551615u; }),
                   "orders.r must be between 1 and 1000000, got 18446744073709551615");
    check_rejected(edited(good, [](Json& d) { d["orders"]["r"] = 0; }), "orders.r must be between 1 and 1000000");
    check_rejected<bonl::HammersteinWienerd>(
        edited(bonl::io::to_json(known_hammerstein_wiener()), [](Json& d) { d["orders"]["r1"] = 33; }),
        "orders.r1 must be between 2 and 32, got 33");
    check_rejected<bonl::HammersteinWienerd>(
        edited(bonl::io::to_json(known_hammerstein_wiener()), [](Json& d) { d["orders"]["r1"] = 1; }),
        "orders.r1 must be between 2 and 32, got 1");
    // Orders that disagree with the type's compile-time orders.
    check_rejected<bonl::PaperPseudoHammersteinWiener>(
        edited(good,
               [](Json& d) {
                 d["orders"]["na"] = 2;
                 d["params"]["a"] = Json::array({-1.0, 0.3});
               }),
        "orders.na = 2 does not match the model type's compile-time order 3", false);
    check_rejected<bonl::ARX<double, 3, 1>>(
        bonl::io::to_json(known_arx()), "orders.nb = 2 does not match the model type's compile-time order 1", false);
    check_rejected<bonl::PseudoHammersteinWiener<double, 3, 2, 2>>(
        good, "orders.r = 3 does not match the model type's compile-time order 2", false);
    check_rejected<bonl::HammersteinWiener<double, 3, 2, 3, 4>>(
        bonl::io::to_json(known_hammerstein_wiener()),
        "orders.r1 = 3 does not match the model type's compile-time order 4", false);
  }
  SECTION("params") {
    check_rejected(edited(good, [](Json& d) { d["params"] = 1; }), "params must be an object, got 1");
    check_rejected(edited(good, [](Json& d) { d["params"].erase("c"); }), "missing key params.c");
    check_rejected(edited(good, [](Json& d) { d["params"].erase("f"); }), "missing key params.f");
    check_rejected(edited(good, [](Json& d) { d["params"]["q"] = Json::array({1.0, 0.2}); }), "unknown key params.q");
    check_rejected(edited(good, [](Json& d) { d["params"]["f"].erase(3); }), "params.f must have 4 entries, got 3");
    check_rejected(edited(good, [](Json& d) { d["params"]["p"].push_back(0.0); }),
                   "params.p must have 4 entries, got 5");
    check_rejected(edited(good,
                          [](Json& d) {
                            d["params"]["b"] = Json::array({1.0, 0.5});
                          }),
                   "params.b must have 3 entries, got 2");
    check_rejected(edited(good, [](Json& d) { d["params"]["a"] = Json::array(); }),
                   "params.a must have 3 entries, got 0");
    check_rejected(edited(good, [](Json& d) { d["params"]["a"] = 0.5; }),
                   "params.a must be an array of numbers, got 0.5");
    check_rejected(edited(good, [](Json& d) { d["params"]["a"][1] = "1.04"; }),
                   "params.a[1] must be a number, got \"1.04\"");
    check_rejected(edited(good, [](Json& d) { d["params"]["f"][2] = nullptr; }),
                   "params.f[2] must be a number, got null");
    check_rejected(edited(good, [](Json& d) { d["params"]["f"][2] = true; }), "params.f[2] must be a number, got true");
    std::string overflow = good;
    overflow.replace(overflow.find("-0.238"), 6, "-1e400");
    check_rejected(overflow,
                   "a number is out of double's range: [json.exception.out_of_range.406] number overflow "
                   "parsing '-1e400'");
    check_rejected(edited(good, [](Json& d) { d["params"]["c"] = -0.1; }),
                   "params.c (backlash half-width) must be >= 0, got -0.1");
    check_rejected(edited(good, [](Json& d) { d["params"]["c"] = "0.1"; }), "params.c must be a number, got \"0.1\"");
    check_rejected(edited(good, [](Json& d) { d["params"]["c"] = Json::array({0.1}); }), "params.c must be a number");
    std::string huge_c = good;
    huge_c.replace(huge_c.find("\"c\":0.1"), 7, "\"c\":1e999");
    check_rejected(huge_c, "a number is out of double's range");
  }
  SECTION("normalisation: b_0 = 1 for the block models, q_1 = 1 for H-W; ARX keeps b_0 free") {
    check_rejected(edited(good, [](Json& d) { d["params"]["b"][0] = 0.5; }),
                   "params.b[0] must be 1 (block models are normalised so that b_0 = 1), got 0.5");
    check_rejected<bonl::Hammersteind>(
        edited(bonl::io::to_json(known_hammerstein()), [](Json& d) { d["params"]["b"][0] = 0; }),
        "params.b[0] must be 1");
    const std::string hw = bonl::io::to_json(known_hammerstein_wiener());
    check_rejected<bonl::HammersteinWienerd>(edited(hw, [](Json& d) { d["params"]["q"][0] = 2.0; }),
                                             "params.q[0] must be 1 (the H-W model is normalised so that q_1 = 1), "
                                             "got 2.0");
    check_rejected<bonl::HammersteinWienerd>(edited(hw, [](Json& d) { d["params"]["q"].erase(2); }),
                                             "params.q must have 3 entries, got 2");
    // Integers are numbers too: b_0 written as 1 reads as 1.0.
    CHECK_NOTHROW(
        bonl::io::model_from_json<bonl::HammersteinWienerd>(edited(hw, [](Json& d) { d["params"]["b"][0] = 1; })));
    CHECK(bonl::io::model_from_json<bonl::ARXd>(bonl::io::to_json(known_arx())).b()[0] == 0.05);
  }
  SECTION("a float model rejects a value beyond float's range") {
    check_rejected<bonl::PseudoHammersteinWiener<float>>(edited(good, [](Json& d) { d["params"]["a"][0] = 1e300; }),
                                                         "params.a[0] = 1e+300 is out of the model's Scalar range",
                                                         false);
  }
}
