#pragma once
// The window refinement of the online output-error estimator: Levenberg-Marquardt on the free-run
// simulation error of the most recent samples, run in bounded slices beside the per-sample
// recursion, whose estimate it replaces when it predicts the newest samples better.
//
// Why: the recursion takes one Gauss-Newton step per sample. Along the ill-conditioned valley
// between a model's numerator and denominator (information matrices with condition numbers of 1e7
// to 1e8) those steps crawl, and the recursion cannot go back over what it has seen. Offline,
// Levenberg-Marquardt walks the same valley in a few iterations because it re-simulates the record.
// Here the samples since the refinement started, up to `length` of the newest, are kept in a ring
// buffer allocated once, and Levenberg-Marquardt iterates on them as offline refinement does: each
// iteration is one free run of a trial estimate over the window with its Jacobian (J'J and J'e
// accumulated on the way, so that a kept trial needs no pass of its own for the next step), the
// window growing with the data between iterations. A trial is kept where it simulates the samples
// the current estimate was scored on better. The damping is Levenberg's, the mean of J'J's diagonal
// on every parameter (detail::levenberg_scale says why). A window longer than it may be drops its
// older samples down to half that, its new start a kept run's state there. It may be `length`
// long, or under a forgetting factor the caller chose (a Steps schedule) 2 / (1 - lambda) samples,
// so that it forgets a changed plant as fast as the recursion does.
//
// After each kept iteration the window's estimate runs on over the samples that came during the
// pass, which it has not been fitted on, and is scored on the newer half of them beside the
// recursion's own a-priori prediction errors there (also made before the recursion saw each sample).
// Where the window's estimate predicts them better it is swapped into the recursion: its estimate,
// its run, and the covariance (w J'J + I / p0)^-1 with w the part of the window the recursion's
// forgetting keeps (its memory over the window's length, at most 1), so that the recursion tracks
// on as fast as before. Not where the window's data leave a parameter undetermined (a constant or
// zero input: determines_every_parameter) or that covariance is not numerically positive definite.
// The estimator reports the window's estimate (has_estimate, estimate) while it predicts the newest
// samples better than the recursion's, or not clearly worse, and the window's data determine every
// parameter; brought up to date by one Levenberg-Marquardt step over the window and the samples
// since, so that it lags the data by no pass.
// Where the recursion predicts them clearly better (by more than kSignificance x n noise variances)
// on four judgements in a row, its estimate is scored on the window: if it simulates the window
// better it becomes the window's estimate, else the plant changed and the window restarts with the
// samples to come. Only under the adaptive memory: a window that keeps to the caller's forgetting
// forgets a change as fast as the recursion does, and a restart would only drop the changed plant's
// samples it holds.
// Every phase advances by at most `work_per_sample` model steps per update; a solve is an update's
// slice of its own.
//
// The window works in the recursion's normalised coordinates (set_scales, estimator/normalisation.hpp):
// its Jacobian, errors, steps, damping and covariance are the same in any units of the data.
// The estimator runs two by default: one starting from the output-error recursion's estimate and one
// from an equation-error recursion's beside it (advance()'s `start`), as identify() refines from both
// (the criterion is not convex). On by default; docs/explanation/algorithm.md has the known systems'
// figures with and without it.

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "../detail/damping.hpp"
#include "../detail/normal_equations.hpp"
#include "../detail/validate.hpp"
#include "../models/estimator_settings.hpp"

namespace bonl {

/// The output-error estimator's window refinement (estimator/window_refinement.hpp), chosen at
/// construction; EstimatorOptions::window.
struct WindowRefinementOptions {
  /// On by default (docs/explanation/algorithm.md has the known systems' figures with and without
  /// it). Used by the output-error method only.
  bool enabled = true;
  /// The most samples the refinement fits at once (>= 100): its memory. Under a forgetting factor
  /// the caller chose (a Steps schedule) it is 2 / (1 - lambda) where that is shorter. The ring buffer
  /// holds twice as many.
  Eigen::Index length = 4000;
  /// Model steps of the refinement per update (>= 2): the bound on one update's extra work. One
  /// iteration over a window of N samples takes N / work_per_sample updates.
  Eigen::Index work_per_sample = 8;
  /// A second window beside, started from an equation-error recursion's estimate instead of the
  /// output-error recursion's: identify()'s two starts (the criterion is not convex, and from the
  /// output-error recursion alone the window settled in a wrong minimum on some records). Doubles
  /// the window's work and adds the equation-error update.
  bool equation_error_start = true;

