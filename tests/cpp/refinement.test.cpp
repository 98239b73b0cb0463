// The refinement of identify() (estimator/output_error.hpp): its analytic Jacobian, its stability
// guard and its two stages on long records.
// - The normal equations J'J and J'e come from the models' OutputErrorTerms; the oracle is J from
//   central differences of simulate() (step 1e-6 relative), which agrees to about 1e-9 relative.
// - A start with poles outside the unit circle is reflected inside; the result is stable.
// - Poles (models/poles.hpp): denominators built from known poles (the product of (1 - z_i z^-1)),
//   and the magnitude response |1 / A(e^jw)| evaluated directly, for the reflection.
// - The normal equations are gathered in blocks of rows; for every record length about a multiple of
//   the block and 2 to 200 parameters they equal J'J and J'e of the whole Jacobian stacked at once
//   (an empty last block once killed the process with SIGFPE from 48 parameters on), and identify()
//   returns a model on such records. With 1 to 33 columns known at compile time (the window
//   refinement's), whose rows are summed in tiles, they equal one product of the same rows.
// - On a record longer than detail::kCoarseSamples, identification reaches the noise floor: a
//   consistent estimate of p parameters from N samples leaves a simulation RMS of about
//   sigma sqrt(1 + p / N) against the noisy output, so within 1% of sigma at N = 40 000.

#include "test_support.hpp"

#include <complex>
#include <vector>

using namespace bonl_test;

TEMPLATE_LIST_TEST_CASE("the refinement's normal equations are those of the simulation's Jacobian", "[refinement]",
                        bonl::Models) {
  const TestType model = known_system<TestType>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(2000, 5, 1.0, 3);
  const Eigen::VectorXd y = model.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 4);
  const bonl::Records<double> records{{u, y}};
  Eigen::MatrixXd normal;
  Eigen::VectorXd gradient;
  REQUIRE(bonl::detail::simulation_normal_equations(model, records, normal, gradient));

  const Eigen::MatrixXd jacobian = simulation_differences(model, u);
  const Eigen::MatrixXd expected_normal = jacobian.transpose() * jacobian;
  const Eigen::VectorXd expected_gradient = jacobian.transpose() * (y - model.simulate(u));
  CHECK((normal - expected_normal).norm() <= 1e-7 * expected_normal.norm());
  CHECK((gradient - expected_gradient).norm() <= 1e-7 * expected_gradient.norm());
}

TEST_CASE("the refinement's normal equations for 2 to 200 parameters and records about a multiple of the block",
          "[refinement]") {
  std::vector<Eigen::Index> sizes;
  for (Eigen::Index n = 2; n <= 64; ++n) sizes.push_back(n);
  for (Eigen::Index n : {96, 127, 128, 129, 160, 200}) sizes.push_back(n);
  for (const Eigen::Index n : sizes) {
    // ARX with na + nb + 1 = n parameters, a stable first-order denominator padded with zeros.
    const Eigen::Index na = (n + 1) / 2, nb = n - na - 1;
    bonl::ARXd model(na, nb, 1);
    Eigen::VectorXd a = Eigen::VectorXd::Zero(na), b = Eigen::VectorXd::Constant(nb + 1, 0.01);
    a[0] = -0.8;
    model.set_a(a);
    model.set_b(b);
    for (const Eigen::Index samples : {255, 256, 257, 512, 513}) {
      INFO(n << " parameters, " << samples << " samples");
      const Eigen::VectorXd u = bonl::signals::random_levels(samples, 5, 1.0, 11);
      const Eigen::VectorXd y = model.simulate(u) + bonl::signals::white_noise(samples, 0.01, 12);
      Eigen::MatrixXd normal;
      Eigen::VectorXd gradient;
      REQUIRE(bonl::detail::simulation_normal_equations(model, bonl::Records<double>{{u, y}}, normal, gradient));
      // The oracle: every row of the Jacobian stacked first, then one product.
      Eigen::MatrixXd jacobian(samples, n);
      Eigen::VectorXd errors(samples);
      bonl::ARXd::OutputErrorTerms terms(model);
      for (Eigen::Index k = 0; k < samples; ++k) {
        const auto step = terms.step(model.theta(), u[k]);
        jacobian.row(k) = step.sensitivity.transpose();
        errors[k] = y[k] - step.output;
        terms.accept();
      }
      const Eigen::MatrixXd expected_normal = jacobian.transpose() * jacobian;
      CHECK((normal - expected_normal).norm() <= 1e-12 * expected_normal.norm());
      CHECK((gradient - jacobian.transpose() * errors).norm() <= 1e-12 * (jacobian.transpose() * errors).norm());
    }
  }
}

