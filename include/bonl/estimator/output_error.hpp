#pragma once
// Refinement of an identified model by minimising its free-run simulation error on the
// identification record or records (output-error / simulation-error criterion), by Levenberg-Marquardt.
// Under white output noise the key-term regressions are biased (their regressors carry the noise);
// the simulation error is not, and it is the criterion models are judged by.
// The Jacobian is analytic: one free run of the model's OutputErrorTerms with theta held fixed gives
// each sample's simulated output and its sensitivity d y(k) / d theta, the same recursion the
// recursive output-error estimator runs (models/model_steps.hpp). Models with a backlash are
// piecewise smooth in theta; their sensitivity is the one of the piece the run is on.
// The linear block is kept stable: a start with poles outside the unit circle is reflected inside
// (models/poles.hpp) and a step that would leave the stable set is not taken.
// With a state-initialisation window of m samples each record's free run starts after its first m
// samples, measured, as Model::simulate(u, u_past, y_past) starts it, and is scored after them: the
// model is fitted the way a protocol with that window will use it. The measured past sets the state
// through the model's internal variables, which depend on theta in ways the OutputErrorTerms'
// recursion from rest does not carry, so that Jacobian is taken by forward differences of the free
// run (num_params() + 1 runs per iteration instead of one).
// With a mask, only the outputs where it is 1 are fitted: the free run goes on through the others on
// their measured input (outputs missing, as in a sensor's dropout, or held out, as a block a fit must
// not see), so that the input there still carries an integrating or slow system's state to the
// samples after them, where cutting the record in two would restart the state from measured outputs.
// With InitialState::Estimated the window's outputs that the state after it depends on (found by
// probing: the model's lags, or further back where its state remembers more, as a backlash inside
// its gap) are estimated beside theta, each record's own: their Jacobian columns touch only their
// record's run.

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
#include "../models/poles.hpp"
#include "initial_state.hpp"
#include "record_view.hpp"