  /// Throws std::invalid_argument for a setting out of range.
  void validate() const {
    detail::require(length >= 100, "window length must be >= 100 samples, got " + std::to_string(length));
    detail::require(work_per_sample >= 2,
                    "window work_per_sample must be >= 2 model steps, got " + std::to_string(work_per_sample));
  }
};

/// What the window refinement did, counted since the estimator's last reset().
struct WindowRefinementCounts {
  Eigen::Index iterations = 0;     ///< Levenberg-Marquardt steps kept
  Eigen::Index refused_steps = 0;  ///< trial steps that did not simulate the window better
  Eigen::Index swaps = 0;          ///< refined estimates swapped into the recursion
  Eigen::Index refusals = 0;  ///< refined estimates not swapped in: the recursion predicted the newest samples as well
  Eigen::Index undetermined = 0;  ///< refined estimates not swapped in although they predicted the newest samples
                                  ///< better: the window's data do not determine every parameter (a poorly exciting
                                  ///< input), or the covariance would not be numerically positive definite
  Eigen::Index reseeds = 0;  ///< restarts with the newest samples only: the recursion's estimate predicted them clearly
                             ///< better and the window worse (a change)
  Eigen::Index overruns =
      0;  ///< restarts because the slices fell behind the ring buffer or a run left the finite numbers

  /// Both windows' counts together (the estimator's second window, EstimatorOptions::window).
  /// \param other the counts to add
  /// \return this, the sums
  WindowRefinementCounts& operator+=(const WindowRefinementCounts& other) noexcept {
    iterations += other.iterations;
    refused_steps += other.refused_steps;
    swaps += other.swaps;
    refusals += other.refusals;
    undetermined += other.undetermined;
    reseeds += other.reseeds;
    overruns += other.overruns;
    return *this;
  }
};

/// The window refinement for one Model's output-error estimator. push() each sample (deviations from
/// the operating point) with the recursion's a-priori prediction error, then advance(); when
/// advance() returns true, theta(), covariance() and run() are what the estimator adopts.
/// Allocation-free and noexcept after construction.
template <class Model>
class WindowRefinement {
 public:
  using Scalar = typename Model::Scalar;                                       ///< the model's arithmetic type
  using Params = typename Model::Params;                                       ///< the model's parameter vector
  using Matrix = Eigen::Matrix<Scalar, Model::kNumParams, Model::kNumParams>;  ///< n x n
  using Run = typename Model::OutputErrorTerms;  ///< a free run of the model with its sensitivities

  /// A refinement with an empty window; a swapped-in covariance is (w J'J + I / p0)^-1, with w the
  /// part of the window's samples the recursion's forgetting keeps (its memory over the window's
  /// length, at most 1).
  /// \param structure the model whose orders are refined
  /// \param options the window's length and the work per sample
  /// \param settings the estimator's model settings (for its OutputErrorTerms)
  /// \param radius the estimator's stability radius
  /// \param p0 the estimator's P(0) scale
  /// \param follow_memory whether the window keeps to the recursion's memory (advance()): at most 2
  /// memory samples (about 86% of the weight the recursion gives its past). True where the
  /// forgetting is the caller's choice (a Steps schedule), so that the window forgets a changed plant
  /// as fast as the caller asked for; false for the adaptive memory, whose cuts while the estimate
  /// converges are for the recursion's linearisation, which the window redoes on every pass.
  WindowRefinement(const Model& structure, const WindowRefinementOptions& options, const ModelSettings<Model>& settings,
                   double radius, double p0, bool follow_memory)
      : m_model(structure), m_options(options), m_radius(Scalar(radius)), m_p0(Scalar(p0)),
        m_follow_memory(follow_memory), m_capacity(2 * options.length), m_u(static_cast<std::size_t>(m_capacity)),
        m_y(m_u.size()), m_e(m_u.size()), m_start_run(detail::output_error_terms(structure, settings)),
        m_trial(m_start_run), m_half_trial(m_start_run), m_half_run(m_start_run), m_catch_up(m_start_run) {
    const Eigen::Index n = structure.num_params();
    m_minimum = std::min(options.length, std::max<Eigen::Index>(100, 10 * n));
    m_theta = Params::Zero(n);
    m_start_theta = m_theta;
    m_trial_theta = m_theta;
    m_half_theta = m_theta;
    m_half_trial_theta = m_theta;
    m_estimate = m_theta;
    m_recent_gradient = m_theta;
    m_delta = m_theta;
    m_shift = m_theta;
    m_gradient = m_theta;
    m_trial_gradient = m_theta;
    m_scale = m_theta;
    m_parameter_scale = Params::Ones(n);
    m_regressor_scale = m_parameter_scale;
    m_normal = Matrix::Zero(n, n);
    m_trial_normal = m_normal;
    m_recent_normal = m_normal;
    m_system = m_normal;
    m_covariance = m_normal;
    m_ldlt.compute(Matrix::Identity(n, n));  // sizes its storage once
    m_rows.resize(kBlock, n);
    m_errors.resize(kBlock);
  }