/// detail::add_rows on a block of rows with N columns known at compile time (the window
/// refinement's, row-major), against one product of the same rows with run-time sizes.
template <int N>
void check_tiled_rows() {
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, N, N == 1 ? Eigen::ColMajor : Eigen::RowMajor>;
  for (const Eigen::Index count : {0, 1, 5, 32}) {
    INFO(N << " columns, " << count << " rows");
    Rows rows(32, N);
    for (Eigen::Index k = 0; k < rows.size(); ++k) rows.data()[k] = std::sin(0.7 * static_cast<double>(k) + N);
    const Eigen::VectorXd errors = Eigen::VectorXd::LinSpaced(32, -1.0, 2.0);
    // J'J and J'e so far: a symmetric start, its strict upper triangle marked (add_rows adds to the
    // lower triangle only)
    Eigen::Matrix<double, N, N> normal = Eigen::Matrix<double, N, N>::Identity();
    normal.template triangularView<Eigen::StrictlyUpper>().setConstant(7.0);
    Eigen::Matrix<double, N, 1> gradient = Eigen::Matrix<double, N, 1>::Ones();
    bonl::detail::add_rows(normal, gradient, rows.topRows(count), errors.head(count));
    const Eigen::MatrixXd block = Eigen::MatrixXd(rows.topRows(count));
    const Eigen::MatrixXd expected = Eigen::MatrixXd::Identity(N, N) + block.transpose() * block;
    const Eigen::VectorXd expected_gradient = Eigen::VectorXd::Ones(N) + block.transpose() * errors.head(count);
    // Entry by entry: GCC 12 at -O3 warns of array bounds in Eigen's copy of a 1 x 1 fixed matrix
    // into a run-time-sized one.
    double lower_error = 0.0, gradient_error = 0.0;
    bool upper_untouched = true;
    for (Eigen::Index i = 0; i < N; ++i) {
      gradient_error = std::max(gradient_error, std::abs(gradient[i] - expected_gradient[i]));
      for (Eigen::Index j = 0; j < N; ++j) {
        if (j <= i) lower_error = std::max(lower_error, std::abs(normal(i, j) - expected(i, j)));
        if (j > i) upper_untouched = upper_untouched && normal(i, j) == 7.0;
      }
    }
    CHECK(lower_error <= 1e-13 * expected.norm());
    CHECK(gradient_error <= 1e-13 * expected_gradient.norm());
    CHECK(upper_untouched);
  }
}

TEST_CASE("the normal equations' rows are summed alike for 1 to 33 columns known at compile time", "[refinement]") {
  // Tiles of 4 x 4 up to detail::kTiledColumns, with a narrower last tile; beyond, Eigen's rank update.
  check_tiled_rows<1>();
  check_tiled_rows<2>();
  check_tiled_rows<3>();
  check_tiled_rows<4>();
  check_tiled_rows<5>();
  check_tiled_rows<7>();
  check_tiled_rows<8>();
  check_tiled_rows<13>();
  check_tiled_rows<14>();
  check_tiled_rows<16>();
  check_tiled_rows<31>();
  check_tiled_rows<32>();
  check_tiled_rows<33>();
}

TEST_CASE("identify() returns a model of 48 or more parameters on records a multiple of the block long",
          "[refinement]") {
  // The records of the command `bonl identify actuator.csv --model ARX --orders na=30 nb=20 nk=1`
  // (1024 samples) and of Hammerstein(na = 40, nb = 1, nk = 0, r = 3) on its first half, from a known
  // small system with 1% output noise: the models hold it, so they simulate the records to the noise.
  const bonl::ARXd truth = known_system<bonl::ARXd>("small");
  for (const Eigen::Index samples : {512, 1024}) {
    const Eigen::VectorXd u = bonl::signals::random_levels(samples, 5, 1.0, 13);
    const Eigen::VectorXd clean = truth.simulate(u);
    const double sigma = 0.01 * standard_deviation(clean);
    const Eigen::VectorXd y = clean + bonl::signals::white_noise(samples, sigma, 14);
    INFO(samples << " samples");
    const bonl::ARXd arx = bonl::identify(bonl::ARXd(30, 20, 1), u, y);
    REQUIRE(arx.num_params() == 51);
    CHECK(std::sqrt((arx.simulate(u) - y).squaredNorm() / static_cast<double>(samples)) <= 1.2 * sigma);
    const bonl::Hammersteind hammerstein = bonl::identify(bonl::Hammersteind(40, 1, 0, 3), u, y);
    REQUIRE(hammerstein.num_params() == 49);
    CHECK(std::sqrt((hammerstein.simulate(u) - y).squaredNorm() / static_cast<double>(samples)) <= 1.2 * sigma);
  }
}