namespace bonl {

/// What refine_output_error() did: its costs before and after, its iterations, and which start won.
struct RefinementReport {
  double initial_cost = std::numeric_limits<double>::infinity();  ///< mean squared simulation error
  double final_cost = std::numeric_limits<double>::infinity();    ///< mean squared simulation error at the end
  int iterations = 0;                                             ///< Levenberg-Marquardt iterations taken
  bool reflected = false;  ///< a start's linear block was unstable and had its poles reflected inside
  int start = 0;           ///< which start the result was refined from (refine_output_error of several)
};

namespace detail {
/// Mean squared free-run simulation error over the records (each from rest, or after its first
/// `window` samples: simulate_records); `y` is their outputs one after another from sample `window`
/// on (stacked_outputs). With a `mask` (as long as y, 1 where an output is fitted, 0 where not;
/// empty: all fitted), over the samples where it is 1. `past_y`: empty, or each record's window
/// outputs in place of the measured ones. Infinity where the simulation diverges.
template <class Model>
double simulation_cost(const Model& model, const Records<typename Model::Scalar>& records,
                       const typename Model::VectorX& y, typename Model::VectorX& simulated,
                       typename Model::VectorX& buffer, Eigen::Index window, const typename Model::VectorX& mask,
                       const std::vector<typename Model::VectorX>& past_y = {}) {
  if (!simulate_records(model, records, simulated, buffer, window, past_y)) {
    return std::numeric_limits<double>::infinity();
  }
  const double cost =
      mask.size() == 0
          ? static_cast<double>((y - simulated).squaredNorm()) / static_cast<double>(y.size())
          : static_cast<double>((y - simulated).cwiseProduct(mask).squaredNorm()) / static_cast<double>(mask.sum());
  return std::isfinite(cost) ? cost : std::numeric_limits<double>::infinity();
}

/// The Gauss-Newton normal equations of the simulation error e(k) = y(k) - y_sim(k) at the model's
/// theta: normal = J'J and gradient = J'e with J(k, :) = d y_sim(k) / d theta, from one free run of
/// each record from rest through the model's OutputErrorTerms with theta held fixed, gathered in
/// blocks (detail::add_rows); with a `mask` (simulation_cost), the rows where it is 1.
/// Returns false if the run leaves the finite numbers.
template <class Model, typename MatrixX>
bool simulation_normal_equations(const Model& model, const Records<typename Model::Scalar>& records, MatrixX& normal,
                                 typename Model::VectorX& gradient,
                                 const typename Model::VectorX& mask = typename Model::VectorX()) {
  using Scalar = typename Model::Scalar;
  constexpr Eigen::Index kBlock = 256;
  const Eigen::Index n = model.num_params();
  const typename Model::Params theta = model.theta();
  // Row-major: each sample writes one contiguous row.
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows(kBlock, n);
  typename Model::VectorX errors(kBlock);
  normal.setZero(n, n);
  gradient.setZero(n);
  Eigen::Index filled = 0;
  const auto flush = [&] {
    detail::add_rows(normal, gradient, rows.topRows(filled), errors.head(filled));
    filled = 0;
  };
  typename Model::OutputErrorTerms terms(model);
  const Scalar u0 = static_cast<Scalar>(model.u0());  // the blocks see deviations from the operating point
  const Scalar y0 = static_cast<Scalar>(model.y0());
  Eigen::Index stacked = 0;
  for (const auto& record : records) {
    terms.reset();
    for (Eigen::Index k = 0; k < record.u.size(); ++k, ++stacked) {
      const auto step = terms.step(theta, record.u[k] - u0);
      const Scalar error = record.y[k] - y0 - step.output;
      if (!std::isfinite(error)) return false;
      if (mask.size() == 0 || mask[stacked] != Scalar(0)) {
        rows.row(filled) = step.sensitivity.transpose();  // before accept(): the terms own it
        errors[filled] = error;
        ++filled;
      }
      terms.accept();
      if (filled == kBlock) flush();
    }
  }
  flush();
  normal.template triangularView<Eigen::StrictlyUpper>() = normal.transpose();
  return normal.allFinite() && gradient.allFinite();
}

/// The same normal equations for the free run after each record's first `window` samples
/// (simulate_records), with J by forward differences: column i is (y_sim(theta + h e_i) - y_sim(theta))
/// / h, h = sqrt(eps) max(|theta_i|, 1), taken backward where the model's constraint holds theta_i at
/// a bound. `y` is the records' outputs after their windows (stacked_outputs); with a `mask`
/// (simulation_cost), the rows where it is 1. With `past_y` (each record's window outputs, in place
/// of the measured ones) and `free` (how many of each record's last window outputs are estimated),
/// the columns after theta's are those outputs' own, one record after another, each nonzero only on
/// its record's rows. Returns false if a run leaves the finite numbers.
template <class Model, typename MatrixX>
bool window_normal_equations(const Model& model, const Records<typename Model::Scalar>& records, Eigen::Index window,
                             const typename Model::VectorX& y, MatrixX& normal, typename Model::VectorX& gradient,
                             const typename Model::VectorX& mask = typename Model::VectorX(),
                             const std::vector<typename Model::VectorX>& past_y = {},
                             const std::vector<Eigen::Index>& free = {}) {
  using Scalar = typename Model::Scalar;
  using VectorX = typename Model::VectorX;
  VectorX base, run, buffer;
  if (!simulate_records(model, records, base, buffer, window, past_y)) return false;
  const Eigen::Index n = model.num_params();
  Eigen::Index estimated = 0;
  for (const Eigen::Index count : free) estimated += count;
  const typename Model::Params theta = model.theta();
  MatrixX jacobian = MatrixX::Zero(base.size(), n + estimated);
  Model trial = model;
  const Scalar root_epsilon = std::sqrt(std::numeric_limits<Scalar>::epsilon());
  for (Eigen::Index i = 0; i < n; ++i) {
    const Scalar h = root_epsilon * std::max(std::abs(theta[i]), Scalar(1));
    typename Model::Params moved = theta;
    moved[i] += h;
    model.constrain(moved);
    if (moved[i] == theta[i]) {  // held at a bound: the other side
      moved = theta;
      moved[i] -= h;
      model.constrain(moved);
    }
    const Scalar step = moved[i] - theta[i];
    if (step == Scalar(0)) {
      jacobian.col(i).setZero();
      continue;
    }
    trial.set_theta(moved);
    if (!simulate_records(trial, records, run, buffer, window, past_y)) return false;
    jacobian.col(i) = (run - base) / step;
  }
  Eigen::Index column = n, row = 0;
  for (std::size_t r = 0; r < free.size(); ++r) {
    const Eigen::Index length = records[r].u.size() - window;
    VectorX past = past_y[r];
    for (Eigen::Index j = window - free[r]; j < window; ++j, ++column) {
      const Scalar kept = past[j];
      past[j] += root_epsilon * std::max(std::abs(kept), Scalar(1));
      const Scalar step = past[j] - kept;
      if (!simulate_record(model, records[r], window, run, &past)) return false;
      jacobian.col(column).segment(row, length) = (run - base.segment(row, length)) / step;
      past[j] = kept;
    }
    row += length;
  }
  VectorX error = y - base;
  if (mask.size() != 0) {
    jacobian = mask.asDiagonal() * jacobian;
    error = error.cwiseProduct(mask);
  }
  normal.noalias() = jacobian.transpose() * jacobian;
  gradient.noalias() = jacobian.transpose() * error;
  return normal.allFinite() && gradient.allFinite();
}

/// How many of each record's last window outputs its free run after the window depends on, by
/// probing: from the oldest on, the first whose change moves the run, and all after it. That is the
/// model's output memory (its lags) where its state after the window forgets older outputs, and
/// more where it does not (a backlash inside its gap holds an older output). It depends on theta (a
/// coefficient at 0 hides its lag). 0 for a record whose run leaves the finite numbers.
template <class Model>
std::vector<Eigen::Index> window_memory(const Model& model, const Records<typename Model::Scalar>& records,
                                        Eigen::Index window) {
  using Scalar = typename Model::Scalar;
  using VectorX = typename Model::VectorX;
  std::vector<Eigen::Index> free(records.size(), 0);
  VectorX base, run;
  for (std::size_t r = 0; r < records.size(); ++r) {
    if (!simulate_record(model, records[r], window, base)) continue;
    VectorX past = records[r].y.head(window);
    for (Eigen::Index j = 0; j < window; ++j) {
      const Scalar kept = past[j];
      past[j] += std::sqrt(std::numeric_limits<Scalar>::epsilon()) * std::max(std::abs(kept), Scalar(1));
      const bool moved = simulate_record(model, records[r], window, run, &past) && run != base;
      past[j] = kept;
      if (moved) {
        free[r] = window - j;
        break;
      }
    }
  }
  return free;
}
}  // namespace detail

namespace detail {

/// Levenberg-Marquardt from `start` (stable, finite cost) on the records: the loop of
/// refine_output_error, starting with `damping` and leaving there the damping it ended with. The
/// damping follows the gain ratio rho (actual over predicted decrease of the cost) as Nielsen (1999)
/// proposes: after a taken step it shrinks by max(1/3, 1 - (2 rho - 1)^3), so it falls fast where the
/// Gauss-Newton model is good, and it grows by doubling factors after a step that is refused.
/// Adds its iterations to report.iterations and sets report.final_cost. `window`: each record's free
/// run starts after its first `window` samples (0: from rest); `mask`: the outputs fitted
/// (simulation_cost; empty: all). With `past_y` (not null: each record's window outputs, in place of
/// the measured ones) and `free` (window_memory), the last free[i] of record i's are refined beside
/// theta and left in *past_y.
template <class Model>
Model levenberg_marquardt(const Model& start, const Records<typename Model::Scalar>& records, int max_iterations,
                          double& damping, RefinementReport& report, Eigen::Index window,
                          const typename Model::VectorX& mask, std::vector<typename Model::VectorX>* past_y = nullptr,
                          const std::vector<Eigen::Index>& free = {}) {
  using Scalar = typename Model::Scalar;
  using VectorX = typename Model::VectorX;
  using MatrixX = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  const VectorX y = stacked_outputs(records, window);
  const double samples = static_cast<double>(mask.size() == 0 ? y.size() : mask.sum());
  const std::vector<Eigen::Index> none;
  const std::vector<Eigen::Index>& estimated = past_y ? free : none;
  std::vector<VectorX> past = past_y ? *past_y : std::vector<VectorX>{};
  std::vector<VectorX> candidate_past = past;
  const Eigen::Index n = start.num_params();
  Model best = start;
  Model trial = start;
  typename Model::OutputErrorTerms checker(start);
  VectorX simulated, candidate_simulated, scratch;
  double cost = simulation_cost(best, records, y, simulated, scratch, window, mask, past);
  report.final_cost = cost;
  if (!std::isfinite(cost)) return best;

  MatrixX normal;
  VectorX gradient;
  int iteration = 0;
  for (; iteration < max_iterations; ++iteration) {
    const bool normal_equations =
        window > 0 ? window_normal_equations(best, records, window, y, normal, gradient, mask, past, estimated)
                   : simulation_normal_equations(best, records, normal, gradient, mask);
    if (!normal_equations) break;
    const typename Model::Params theta = best.theta();
    VectorX scale(normal.rows());
    damping_scale(normal, scale);

    bool accepted = false;
    double new_cost = cost;
    double growth = 2.0;
    while (damping < 1e12) {
      MatrixX damped = normal;
      damped.diagonal() += Scalar(damping) * scale;
      const VectorX step = damped.ldlt().solve(gradient);
      typename Model::Params candidate = theta + step.head(n);
      start.constrain(candidate);
      Eigen::Index at = n;
      for (std::size_t r = 0; r < estimated.size(); ++r) {
        candidate_past[r] = past[r];
        candidate_past[r].tail(estimated[r]) += step.segment(at, estimated[r]);
        at += estimated[r];
      }
      if (candidate.allFinite() && step.allFinite() && checker.stable(candidate, Scalar(1))) {
        trial.set_theta(candidate);
        new_cost = simulation_cost(trial, records, y, candidate_simulated, scratch, window, mask, candidate_past);
        if (new_cost < cost) {
          // Predicted decrease of the sum of squares: step' (gradient + damping D step).
          const double predicted =
              static_cast<double>(step.dot(gradient) + Scalar(damping) * step.dot(scale.cwiseProduct(step)));
          const double rho = predicted > 0.0 ? (cost - new_cost) * samples / predicted : 1.0;
          damping = damping_after_kept_step(damping, rho);
          accepted = true;
          break;
        }
      }
      damping *= growth;
      growth *= 2.0;
    }
    if (!accepted) break;
    const double improvement = (cost - new_cost) / cost;
    best = trial;
    simulated.swap(candidate_simulated);
    past.swap(candidate_past);
    cost = new_cost;
    if (improvement < 1e-10 || cost == 0.0) {
      ++iteration;
      break;
    }
  }
  report.final_cost = cost;
  report.iterations += iteration;
  if (past_y) *past_y = past;
  return best;
}

/// Records longer together than this are refined first on their first kCoarseSamples samples
/// (in proportion to each record's length), then on all of them: most iterations happen far from the
/// minimum, where a part of the data points the same way as all of it, at a fraction of the cost.
inline constexpr Eigen::Index kCoarseSamples = 16384;

}  // namespace detail

/// Levenberg-Marquardt on the mean squared free-run simulation error over the records, each
/// simulated from rest, with the analytic Jacobian (detail::simulation_normal_equations), from
/// several starts (the criterion is not convex): each start is refined, and the one that simulates
/// the records best is returned. Only steps that lower the cost and keep the linear block stable are
/// taken, so the result is never worse on these records than the best (stabilised) start. Each
/// refinement stops after `max_iterations`, or when a step improves the cost by less than a relative
/// 1e-10. The report's initial_cost is the best start's.
/// Long records (more than detail::kCoarseSamples samples together) are refined in two stages: every
/// start on the records' first part, then only the one that simulates all the records best on all
/// of them. Most iterations happen far from a minimum, where a part of the data points the same way
/// as all of it, at a fraction of the cost.
/// With an initialisation window of m > 0 samples each record is simulated after its first m
/// samples, measured (Model::simulate's past), and scored after them; the costs are over those
/// samples, and the Jacobian is taken by forward differences (the file's header says why).
/// With a mask, the costs are over the outputs where it is 1 (the free run goes on through the others,
/// on their measured input), in one stage.
/// With InitialState::Estimated (and a window), the window outputs each record's state depends on
/// (detail::window_memory) are refined beside the parameters, from the measured ones; the report's
/// initial cost is from the measured ones, its final cost from the estimated ones, which are not
/// returned: the model is what the records identify, its initial states their nuisance.
/// \param starts the models to start from, at least one
/// \param records the records, checked (CheckedRecords)
/// \param max_iterations the most Levenberg-Marquardt iterations per start, >= 0
/// \param report when not null, filled with the costs and iterations
/// \param initialisation_window the measured samples each record's free run starts after, >= 0 and
/// shorter than every record; 0: from rest
/// \param mask empty (every output fitted), or one entry per record's sample after its window, one
/// record after another: 1 where the output is fitted, 0 where not (the records' outputs there may be
/// any finite numbers); more 1s than the model has parameters
/// \param initial_state where each record's state after the window comes from: its measured outputs,
/// or estimated (which needs a window)
/// \return the refined model that simulates the records best
template <class Model>
Model refine_output_error(const std::vector<Model>& starts, const CheckedRecords<typename Model::Scalar>& records,
                          int max_iterations = 100, RefinementReport* report = nullptr,
                          Eigen::Index initialisation_window = 0,
                          const typename Model::VectorX& mask = typename Model::VectorX(),
                          InitialState initial_state = InitialState::Measured) {
  using Scalar = typename Model::Scalar;
  using VectorX = typename Model::VectorX;
  detail::require(!starts.empty(), "starts must hold at least one model");
  detail::require(max_iterations >= 0, "max_iterations must be >= 0, got " + std::to_string(max_iterations));
  detail::require_initialisation_window(records.records(), initialisation_window);
  detail::require_initial_state(initial_state, initialisation_window);
  const Eigen::Index window = initialisation_window;
  const Eigen::Index samples = records.samples();
  const typename Model::VectorX y = detail::stacked_outputs(records.records(), window);
  if (mask.size() != 0) {
    detail::require(mask.size() == y.size(), "mask must have one entry per sample after the windows (" +
                                                 std::to_string(y.size()) + "), got " + std::to_string(mask.size()));
    detail::require((mask.array() == Scalar(0) || mask.array() == Scalar(1)).all(), "mask's entries must be 0 or 1");
    detail::require(mask.sum() > static_cast<Scalar>(starts.front().num_params()),
                    "mask must fit more samples than the model has parameters (" +
                        std::to_string(starts.front().num_params()) + "), got " +
                        detail::format_number(static_cast<double>(mask.sum())));
  }
  typename Model::VectorX simulated, scratch;

  RefinementReport local;
  std::vector<Model> candidates = starts;
  std::vector<double> costs(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    Model& candidate = candidates[i];
    detail::require(candidate.num_params() == starts.front().num_params(),
                    "starts must all have the same structure (starts[" + std::to_string(i) + "] differs)");
    typename Model::OutputErrorTerms checker(candidate);
    if (!checker.stable(candidate.theta(), Scalar(1)) && detail::reflect_poles_inside(candidate, Scalar(0.999))) {
      local.reflected = true;
    }
    costs[i] = detail::simulation_cost(candidate, records.records(), y, simulated, scratch, window, mask);
  }
  local.initial_cost = *std::min_element(costs.begin(), costs.end());
  // Each start's own estimate of the records' window outputs, from the measured ones: those that
  // any start's run depends on (a start that diverges says nothing; a coefficient at 0 hides a lag).
  const bool estimate = initial_state == InitialState::Estimated;
  std::vector<Eigen::Index> free(estimate ? records.size() : 0, 0);
  for (std::size_t i = 0; i < candidates.size() && estimate; ++i) {
    if (!std::isfinite(costs[i])) continue;
    const std::vector<Eigen::Index> memory = detail::window_memory(candidates[i], records.records(), window);
    for (std::size_t r = 0; r < free.size(); ++r) free[r] = std::max(free[r], memory[r]);
  }
  std::vector<VectorX> measured;
  if (estimate) {
    for (const auto& record : records) measured.push_back(record.y.head(window));
  }
  std::vector<std::vector<VectorX>> pasts(candidates.size(), measured);
  const auto past_of = [&](std::size_t i) { return estimate ? &pasts[i] : nullptr; };
  // Stage one: every start on the records' first part (all of them when they are short).
  // With a window, each first part must be longer than it.
  bool two_stages = mask.size() == 0 && samples > detail::kCoarseSamples;
  const CheckedRecords<Scalar> first_part = two_stages ? records.first_part(detail::kCoarseSamples) : records;
  for (const auto& part : first_part) two_stages = two_stages && part.u.size() > window;
  const CheckedRecords<Scalar>& stage_one = two_stages ? first_part : records;
  std::vector<double> dampings(candidates.size(), 1e-3);
  for (std::size_t i = 0; i < candidates.size() && max_iterations > 0; ++i) {
    if (!std::isfinite(costs[i])) continue;
    RefinementReport stage;
    std::vector<VectorX> past = pasts[i];
    const Model refined = detail::levenberg_marquardt(candidates[i], stage_one.records(), max_iterations, dampings[i],
                                                      stage, window, mask, estimate ? &past : nullptr, free);
    local.iterations += stage.iterations;
    // Kept only where it simulates all the records better (on one stage, always).
    const double cost = detail::simulation_cost(refined, records.records(), y, simulated, scratch, window, mask, past);
    if (cost < costs[i]) {
      candidates[i] = refined;
      costs[i] = cost;
      pasts[i] = past;
    }
  }
  std::size_t chosen = 0;
  for (std::size_t i = 1; i < candidates.size(); ++i) {
    if (costs[i] < costs[chosen]) chosen = i;
  }
  local.start = static_cast<int>(chosen);
  local.final_cost = costs[chosen];
  Model best = candidates[chosen];
  // Stage two: the best on all the records.
  if (two_stages && std::isfinite(costs[chosen]) && max_iterations > 0) {
    best = detail::levenberg_marquardt(best, records.records(), max_iterations, dampings[chosen], local, window, mask,
                                       past_of(chosen), free);
  }
  if (report) *report = local;
  return best;
}

/// The same on records checked here (std::invalid_argument naming the bad record).
/// \param starts the models to start from, at least one
/// \param records the records, each an input u and measured output y of equal length
/// \param max_iterations the most Levenberg-Marquardt iterations per start, >= 0
/// \param report when not null, filled with the costs and iterations
/// \param initialisation_window the measured samples each record's free run starts after; 0: from rest
/// \return the refined model that simulates the records best
template <class Model>
Model refine_output_error(const std::vector<Model>& starts, const Records<typename Model::Scalar>& records,
                          int max_iterations = 100, RefinementReport* report = nullptr,
                          Eigen::Index initialisation_window = 0) {
  detail::require(!starts.empty(), "starts must hold at least one model");
  return refine_output_error(starts, CheckedRecords<typename Model::Scalar>(records, starts.front().num_params()),
                             max_iterations, report, initialisation_window);
}

/// The same from one start.
/// \param start the model to start from
/// \param records the records, each an input u and measured output y of equal length
/// \param max_iterations the most Levenberg-Marquardt iterations per start, >= 0
/// \param report when not null, filled with the costs and iterations
/// \param initialisation_window the measured samples each record's free run starts after; 0: from rest
/// \return the refined model that simulates the records best
template <class Model>
Model refine_output_error(const Model& start, const Records<typename Model::Scalar>& records, int max_iterations = 100,
                          RefinementReport* report = nullptr, Eigen::Index initialisation_window = 0) {
  return refine_output_error(std::vector<Model>{start}, records, max_iterations, report, initialisation_window);
}

/// The same on one record (u, y).
/// \param start the model to start from
/// \param u the input, one record
/// \param y the measured output, as long as u
/// \param max_iterations the most Levenberg-Marquardt iterations per start, >= 0
/// \param report when not null, filled with the costs and iterations
/// \param initialisation_window the measured samples each record's free run starts after; 0: from rest
/// \return the refined model that simulates the records best
template <class Model, typename U, typename Y>
Model refine_output_error(const Model& start, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y,
                          int max_iterations = 100, RefinementReport* report = nullptr,
                          Eigen::Index initialisation_window = 0) {
  const typename Model::VectorX input = u, output = y;
  return refine_output_error(std::vector<Model>{start},
                             CheckedRecords<typename Model::Scalar>(input, output, start.num_params()), max_iterations,
                             report, initialisation_window);
}

}  // namespace bonl