  /// The estimator's coordinates (estimator/normalisation.hpp): the window's Jacobian, errors,
  /// steps and covariance are the recursion's, theta = parameter_scale .* theta_n and errors times
  /// inverse_output_scale, so that its damping and its tests mean the same in any units. Set before
  /// samples are scored (the samples pushed are kept in the data's units).
  /// \param parameter_scale d, num_params() positive values
  /// \param inverse_output_scale 1 / sy
  void set_scales(const Params& parameter_scale, Scalar inverse_output_scale) noexcept {
    m_parameter_scale = parameter_scale;
    m_inverse_output_scale = inverse_output_scale;
    m_regressor_scale = parameter_scale * inverse_output_scale;
    // The recursion starts estimating now: its estimate is a start worth refining once it has had
    // as many samples as a window's first pass needs (the samples it waited for are in the window).
    m_first_pass = m_count + m_minimum;
  }

  /// Starts over after the sample in hand: the window begins with the next sample, from the run
  /// `run` (the recursion's, which has just taken that sample) and the estimate theta.
  /// \param theta the recursion's estimate
  /// \param run the recursion's free run, which has just taken the sample in hand
  void restart(const Params& theta, const Run& run) noexcept {
    m_start_run = run;
    m_start_theta = theta;
    m_theta = theta;
    m_start = m_count;
    m_length = 0;
    m_have_iterate = false;
    m_determined = false;
    m_have_half = false;
    m_reseed_pass = false;
    m_clearly_worse = 0;
    m_has_estimate = false;
    m_idle = false;
    m_damping = kInitialDamping;
    m_phase = Phase::Collect;
  }

  /// Everything back to the start (the estimator's reset): the counts too.
  /// \param theta the recursion's estimate
  /// \param run the recursion's free run, at rest
  void reset(const Params& theta, const Run& run) noexcept {
    m_count = 0;
    m_counts = WindowRefinementCounts{};
    restart(theta, run);
  }

  /// One sample: u and y as the model's blocks see them (deviations from the operating point), and
  /// the recursion's a-priori prediction error of y, all in the data's units.
  /// \param u the input's deviation u(k) - u0
  /// \param y the output's deviation y(k) - y0
  /// \param recursion_error the recursion's a-priori error of y(k)
  void push(Scalar u, Scalar y, Scalar recursion_error) noexcept {
    const auto slot = static_cast<std::size_t>(m_count % m_capacity);
    m_u[slot] = u;
    m_y[slot] = y;
    m_e[slot] = recursion_error;
    ++m_count;
  }

  /// At most work_per_sample model steps of the refinement.
  /// \param recursion the recursion's estimate after this sample
  /// \param run the recursion's run after this sample
  /// \param memory the recursion's forgetting's memory in samples, 1 / (1 - lambda) (infinity without
  /// forgetting)
  /// \param start the estimate a first pass and a re-seeded pass start from; null: the recursion's
  /// (the estimator's second window starts from its equation-error recursion's)
  /// \return true when a refined estimate is to be swapped in: theta(), covariance() and run() hold it
  bool advance(const Params& recursion, const Run& run, double memory, const Params* start = nullptr) noexcept {
    m_memory = memory;
    m_start_estimate = start ? start : &recursion;
    if (!m_follow_memory && memory > static_cast<double>(m_options.length)) {
      // The adaptive memory keeps more samples than a window may hold: the recursion's estimate is
      // then the better informed one, and swapped or reported, the window's would cap it at
      // `length` samples' worth (measured: under 2% noise the error at 16000 samples was above the
      // one at 4000). The window idles until the memory is cut back (a change), then starts afresh.
      m_idle = true;
      m_has_estimate = false;
      return false;
    }
    if (m_idle) {
      restart(recursion, run);
      return false;
    }
    if (m_count - m_start > m_capacity) {  // the window's first samples are being overwritten
      ++m_counts.overruns;
      restart(recursion, run);
      return false;
    }
    Eigen::Index budget = m_options.work_per_sample;
    while (budget > 0) {
      switch (m_phase) {
        case Phase::Collect:
          if (m_count - m_start < m_minimum || m_count < m_first_pass || !stable_start()) return false;
          m_trial_theta = *m_start_estimate;  // the first pass: the start, kept whatever it scores
          begin_pass(recursion, run);
          break;
        case Phase::Pass:
          budget -= pass_steps(budget);
          if (m_position == m_pass_length) end_pass(recursion, run);
          break;
        case Phase::CatchUp:
          budget -= catch_up_steps(budget);
          if (m_position == m_count - m_start && judge_recent(recursion, run)) return true;
          break;
        case Phase::Solve: solve(recursion, run); return false;  // a solve is a slice of its own
      }
    }
    return false;
  }