TEMPLATE_LIST_TEST_CASE("a start with an unstable linear block is reflected inside and refined to a stable model",
                        "[refinement]", bonl::Models) {
  const TestType truth = known_system<TestType>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(3000, 5, 1.0, 5);
  const Eigen::VectorXd y = truth.simulate(u);
  REQUIRE(bonl::pole_radius(truth) < 1.0);

  TestType start = truth;
  Eigen::VectorXd a = bonl::detail::denominator(truth, 0);  // the (first) linear block's
  a[a.size() - 1] = 2.5;  // the product of the poles' magnitudes is |a_na| > 1: some pole outside
  bonl::detail::set_denominator(start, 0, a);
  REQUIRE(bonl::pole_radius(start) > 1.0);

  bonl::RefinementReport report;
  const TestType refined = bonl::refine_output_error(start, u, y, 100, &report);
  CHECK(report.reflected);
  CHECK(std::isfinite(report.initial_cost));
  CHECK(report.final_cost <= report.initial_cost);
  CHECK(bonl::pole_radius(refined) < 1.0);
}

TEST_CASE("on a long record identification reaches the noise floor in two stages", "[refinement]") {
  const bonl::HammersteinWienerd truth = known_system<bonl::HammersteinWienerd>("small");
  const Eigen::Index samples = 40000;
  REQUIRE(samples > 2 * bonl::detail::kCoarseSamples);
  const double sigma = 0.01;
  const Eigen::VectorXd u = bonl::signals::random_levels(samples, 5, 1.0, 6);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(samples, sigma, 7);
  const bonl::HammersteinWienerd fitted = bonl::identify(truth, u, y);
  const double rms = std::sqrt((fitted.simulate(u) - y).squaredNorm() / static_cast<double>(samples));
  CHECK(rms <= 1.01 * sigma);
  CHECK(bonl::pole_radius(fitted) < 1.0);
}

TEST_CASE("refine_output_error of several starts keeps the best of them and reports which", "[refinement]") {
  const bonl::Hammersteind truth = known_system<bonl::Hammersteind>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(2000, 5, 1.0, 8);
  const Eigen::VectorXd y = truth.simulate(u);
  const bonl::Records<double> records{{u, y}};
  bonl::Hammersteind far = truth;
  far.set_f(truth.f() * 0.2);
  bonl::RefinementReport report;
  const auto refined = bonl::refine_output_error(std::vector<bonl::Hammersteind>{far, truth}, records, 100, &report);
  CHECK(report.start == 1);
  CHECK(report.initial_cost == 0.0);
  CHECK((refined.theta() - truth.theta()).norm() == 0.0);

  CHECK_THROWS_WITH(bonl::refine_output_error(std::vector<bonl::Hammersteind>{}, records),
                    Catch::Matchers::Contains("starts must hold at least one model"));
}

namespace {

/// a_1..a_n of prod_i (1 - z_i z^-1) for real poles and complex pairs (given once, with their conjugate).
Eigen::VectorXd denominator(const std::vector<std::complex<double>>& poles) {
  std::vector<std::complex<double>> all;
  for (const auto& z : poles) {
    all.push_back(z);
    if (z.imag() != 0.0) all.push_back(std::conj(z));
  }
  Eigen::VectorXcd product = Eigen::VectorXcd::Zero(static_cast<Eigen::Index>(all.size()) + 1);
  product[0] = 1.0;
  for (std::size_t i = 0; i < all.size(); ++i)
    for (Eigen::Index j = static_cast<Eigen::Index>(i) + 1; j >= 1; --j) product[j] -= all[i] * product[j - 1];
  return product.tail(static_cast<Eigen::Index>(all.size())).real();
}

double magnitude(const Eigen::VectorXd& a, double w) {
  std::complex<double> value = 1.0;
  for (Eigen::Index j = 0; j < a.size(); ++j) value += a[j] * std::polar(1.0, -w * static_cast<double>(j + 1));
  return 1.0 / std::abs(value);
}

}  // namespace

TEST_CASE("pole_radius is the largest pole magnitude", "[poles]") {
  bonl::ARXd model(3, 0, 0);
  model.set_a(denominator({{0.5, 0.0}, {0.3, 0.8}}));  // |0.3 +- 0.8j| = 0.854
  CHECK(bonl::pole_radius(model) == Approx(std::abs(std::complex<double>(0.3, 0.8))).epsilon(1e-12));
  model.set_a(denominator({{-1.2, 0.0}, {0.3, 0.8}}));
  CHECK(bonl::pole_radius(model) == Approx(1.2).epsilon(1e-12));
}

