#pragma once
// Pseudo-Hammerstein-Wiener (P-H-W) model: the Hammerstein model followed by a symmetric,
// unit-slope backlash of half-width c (eqs. 10-12), starting engaged at y(-1) = 0.
// Parameters in eq. (19) order: f_0..f_r, p_0..p_r, b_1..b_nb, a_1..a_na, c.

#include <algorithm>
#include <cmath>
#include <string>

#include "../blocks/backlash.hpp"
#include "../detail/validate.hpp"
#include "detail/hammerstein_front.hpp"
#include "detail/model_runs.hpp"

namespace bonl {

/// What the P-H-W model adds to the estimator's options (its EstimatorSettings; Estimator, identify).
struct BacklashEstimatorSettings {
  /// The initial backlash half-width c(0) of the equation-error and paper methods (the paper's 0.01),
  /// in the output's units; the output-error method starts at c = 0.
  double c0 = 0.01;
  /// The output-error method holds c at 0 for this many samples after each start from rest (the
  /// model's OutputErrorTerms).
  Eigen::Index backlash_hold = 200;

  /// Throws std::invalid_argument for a setting out of range (docs/reference/bad_input.md lists them).
  void validate() const {
    detail::require(std::isfinite(c0) && c0 >= 0.0, "c0 (initial backlash half-width) must be finite and >= 0");
    detail::require(backlash_hold >= 0, "backlash_hold must be >= 0");
  }
  /// The settings for the data multiplied by u_scale and y_scale: c0 is in the output's units.
  /// \param y_scale the output's factor (nothing here is in the input's units)
  /// \return the settings for the scaled data
  BacklashEstimatorSettings rescaled(double /*u_scale*/, double y_scale) const { return {c0 * y_scale, backlash_hold}; }
};

/// The Pseudo-Hammerstein-Wiener (P-H-W) model: the Hammerstein model followed by a symmetric,
/// unit-slope backlash of half-width c (eqs. 10-12), starting engaged at y(-1) = 0. Parameters in
/// eq. (19) order: f_0..f_r, p_0..p_r, b_1..b_nb, a_1..a_na, c.
template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic, int R_ = Eigen::Dynamic>
class PseudoHammersteinWiener : public detail::HammersteinFront<Scalar_, Na_, Nb_, R_, 1>,
                                public detail::ModelRuns<PseudoHammersteinWiener<Scalar_, Na_, Nb_, R_>> {
  using Front = detail::HammersteinFront<Scalar_, Na_, Nb_, R_, 1>;

 public:
  using typename Front::Params;
  using typename Front::Scalar;
  using typename Front::VectorX;
  /// \copydoc ARX::kName
  static constexpr const char* kName = "PseudoHammersteinWiener";
  /// \copydoc ARX::kDescription
  static constexpr ModelDescription<5, 5> kDescription{
      kName,
      "Pseudo-Hammerstein-Wiener model: the Hammerstein model followed by a symmetric, unit-slope "
      "backlash of half-width c. y(k) = x(k) - c if x(k) > y(k-1) + c; x(k) + c if x(k) < y(k-1) - c; "
      "else y(k-1).",
      detail::concat(detail::front_orders<Na_, Nb_, R_>(), std::array<OrderDescription, 1>{detail::kIntegratorsOrder}),
      detail::concat(detail::kFrontParameters,
                     std::array<ParameterDescription, 1>{
                         {{"c", ParameterShape::Number, 0, "backlash half-width", nullptr, true, {1, 0, 0, 0}}}})};

  /// A model with the orders na >= 1, nb >= 1, nk >= 0, r >= 0 and ni in 0..2, all parameters zero
  /// (c = 0 included). Throws std::invalid_argument for an order out of range or one that differs from
  /// the compile-time order.
  /// \param na poles of the linear block, >= 1
  /// \param nb B has nb + 1 coefficients, b_0 = 1, >= 1
  /// \param nk pure delay in samples, >= 0
  /// \param r degree of each segment of the input polynomial, >= 0
  /// \param ni integrators (poles fixed at 1), 0..2
  PseudoHammersteinWiener(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index r, Eigen::Index ni = 0)
      : Front(na, nb, nk, r, 1, ni) {}

  /// \copydoc ARX::orders
  std::array<Eigen::Index, 5> orders() const noexcept {
    return {this->na(), this->nb(), this->nk(), this->r(), this->ni()};
  }
  /// The parameter block kDescription.parameters[i]: b, a, f, p, c (one entry).
  /// \copydetails ARX::parameter
  VectorX parameter(std::size_t i) const {
    if (i < Front::kFrontBlocks) return this->front_parameter(i);
    if (i == Front::kFrontBlocks) return VectorX::Constant(1, c());
    detail::no_such_parameter(kName, i);
  }
  /// \copydoc ARX::set_parameter
  void set_parameter(std::size_t i, const VectorX& value) {
    if (i < Front::kFrontBlocks) return this->set_front_parameter(i, value);
    if (i == Front::kFrontBlocks) {
      detail::require_size(value, 1, "c");
      return set_c(value[0]);
    }
    detail::no_such_parameter(kName, i);
  }

  /// Backlash half-width c (the model is valid for c >= 0).
  /// \return the last entry of theta, c; a negative value is possible in an unprojected estimate
  Scalar c() const noexcept { return this->m_theta[this->num_params() - 1]; }
  /// Sets the backlash half-width; throws std::invalid_argument unless c is finite and >= 0.
  /// \param c the half-width, in the output's units
  void set_c(Scalar c) {
    detail::require(std::isfinite(c) && c >= Scalar(0), "c (backlash half-width) must be finite and >= 0");
    this->m_theta[this->num_params() - 1] = c;
  }
  /// The backlash block with the half-width c (a negative c, possible in an estimate before it is
  /// projected, counts as 0).
  /// \return a Backlash with half-width max(c, 0), at rest
  Backlash<Scalar> backlash() const { return Backlash<Scalar>(std::max(c(), Scalar(0))); }

  /// All parameters in the order of eq. (19); c, the last, must be >= 0 as for set_c (an estimate
  /// with c < 0 is projected first: Estimator::model() does that).
  /// \param theta the new parameter vector, num_params() entries
  template <typename T>
  void set_theta(const Eigen::MatrixBase<T>& theta) {
    detail::require_size(theta, this->num_params(), "theta");
    const auto c = theta[this->num_params() - 1];
    detail::require(!(c < Scalar(0)), "theta: c (the last entry, the backlash half-width) must be >= 0, got " +
                                          detail::format_number(static_cast<double>(c)));
    Front::set_theta(theta);
  }

  /// \copydoc ARX::try_simulate_deviations
  template <typename U>
  bool try_simulate_deviations(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    Backlash<Scalar> play = backlash();
    return this->simulate_front(
        u, y, this->linear_block(), [&play](Scalar x) { return play.step(x); }, this->input_deviation_range());
  }

  /// Projects an estimate onto the model's valid set: c >= 0.
  /// \param theta the estimate, its c raised to 0 when negative
  void constrain(Params& theta) const noexcept {
    Scalar& c = theta[this->num_params() - 1];
    if (c < Scalar(0)) c = Scalar(0);
  }

  /// What the model adds to the estimator's options (models/estimator_settings.hpp).
  using EstimatorSettings = BacklashEstimatorSettings;

  /// Zero, but c = c0 (the paper starts from c(0) = 0.01).
  /// \param settings the estimator settings: c0, the backlash half-width to start from
  /// \return theta to start the recursion from
  Params initial_estimate(const EstimatorSettings& settings) const {
    Params theta = Params::Zero(this->num_params());
    theta[this->num_params() - 1] = Scalar(settings.c0);
    return theta;
  }

  /// Key-term form (eqs. 15-18): [front, s(k)] . theta = y_c(k).
  /// Paper: s = 0.5 {(1 - sgn dx) g4 - (1 + sgn dx) g3} and y_c from eq. (27), with g3, g4 from
  /// eqs. (30)-(31) and dx the change of the model's free-run x.
  /// EquationError: the a-priori x decides the regime against the measured y(k-1) (eqs. 30-31); pushing
  /// up gives y = x - c (s = -1), down y = x + c (s = +1); inside the gap y(k) = y(k-1) says nothing
  /// about theta and the sample is not informative. Past x are clipped to [y - c, y + c].
  class KeyTerms {
   public:
    /// \copydoc ARX::KeyTerms::KeyTerms
    /// \param method KeyTermMethod::EquationError or KeyTermMethod::Paper: where the past internal variables come from
    KeyTerms(const PseudoHammersteinWiener& model, KeyTermMethod method)
        : m_front(model.na(), model.nb(), model.nk(), model.r(), method, model.ni()), m_method(method),
          m_last(model.num_params() - 1), m_phi(Params::Zero(model.num_params())) {}
    /// Where the input block continues linearly (FrontKeyTerms::set_input_range).
    /// \param range the input range as deviations from u0
    void set_input_range(const detail::InputDeviationRange& range) noexcept { m_front.set_input_range(range); }
    /// \copydoc ARX::KeyTerms::reset
    void reset() noexcept {
      m_front.reset();
      m_y_prev = Scalar(0);
      m_x_prev = Scalar(0);
    }
    /// \copydoc ARX::KeyTerms::step
    Regression<Scalar, Params> step(const Params& theta, Scalar u, Scalar y) noexcept {
      if (m_front.pending()) m_x_prev = m_front.store_a_posteriori(theta, m_phi);
      const Scalar carried = m_front.carried();
      const Scalar x = m_front.begin(theta, u, m_phi);
      const Scalar prediction = Backlash<Scalar>::map(x, m_y_prev, std::max(theta[m_last], Scalar(0)));
      Scalar target = y;
      bool informative = true;
      m_phi[m_last] = Scalar(0);
      if (m_method == KeyTermMethod::Paper) {
        const Scalar c = theta[m_last];
        const Scalar g3 = backlash_g3(x, m_y_prev, c);
        const Scalar g4 = backlash_g4(x, m_y_prev, c);
        const Scalar dx = x - m_x_prev;
        const Scalar sgn = dx > Scalar(0) ? Scalar(1) : (dx < Scalar(0) ? Scalar(-1) : Scalar(0));
        const Scalar y1 = x - Scalar(0.5) * c * (sgn + Scalar(1)) * g3 + Scalar(0.5) * c * (Scalar(1) - sgn) * g4;
        target = y - (m_y_prev - y1) * (g3 - Scalar(1)) * (g4 - Scalar(1));
        m_phi[m_last] = Scalar(0.5) * ((Scalar(1) - sgn) * g4 - (Scalar(1) + sgn) * g3);
      } else {
        // With no model yet (the estimate's front still all zero) the a-priori x says nothing about
        // the regime, so do not guess one: the sample informs the front as a Hammerstein sample.
        const Scalar c = std::max(theta[m_last], Scalar(0));
        if (!theta.head(m_last).isZero(0)) {
          const Scalar g3 = backlash_g3(x, m_y_prev, c);
          const Scalar g4 = backlash_g4(x, m_y_prev, c);
          m_phi[m_last] = g4 - g3;
          informative = g3 + g4 > Scalar(0);
        }
        m_front.store(std::isnan(y) ? x : std::min(std::max(x, y - c), y + c));
      }
      m_y_prev = std::isnan(y) ? prediction : y;
      return {m_phi, target - carried, prediction, x, informative};
    }

   private:
    detail::FrontKeyTerms<Scalar, Na_, Nb_, R_> m_front;
    KeyTermMethod m_method;
    Eigen::Index m_last;
    Params m_phi;
    Scalar m_y_prev = Scalar(0);
    Scalar m_x_prev = Scalar(0);  // the paper's method: the model's x(k-1), a posteriori
  };

  /// The output-error method's view: the front's free run with its sensitivities, then the
  /// backlash with the model's own previous output as its memory. Driving up (x - c > y(k-1))
  /// y = x - c, so dy/dtheta = [dx/dtheta, -1]; driving down y = x + c and [dx/dtheta, +1]; inside the
  /// gap y(k) = y(k-1) and its sensitivity is held. With c = 0 the block is the identity and counts
  /// as driving.
  ///
  /// A model at rest inside its own gap (front all zero, c > 0) has a zero gradient: nothing can
  /// move it. The estimator therefore starts P-H-W with c = 0, and these terms hold c there (its
  /// sensitivity zero) for the first `hold` samples after each start from rest, so that the front is
  /// learnt first, as a Hammerstein model's.
  class OutputErrorTerms {
   public:
    /// \copydoc ARX::OutputErrorTerms::OutputErrorTerms
    /// \param hold the number of first samples after a start from rest for which c is held
    explicit OutputErrorTerms(const PseudoHammersteinWiener& model, Eigen::Index hold = 0)
        : m_front(model.na(), model.nb(), model.nk(), model.r(), model.ni()),
          m_last(model.num_params() - 1), m_sensitivities{Params::Zero(model.num_params()),
                                                          Params::Zero(model.num_params())},
          m_hold(hold) {}
    /// The estimator's: hold = settings.backlash_hold.
    /// \param model the model whose orders the run has; only its orders are read
    /// \param settings the estimator settings, of which backlash_hold is read
    OutputErrorTerms(const PseudoHammersteinWiener& model, const EstimatorSettings& settings)
        : OutputErrorTerms(model, settings.backlash_hold) {}
    /// \copydoc ARX::OutputErrorTerms::reset
    void reset() noexcept {
      m_front.reset();
      m_y = Scalar(0);
      m_sensitivities[m_stored].setZero();
      m_next = m_stored;
      m_samples = 0;
    }
    /// \copydoc ARX::OutputErrorTerms::step
    SimulationStep<Scalar, Params> step(const Params& theta, Scalar u) noexcept {
      const Scalar x = m_front.step(theta, u);
      const Scalar c = std::max(theta[m_last], Scalar(0));
      // The step's sensitivity goes into the buffer that is not the stored y(k-1)'s, so that
      // accept() swaps the two instead of copying (a copy per step was a tenth of the window
      // refinement's time); inside the gap the step's sensitivity is the stored one itself.
      m_next = 1 - m_stored;
      Params& psi = m_sensitivities[m_next];
      if (x - c > m_y || (c == Scalar(0) && x >= m_y)) {
        psi.head(m_last) = m_front.sensitivity();
        psi[m_last] = Scalar(-1);
        m_output = x - c;
      } else if (x + c < m_y) {
        psi.head(m_last) = m_front.sensitivity();
        psi[m_last] = Scalar(1);
        m_output = x + c;
      } else {
        m_next = m_stored;
        m_output = m_y;
      }
      if (m_samples < m_hold) {
        if (m_next == m_stored) {  // never write into the stored sensitivity before accept()
          psi = m_sensitivities[m_stored];
          m_next = 1 - m_stored;
        }
        psi[m_last] = Scalar(0);
        ++m_samples;
      }
      return {m_output, m_sensitivities[m_next], x};
    }
    /// Stores the step: x and its sensitivity in the front, y(k) and its sensitivity as the
    /// backlash memory.
    void accept() noexcept {
      m_front.commit();
      m_y = m_output;
      m_stored = m_next;
    }
    /// \copydoc ARX::OutputErrorTerms::correct
    void correct(const Params& delta) noexcept {
      m_front.correct(delta.head(m_last));
      m_y += m_sensitivities[m_stored].dot(delta);
    }
    /// \copydoc ARX::OutputErrorTerms::stable
    bool stable(const Params& theta, Scalar radius) noexcept { return m_front.stable(theta, radius); }

   private:
    detail::FrontOutputError<Scalar, Na_, Nb_, R_> m_front;
    Eigen::Index m_last;
    // d y / d theta: the stored y(k-1)'s (the backlash memory's) and the last step's, two buffers
    // whose roles m_stored and m_next name
    Params m_sensitivities[2];
    int m_stored = 0;
    int m_next = 0;
    Scalar m_y = Scalar(0);       // the model's own y(k-1), the backlash memory
    Scalar m_output = Scalar(0);  // y(k) of the last step
    Eigen::Index m_hold;
    Eigen::Index m_samples = 0;
  };
};

}  // namespace bonl