  /// The estimate to swap in (after advance() returned true)
  /// \return num_params values
  const Params& theta() const noexcept { return m_theta; }
  const Matrix& covariance() const noexcept { return m_covariance; }  ///< its covariance \return n x n, symmetric
  /// Its free run, up to the sample in hand
  /// \return the run, to continue from
  const Run& run() const noexcept { return m_catch_up; }
  /// What it did since the last reset
  /// \return the counts
  const WindowRefinementCounts& counts() const noexcept { return m_counts; }
  /// Whether estimate() is the estimate to report: at the last judgement the window's estimate
  /// predicted the newest samples better than the recursion's, or not clearly worse, and the
  /// window's data determine every parameter. False after a restart, until such a judgement.
  /// \return true while estimate() stands
  bool has_estimate() const noexcept { return m_has_estimate; }
  /// The window's estimate as of its last judgement (valid while has_estimate()).
  /// \return num_params values
  const Params& estimate() const noexcept { return m_estimate; }

 private:
  enum class Phase { Collect, Pass, CatchUp, Solve };

  /// The recursion predicting the newest samples better than the window's estimate by more than
  /// this many noise variances per parameter, kConfirmations judgements in a row, restarts the window
  /// (a chi-squared variable with n degrees of freedom is beyond 6 n with probability below 0.1% for
  /// n >= 5, where the noise is white).
  static constexpr double kSignificance = 6.0;
  /// Why four: one judgement is made on a few hundred errors, and under coloured noise (AR(1), pole
  /// 0.9) those are worth far fewer independent ones, so that fewer judgements in a row restarted
  /// windows that had met no change and left their estimates fitted on a fraction of the data (on
  /// the known systems, scripts/online_accuracy.sh). The price: under the adaptive memory a real
  /// change is acted on later, and on some known systems the window tracked a step change a few
  /// hundred samples slower.
  static constexpr int kConfirmations = 4;
  /// The damping a window starts with, as the offline refinement's; again after kMaxTrials refused
  /// steps (solve).
  static constexpr double kInitialDamping = 1e-3;
  /// Refused trials in a row after which the estimate is taken as converged on the window: the next
  /// pass re-scores it on the grown window instead of trying a step.
  static constexpr int kMaxTrials = 3;
  /// The fewest new samples the swap test judges on.
  static constexpr Eigen::Index kMinimumRecent = 20;
  /// The smallest pivot of the window's J'J, relative to its largest, for its data to determine every
  /// parameter they reach (determines_every_parameter). Measured on the known systems' rich data
  /// (scripts/online_accuracy.sh, under noise): 4 of about 5,400 swaps had ratios below it (most are
  /// 1e-7 to 1e-2), and refusing them moved no figure; on the soak's constant and zero inputs they
  /// are zero or negative, rounding's.
  static constexpr double kRankTolerance = 1e-10;
  /// The least information a window's data give per sample for it to say anything (informative()): in
  /// the normalised coordinates an exciting input gives each parameter a sensitivity of order 1, its
  /// J'J diagonal of order 1 per sample; 1e-6 is sensitivities of 1e-3 of that.
  static constexpr double kMinimumInformation = 1e-6;
  /// The smallest pivot of the swapped information matrix, relative to its largest: below it the
  /// inverse's smallest eigenvalues are rounding's.
  static constexpr double kPositiveTolerance = 1e-13;
  /// Rows of the Jacobian gathered before they are added to J'J.
  static constexpr Eigen::Index kBlock = 32;

  static double squared(Scalar e) noexcept { return static_cast<double>(e) * static_cast<double>(e); }
  std::size_t slot(Eigen::Index k) const noexcept { return static_cast<std::size_t>((m_start + k) % m_capacity); }
  double num_params() const noexcept { return static_cast<double>(m_theta.size()); }

  /// Whether the start may begin a pass: finite, and its linear blocks within the stability radius,
  /// as every step the window keeps. Why: the recursions' estimates are not held to that test (the
  /// equation-error one's least of all), a first pass keeps its start whatever it scores, and from an
  /// unstable estimate no step is stable: the window refused a step on every update for good
  /// (measured: 3,819 in 4,000 samples, a Wiener-Hammerstein system under 2% noise). The window
  /// waits for a stable start instead.
  bool stable_start() noexcept { return m_start_estimate->allFinite() && m_trial.stable(*m_start_estimate, m_radius); }