TEST_CASE("an unstable denominator is reflected inside with the same magnitude response shape", "[poles]") {
  const Eigen::VectorXd unstable = denominator({{1.5, 0.0}, {0.9, 0.6}, {0.2, 0.0}});  // 1.5 and |0.9+0.6j| = 1.08
  const Eigen::VectorXd stable = bonl::detail::reflected_inside(unstable, 0.999);
  bonl::ARXd model(4, 0, 0);
  model.set_a(stable);
  CHECK(bonl::pole_radius(model) < 1.0);
  // |1 / A| changes by one constant factor at every frequency.
  const double ratio = magnitude(stable, 0.1) / magnitude(unstable, 0.1);
  for (double w : {0.3, 0.7, 1.3, 2.0, 3.0}) {
    CHECK(magnitude(stable, w) / magnitude(unstable, w) == Approx(ratio).epsilon(1e-9));
  }
  // Stable denominators are left as they are.
  const Eigen::VectorXd already = denominator({{0.5, 0.0}, {0.3, 0.8}});
  CHECK(bonl::detail::reflected_inside(already, 0.999) == already);
}

// A mask fits the outputs where it is 1 and runs the free run through the others. The oracle is the
// truth: an integrating ARX model's noise-free record whose outputs in a block are replaced by
// nonsense (an offset of 50 and a ramp), refined from a start 20% off. Masked out, the block changes
// nothing: the truth comes back to 1e-8, from rest and after a window, and the mask's block's outputs
// may be anything. Fitted, the block pulls the model away.
TEST_CASE("with a mask the refinement fits the outputs where it is 1 and runs through the others", "[refinement]") {
  bonl::ARXd truth(2, 1, 1, 1);
  truth.set_a(Eigen::Vector2d(-1.2, 0.35));
  truth.set_b(Eigen::Vector2d(0.3, 0.1));
  const Eigen::VectorXd u = bonl::signals::random_levels(1500, 10, 1.0, 21);
  const Eigen::VectorXd clean = truth.simulate(u);
  Eigen::VectorXd y = clean;
  for (Eigen::Index k = 600; k < 900; ++k) y[k] += 50.0 + 0.1 * static_cast<double>(k - 600);
  bonl::ARXd start = truth;
  start.set_theta(truth.theta() * 0.8);
  const bonl::CheckedRecords<double> records(bonl::Records<double>{{u, y}}, truth.num_params());
  for (const Eigen::Index window : {Eigen::Index(0), Eigen::Index(10)}) {
    INFO("window " << window);
    Eigen::VectorXd mask = Eigen::VectorXd::Ones(u.size() - window);
    mask.segment(600 - window, 300).setZero();
    const bonl::ARXd masked =
        bonl::refine_output_error(std::vector<bonl::ARXd>{start}, records, 100, nullptr, window, mask);
    CHECK((masked.theta() - truth.theta()).norm() <= 1e-8 * truth.theta().norm());
    const bonl::ARXd fitted = bonl::refine_output_error(std::vector<bonl::ARXd>{start}, records, 100, nullptr, window);
    CHECK((fitted.theta() - truth.theta()).norm() >= 1e-3 * truth.theta().norm());
  }
}

TEST_CASE("E25 a bad refinement mask is refused with what was wrong", "[refinement][bad_input]") {
  const bonl::ARXd truth = known_system<bonl::ARXd>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(200, 5, 1.0, 3);
  const Eigen::VectorXd y = truth.simulate(u);
  const bonl::CheckedRecords<double> records(bonl::Records<double>{{u, y}}, truth.num_params());
  const std::vector<bonl::ARXd> starts{truth};
  CHECK_THROWS_WITH(bonl::refine_output_error(starts, records, 10, nullptr, 0, Eigen::VectorXd::Ones(199)),
                    Catch::Matchers::Contains("mask must have one entry per sample after the windows (200), got 199"));
  CHECK_THROWS_WITH(bonl::refine_output_error(starts, records, 10, nullptr, 5, Eigen::VectorXd::Ones(200)),
                    Catch::Matchers::Contains("mask must have one entry per sample after the windows (195), got 200"));
  Eigen::VectorXd half = Eigen::VectorXd::Ones(200);
  half[7] = 0.5;
  CHECK_THROWS_WITH(bonl::refine_output_error(starts, records, 10, nullptr, 0, half),
                    Catch::Matchers::Contains("mask's entries must be 0 or 1"));
  Eigen::VectorXd few = Eigen::VectorXd::Zero(200);
  few.head(truth.num_params()).setOnes();
  CHECK_THROWS_WITH(bonl::refine_output_error(starts, records, 10, nullptr, 0, few),
                    Catch::Matchers::Contains("mask must fit more samples than the model has parameters"));
}