  /// The most samples the window holds now: `length`, or where it follows the recursion's memory,
  /// 2 memory samples, at least twice the fewest a pass starts with.
  Eigen::Index longest() const noexcept {
    if (!m_follow_memory || !(2.0 * m_memory < static_cast<double>(m_options.length))) return m_options.length;
    return std::max(static_cast<Eigen::Index>(2.0 * m_memory), 2 * m_minimum);
  }

  /// A pass of m_trial_theta over the window as it is now; a window longer than longest() first drops
  /// its older samples, starting anew where a kept pass left half of longest() (its run there).
  void begin_pass(const Params& recursion, const Run& run) noexcept {
    if (m_count - m_start > longest()) {
      if (!m_have_half) {
        ++m_counts.overruns;
        restart(recursion, run);
        return;
      }
      m_start += m_half_offset;
      m_start_run = m_half_run;
      m_start_theta = m_half_theta;
      m_have_half = false;
      m_have_iterate = false;  // scored on another window: the next pass re-scores it, kept as it is
      m_trial_theta = m_theta;
    }
    m_trial = m_start_run;
    m_shift = m_trial_theta - m_start_theta;  // a member: an expression would be a temporary
    m_trial.correct(m_shift);
    m_trial_normal.setZero();
    m_trial_gradient.setZero();
    m_filled = 0;
    m_sse_trial = 0.0;
    m_sse_common = 0.0;
    m_pass_length = m_count - m_start;
    const Eigen::Index keep = longest() / 2;
    m_half_offset_trial = m_pass_length > keep ? m_pass_length - keep : 0;
    m_position = 0;
    m_phase = Phase::Pass;
  }

  /// The trial's free run with its Jacobian; the run's state where half of longest() is left is kept
  /// for a later slide of the window.
  Eigen::Index pass_steps(Eigen::Index budget) noexcept {
    const Eigen::Index samples = std::min(budget, m_pass_length - m_position);
    for (Eigen::Index i = 0; i < samples; ++i, ++m_position) {
      if (m_position == m_half_offset_trial && m_half_offset_trial > 0) {
        m_half_trial = m_trial;
        m_half_trial_theta = m_trial_theta;
      }
      const auto index = slot(m_position);
      const auto step = m_trial.step(m_trial_theta, m_u[index]);
      const Scalar error = (m_y[index] - step.output) * m_inverse_output_scale;
      m_rows.row(m_filled) = step.sensitivity.cwiseProduct(m_regressor_scale).transpose();
      m_errors[m_filled] = error;
      if (++m_filled == kBlock) flush_rows(m_trial_normal, m_trial_gradient);
      m_trial.accept();
      m_sse_trial += squared(error);
      if (m_position < m_length) m_sse_common += squared(error);
    }
    if (m_position == m_pass_length) flush_rows(m_trial_normal, m_trial_gradient);
    return std::max<Eigen::Index>(samples, 1);
  }

  /// J'J and J'e gathered a block of rows at a time (detail::add_rows).
  /// \param normal the J'J (lower triangle) the rows are added to
  /// \param gradient the J'e they are added to
  void flush_rows(Matrix& normal, Params& gradient) noexcept {
    detail::add_rows(normal, gradient, m_rows.topRows(m_filled), m_errors.head(m_filled));
    m_filled = 0;
  }

  /// Keeps the trial where it simulates the samples the estimate was scored on better (or where
  /// there is no estimate yet), then runs it on over the samples since; else a larger damping.
  void end_pass(const Params& recursion, const Run& run) noexcept {
    const bool finite = std::isfinite(m_sse_trial) && m_trial_normal.allFinite() && m_trial_gradient.allFinite();
    const bool kept = finite && (!m_have_iterate || m_sse_common <= m_objective);
    if (m_reseed_pass) {
      // The recursion's estimate, which predicted the newest samples clearly better: where it does
      // not simulate the window better either, the plant changed, and the window restarts with the
      // samples to come; else it is the estimate from here on.
      m_reseed_pass = false;
      if (!kept) {
        ++m_counts.reseeds;
        restart(recursion, run);
        return;
      }
      m_delta.setZero();  // no damping update: not a step of the iteration
    }
    if (kept) {
      if (m_have_iterate && !m_delta.isZero()) {
        // The damping follows the gain ratio, as in refine_output_error.
        const double predicted = static_cast<double>(m_delta.dot(m_gradient) +
                                                     Scalar(m_damping) * m_delta.dot(m_scale.cwiseProduct(m_delta)));
        const double rho = predicted > 0.0 ? (m_objective - m_sse_common) / predicted : 1.0;
        m_damping = detail::damping_after_kept_step(m_damping, rho);
        ++m_counts.iterations;
      }
      m_theta = m_trial_theta;
      m_objective = m_sse_trial;
      m_length = m_pass_length;
      m_normal = m_trial_normal;
      m_normal.template triangularView<Eigen::StrictlyUpper>() = m_normal.transpose();
      // The rank test of the J'J the next judgement uses, here rather than in that judgement: the
      // judgement that swaps already factorises twice and inverts, and was the costliest update.
      m_determined = determines_every_parameter();
      m_gradient = m_trial_gradient;
      m_have_iterate = true;
      m_trials = 0;
      if (m_half_offset_trial > 0) {
        m_half_offset = m_half_offset_trial;
        m_half_run = m_half_trial;
        m_half_theta = m_half_trial_theta;
        m_have_half = true;
      }
      m_catch_up = m_trial;
      m_recent_normal.setZero();
      m_recent_gradient.setZero();
      m_sse_recent = 0.0;
      m_sse_recent_recursion = 0.0;
      m_scored = 0;
      m_phase = Phase::CatchUp;
      return;
    }
    ++m_counts.refused_steps;
    ++m_trials;
    m_damping = std::min(m_damping * 4.0, 1e12);
    m_phase = Phase::Solve;
  }

  /// The window's estimate on from the window's end over the samples that came since, beside the
  /// recursion's a-priori errors on them. Both are scored on the newer half of those samples only:
  /// the recursion's errors there are closer to what its estimate now does.
  Eigen::Index catch_up_steps(Eigen::Index budget) noexcept {
    const Eigen::Index samples = std::min(budget, m_count - m_start - m_position);
    const Eigen::Index scored_from = m_length + (m_count - m_start - m_length) / 2;
    for (Eigen::Index i = 0; i < samples; ++i, ++m_position) {
      const auto index = slot(m_position);
      const auto step = m_catch_up.step(m_theta, m_u[index]);
      const Scalar error = (m_y[index] - step.output) * m_inverse_output_scale;
      m_rows.row(m_filled) = step.sensitivity.cwiseProduct(m_regressor_scale).transpose();
      m_errors[m_filled] = error;
      if (++m_filled == kBlock) flush_rows(m_recent_normal, m_recent_gradient);
      m_catch_up.accept();
      if (m_position < scored_from) continue;
      m_sse_recent += squared(error);
      m_sse_recent_recursion += squared(m_e[index] * m_inverse_output_scale);
      ++m_scored;
    }
    if (m_position == m_count - m_start) flush_rows(m_recent_normal, m_recent_gradient);
    return std::max<Eigen::Index>(samples, 1);
  }

  /// On the samples since the window's end: a swap (returns true), a restart, or neither.
  bool judge_recent(const Params& recursion, const Run& run) noexcept {
    m_phase = Phase::Solve;
    const Eigen::Index recent = m_position - m_length;
    if (!std::isfinite(m_sse_recent)) {
      ++m_counts.overruns;
      restart(recursion, run);
      return false;
    }
    if (recent < kMinimumRecent || m_scored == 0) return false;
    const double variance = m_sse_recent_recursion / static_cast<double>(m_scored);
    const bool determined = m_determined;
    if (m_sse_recent < m_sse_recent_recursion) {
      report(determined);
      if (!determined || !swap_covariance()) {
        ++m_counts.undetermined;
        return false;
      }
      ++m_counts.swaps;
      m_clearly_worse = 0;
      return true;
    }
    const bool clearly_worse = m_sse_recent_recursion + kSignificance * num_params() * variance < m_sse_recent;
    report(determined && !clearly_worse);
    m_clearly_worse = clearly_worse ? m_clearly_worse + 1 : 0;
    if (!m_follow_memory && m_clearly_worse >= kConfirmations && stable_start()) {
      m_clearly_worse = 0;
      m_reseed_pass = true;
      m_trial_theta = *m_start_estimate;
      begin_pass(recursion, run);
      return false;
    }
    ++m_counts.refusals;
    return false;
  }

  /// The window's estimate becomes the one to report, or the recursion's does. Why the window's
  /// where it predicts the newest samples about as well: the recursion's adaptive memory keeps
  /// about half the samples it has seen, and each of its steps after a swap adds that memory's
  /// variance, while the window's estimate is the fit to all of them up to its pass (the table in
  /// docs/explanation/algorithm.md has both). The window's estimate is reported brought up to date:
  /// one Levenberg-Marquardt step from it over the window and the samples since, whose Jacobian the
  /// catch-up run gathered, so that it lags the data by no pass (where that step leaves the valid,
  /// stable or finite estimates, the window's own).
  void report(bool window) noexcept {
    m_has_estimate = window;
    if (!window) return;
    m_system = m_recent_normal;
    m_system.template triangularView<Eigen::StrictlyUpper>() = m_system.transpose();
    m_system += m_normal;
    m_shift = m_gradient + m_recent_gradient;  // J'e over the window and the samples since
    detail::levenberg_scale(m_system, m_scale);
    m_system.diagonal() += Scalar(m_damping) * m_scale;
    m_ldlt.compute(m_system);
    m_delta = m_ldlt.solve(m_shift);  // m_delta and m_scale are set afresh by the next solve()
    m_estimate = m_theta + m_delta.cwiseProduct(m_parameter_scale);
    m_model.constrain(m_estimate);
    if (!m_estimate.allFinite() || !m_catch_up.stable(m_estimate, m_radius)) m_estimate = m_theta;
  }

  /// Whether the window's J'J has full numerical rank: its pivoted LDLT's smallest pivot above
  /// kRankTolerance of its largest, on data that say anything at all (informative()). Why: under a
  /// constant or zero input the window's data leave directions undetermined (in P-H-W, the gain
  /// between the nonlinearity and the linear block), its estimate wanders along them from pass to
  /// pass, and swapped in, that walk became the recursion's: on the soak |theta| grew to 4e5 and the
  /// swapped covariance lost its positive definiteness. The recursion's own estimate is the better
  /// one to keep there. A parameter the data do not reach at all (a zero pivot) is undetermined too:
  /// left out of the test, it let a window of zero input, which reaches P-H-W's f_0 alone, swap in
  /// b_1 = -2804 (bonl_soak, seed 10); the backlash's c, held at 0 for its first 200 samples after a
  /// start, is reached by every window longer than that.
  bool determines_every_parameter() noexcept {
    if (!informative()) return false;
    m_ldlt.compute(m_normal);
    const auto pivots = m_ldlt.vectorD();
    const double largest = static_cast<double>(pivots.maxCoeff());
    if (!(largest > 0.0) || !std::isfinite(largest)) return false;
    for (Eigen::Index i = 0; i < pivots.size(); ++i) {
      const double pivot = static_cast<double>(pivots[i]);
      if (!(pivot > kRankTolerance * largest)) return false;
    }
    return true;
  }

  /// Whether the window's data say anything at all: the largest diagonal entry of its J'J, in the
  /// recursion's normalised coordinates, above kMinimumInformation per sample. The relative tests
  /// (determines_every_parameter, the steps' gain ratio) cannot see a window without information:
  /// under a zero input the sensitivities decay to 1e-190, steps fitted to that rounding were kept,
  /// their rank test passed, and one swapped b1 = -2804 into the recursion (bonl_soak, seed 10).
  bool informative() const noexcept {
    return static_cast<double>(m_normal.diagonal().maxCoeff()) > kMinimumInformation * static_cast<double>(m_length);
  }

  /// The covariance the recursion would hold after the window's samples: the window's information,
  /// of which its forgetting keeps about `memory` samples' worth, on top of P(0) = p0 I. False where
  /// it is not numerically positive definite (its pivots within rounding of zero), which the
  /// recursion's downdates would turn indefinite.
  bool swap_covariance() noexcept {
    const double kept = std::min(1.0, m_memory / static_cast<double>(m_length));
    m_covariance = m_normal * Scalar(kept);
    m_covariance.diagonal().array() += Scalar(1) / m_p0;
    m_ldlt.compute(m_covariance);
    const auto pivots = m_ldlt.vectorD();
    if (m_ldlt.info() != Eigen::Success || !(pivots.minCoeff() > kPositiveTolerance * pivots.maxCoeff())) return false;
    m_covariance.setIdentity();
    m_ldlt.solveInPlace(m_covariance);
    // Exactly symmetric, as the recursion keeps P: the upper triangle mirrors the lower.
    m_covariance.template triangularView<Eigen::StrictlyUpper>() = m_covariance.transpose();
    return m_covariance.allFinite();
  }

  /// One damped Gauss-Newton step from the estimate, and the pass of its trial. After kMaxTrials
  /// refused steps in a row the estimate itself is re-scored on the grown window.
  void solve(const Params& recursion, const Run& run) noexcept {
    if (!informative()) m_trials = kMaxTrials;  // no step on data that say nothing: re-scored as it is
    if (m_trials >= kMaxTrials) {
      // The estimate is taken as converged: the grown window is a new problem, started with the
      // initial damping. Carried on, the damping that refused steps raised (under a constant input,
      // to its ceiling: no step changes the fit there beyond rounding) kept every later step refused
      // where restarts no longer reset it (bonl_soak: 3,585 steps kept in 1e8 samples).
      m_damping = kInitialDamping;
      m_trials = 0;
      m_trial_theta = m_theta;
      m_delta.setZero();
      begin_pass(recursion, run);
      return;
    }
    m_system = m_normal;
    detail::levenberg_scale(m_system, m_scale);
    m_system.diagonal() += Scalar(m_damping) * m_scale;
    m_ldlt.compute(m_system);
    m_delta = m_ldlt.solve(m_gradient);
    m_trial_theta = m_theta + m_delta.cwiseProduct(m_parameter_scale);
    m_model.constrain(m_trial_theta);
    m_delta = (m_trial_theta - m_theta).cwiseQuotient(m_parameter_scale);
    if (!m_trial_theta.allFinite() || !m_trial.stable(m_trial_theta, m_radius)) {
      // A step too long to keep the linear block stable: a shorter one, with more damping, until
      // one is (the estimate is stable, so a short enough step is). Not a trial that the data
      // refused: counted toward kMaxTrials, the damping's reset would undo its growth, and from a
      // poor start every step stayed too long (measured: a window held at the recursion's first
      // estimate for 4000 samples).
      ++m_counts.refused_steps;
      m_damping = std::min(m_damping * 4.0, 1e12);
      return;  // solved again in the next update
    }
    begin_pass(recursion, run);
  }

  Model m_model;  // the structure: constrain()
  WindowRefinementOptions m_options;
  Scalar m_radius;
  Scalar m_p0;
  bool m_follow_memory;  // the window keeps to 2 m_memory samples (set at construction)
  Eigen::Index m_capacity;
  Eigen::Index m_minimum = 100;       // samples in a window before its first pass
  Eigen::Index m_first_pass = 0;      // and the sample count the first pass waits for (set_scales)
  std::vector<Scalar> m_u, m_y, m_e;  // the ring buffer: inputs, outputs, the recursion's a-priori errors
  Eigen::Index m_count = 0;           // samples pushed since the last reset
  Eigen::Index m_start = 0;           // the window's first sample
  Eigen::Index m_length = 0;          // the samples the estimate was scored on, from m_start
  Eigen::Index m_pass_length = 0;     // the samples of the current pass
  Eigen::Index m_position = 0;        // the phase's next sample, from m_start
  Phase m_phase = Phase::Collect;
  Run m_start_run;   // the window's start state, simulated with m_start_theta
  Run m_trial;       // the trial's run
  Run m_half_trial;  // the trial's run where half of longest() is left ...
  Run m_half_run;    // ... and a kept one's: the start after a slide
  Run m_catch_up;    // the estimate's run on to the sample in hand
  Params m_theta;    // the window's estimate
  Params m_start_theta, m_trial_theta, m_half_theta, m_half_trial_theta;
  Params m_delta, m_shift, m_gradient, m_trial_gradient, m_scale;  // m_delta in the recursion's coordinates
  Params m_parameter_scale, m_regressor_scale;                     // set_scales(); 1 where not normalised
  Scalar m_inverse_output_scale = Scalar(1);
  const Params* m_start_estimate = nullptr;  // where passes start from, for the duration of advance()
  Matrix m_normal, m_trial_normal;           // J'J at the estimate and at the trial
  Matrix m_recent_normal;                    // J'J over the samples since the window's end, at the estimate
  Params m_recent_gradient;                  // J'e there
  Eigen::Matrix<Scalar, Eigen::Dynamic, Model::kNumParams, Model::kNumParams == 1 ? Eigen::ColMajor : Eigen::RowMajor>
      m_rows;                                         // Jacobian rows not yet in J'J
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> m_errors;  // their errors
  Eigen::Index m_filled = 0;
  Matrix m_system, m_covariance;
  Eigen::LDLT<Matrix> m_ldlt;
  double m_objective = 0.0;                                 // the estimate's sum of squares over its m_length samples
  double m_sse_trial = 0.0, m_sse_common = 0.0;             // the trial's, over its pass and over m_length
  double m_sse_recent = 0.0, m_sse_recent_recursion = 0.0;  // since the window's end
  double m_damping = kInitialDamping;
  double m_memory = std::numeric_limits<double>::infinity();  // the recursion's, in samples
  bool m_have_iterate = false;
  bool m_determined = false;  // determines_every_parameter() of m_normal, taken where m_normal was set
  bool m_have_half = false;
  Eigen::Index m_half_offset = 0;        // where m_half_run is, from m_start
  Eigen::Index m_half_offset_trial = 0;  // where this pass keeps m_half_trial (0: nowhere)
  bool m_reseed_pass = false;            // the pass scores the recursion's estimate on the window
  Params m_estimate;                     // the window's estimate as of its last judgement ...
  bool m_has_estimate = false;           // ... and whether it is the one to report
  bool m_idle = false;                   // the recursion's memory is longer than the window may be
  int m_clearly_worse = 0;               // judgements in a row the recursion predicted clearly better
  int m_trials = 0;
  Eigen::Index m_scored = 0;  // the samples the swap test scores
  WindowRefinementCounts m_counts;
};

}  // namespace bonl
