#pragma once
// Order selection: identify every candidate structure of a grid and rank them. score_candidate() is
// the one scoring of a candidate, which select() runs on threads and Python's bonl.select
// (python/bonl/selection.py) runs on its executors.
// - SelectionCriterion::Validation (the default) fits each candidate on the first part of every record
//   (the last round(fraction n) samples, half away from zero, at least 1, held out) and scores the mean
//   squared free-run simulation error on the held-out last part: each record simulated whole, from
//   rest, and scored on its tail only; or, with a window of m samples, the held-out part simulated
//   after its first m samples (measured, as a test record's state-initialisation window) and scored
//   after them;
// - SelectionCriterion::CrossValidation (blocked cross-validation, for records too short for one
//   held-out part to be representative) cuts every record into `folds` consecutive blocks of equal
//   length; fold f holds out block f of every record and fits on the rest (the parts before and after
//   it, each a record of its own, fitted after identify's initialisation window of at least
//   kFoldFitWindow samples, since a part after a block does not start at rest), and scores the mean
//   squared free-run error over every held-out block: the record simulated from rest up to the
//   block's end and scored on the block, or, with a window, the block simulated after its first m
//   samples. Each sample is held out once; the folds' own mean squared errors are kept (fold_mse).
//   With a window the best is refitted after it too, as its folds were fitted;
// - AIC and BIC fit on all the data and score N log(mse) + 2 p or N log(mse) + p log(N) of the
//   free-run simulation error.
// The best is refitted on all the data. A candidate that cannot be fitted (more parameters than its
// fit part has samples) or whose identification throws (NumericalError, ...) is kept in the table with
// the reason and an infinite score; the others are unaffected.
// A model whose free run is not bounded is never chosen: a good held-out score does not stop a model
// that diverges elsewhere (on a short record's test part, for one). Bounded: from rest, on every
// record's input and on the same input stretched kFreeRunStretch times about the model's input
// operating point u0 (inputs somewhat beyond those measured), the simulated output stays within
// kFreeRunEnvelope half-ranges of the middle of the record's measured output. A candidate that fails
// it keeps its model and gets the reason and an infinite score; where the best candidate refitted on
// all the data fails it, the next one is refitted.

#include <Eigen/Core>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <exception>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "../detail/validate.hpp"
#include "../error.hpp"
#include "identify.hpp"
#include "record_view.hpp"

namespace bonl {

/// The free-run bound of select() (the file's header): how far, in half-ranges of a record's measured
/// output from its middle, a candidate's simulated output may go.
inline constexpr double kFreeRunEnvelope = 10.0;
/// The free-run bound of select(): the records' inputs are also simulated stretched this many times
/// about the model's input operating point, inputs somewhat beyond those measured.
inline constexpr double kFreeRunStretch = 1.25;

/// How select() ranks the candidate structures: by the free-run MSE on held-out data (Validation), or
/// by Akaike's or the Bayesian information criterion on the fitted data (AIC, BIC).
enum class SelectionCriterion { Validation, AIC, BIC, CrossValidation };

/// Blocked cross-validation (SelectionCriterion::CrossValidation): a fit part after a held-out block
/// does not start at rest, so the folds are fitted after identify's initialisation window of at least
/// this many samples (the recent past that sets a model's state).
inline constexpr Eigen::Index kFoldFitWindow = 10;

/// The name of a criterion, as Python spells it: "validation", "aic", "bic", "cross_validation".
/// \param criterion the criterion
/// \return the name, a string literal
inline const char* to_string(SelectionCriterion criterion) {
  switch (criterion) {
    case SelectionCriterion::AIC: return "aic";
    case SelectionCriterion::BIC: return "bic";
    case SelectionCriterion::CrossValidation: return "cross_validation";
    case SelectionCriterion::Validation: break;
  }
  return "validation";
}

/// What select() is told: the criterion, the held-out fraction, the window, the threads, the
/// identification's options.
struct SelectOptions {
  SelectionCriterion criterion = SelectionCriterion::Validation;  ///< how the candidates are ranked
  double validation_fraction = 0.25;                              ///< the held-out last part of every record, in (0, 1)
  /// Validation and CrossValidation only: each held-out part is scored as a test record with a
  /// state-initialisation window of this many samples is (simulated after them, from their measured
  /// values, and scored after them) instead of as the continuation of its record simulated from rest;
  /// 0: no window.
  Eigen::Index window = 0;
  int folds = 5;  ///< CrossValidation only: the blocks every record is cut into, each held out once (>= 2)
  /// CrossValidation only: where the folds' fit parts take their state at the end of their
  /// initialisation window (IdentifyOptions::initial_state): a part after a held-out block starts in
  /// motion, and an integrating model's state there is its position, which the window's noisy measured
  /// outputs set poorly (InitialState::Estimated estimates it beside the parameters). The refit on all
  /// the records keeps identify's own.
  InitialState fold_initial_state = InitialState::Measured;
  unsigned threads = 0;      ///< select()'s threads; 0: one per hardware thread
  IdentifyOptions identify;  ///< for every identification
};

/// One row of a selection's ranked table.
template <class Model>
struct SelectionCandidate {
  /// A row for candidate, not yet identified (infinite score).
  /// \param candidate the structure
  explicit SelectionCandidate(const Model& candidate) : structure(candidate) {}

  Model structure;                                         ///< the candidate as given
  double score = std::numeric_limits<double>::infinity();  ///< lower is better; infinity when it failed
  double fit_mse =
      std::numeric_limits<double>::infinity();  ///< free-run MSE on the data it was fitted on, run as fitted
  double validation_mse =
      std::numeric_limits<double>::quiet_NaN();  ///< held-out MSE (Validation and CrossValidation only)
  std::vector<double> fold_mse;  ///< CrossValidation: each fold's held-out MSE, in the folds' order; else empty
  std::string error;             ///< why the candidate has no model; empty when it has one
  std::optional<Model> model;    ///< the identified model (none when it failed)
};

/// What select() returns: the ranked table of the candidates and the best structure identified on all
/// the records.
template <class Model>
struct Selection {
  SelectionCriterion criterion;                  ///< the criterion the table is ranked by
  std::vector<SelectionCandidate<Model>> table;  ///< best first; ties keep the candidates' order
  Model best;                                    ///< the best structure identified on all the records
};

/// The length of a record of `samples` samples' held-out part: fraction * samples rounded half away
/// from zero (std::lround), at least 1.
/// \param samples the record's length
/// \param fraction the held-out fraction, in (0, 1)
/// \return the held-out part's length, >= 1
inline Eigen::Index held_out_samples(Eigen::Index samples, double fraction) {
  return std::max<Eigen::Index>(1, static_cast<Eigen::Index>(std::lround(fraction * static_cast<double>(samples))));
}

/// One fold of a blocked cross-validation (SelectionCriterion::CrossValidation): the parts of the
/// records it is fitted on and the block of each record it holds out. It views the records.
template <typename Scalar = double>
struct SelectionFold {
  Records<Scalar> fit;                                ///< the parts before and after each held-out block
  std::optional<CheckedRecords<Scalar>> fit_checked;  ///< the same, checked; none where fit_error says why
  std::string fit_error;                              ///< why the fold cannot be fitted; "" where it can
  std::vector<Eigen::Index> begin;                    ///< per record, the held-out block's first sample
  std::vector<Eigen::Index> end;                      ///< per record, one past its last
  Eigen::Index fit_samples = 0;                       ///< the fit parts' samples together
};

/// The records and options of a selection, checked once, and the part of each record the candidates
/// are fitted on: what score_candidate() and select() take. It views the records (their vectors must
/// outlive it).
template <typename Scalar = double>
class SelectionData {
 public:
  /// Checks the records and the options (std::invalid_argument naming the bad one) and splits every
  /// record into its fit part and its held-out part (under AIC and BIC the fit part is all of it;
  /// under CrossValidation, into its folds' blocks).
  /// \param records the records, each an input u and measured output y of equal length
  /// \param options the selection's options
  SelectionData(const Records<Scalar>& records, const SelectOptions& options) : m_records(records), m_options(options) {
    const bool validation = options.criterion == SelectionCriterion::Validation;
    const bool cross_validation = options.criterion == SelectionCriterion::CrossValidation;
    detail::require(
        options.validation_fraction > 0.0 && options.validation_fraction < 1.0,
        "select: validation_fraction must be in (0, 1), got " + detail::format_number(options.validation_fraction));
    detail::require(options.window >= 0,
                    "select: window must be an integer >= 0, got " + std::to_string(options.window));
    detail::require(options.window == 0 || validation || cross_validation,
                    std::string("select: window applies to criteria 'validation' and 'cross_validation' only, got "
                                "criterion '") +
                        to_string(options.criterion) + "'");
    detail::require(options.folds >= 2, "select: folds must be >= 2, got " + std::to_string(options.folds));
    detail::require(options.fold_initial_state == InitialState::Measured || cross_validation,
                    std::string("select: fold_initial_state 'estimated' applies to criterion 'cross_validation' only, "
                                "got criterion '") +
                        to_string(options.criterion) + "'");
    options.identify.validate();
    m_checked.emplace(records, 0);
    m_refit_identify = options.identify;
    if (cross_validation) {
      m_refit_identify.initialisation_window = std::max(options.identify.initialisation_window, options.window);
      detail::require_initialisation_window(records, m_refit_identify.initialisation_window);
      make_folds();
      return;
    }
    for (std::size_t i = 0; i < records.size(); ++i) {
      const std::string name = "records[" + std::to_string(i) + "]";
      const Eigen::Index n = records[i].u.size();
      detail::require(n > 1, name + " must have at least 2 samples");
      const Eigen::Index held_out = held_out_samples(n, options.validation_fraction);
      detail::require(held_out > options.window, "select: " + name + "'s held-out part (" + std::to_string(held_out) +
                                                     " samples) must be longer than the window (" +
                                                     std::to_string(options.window) + ")");
      m_split.push_back(validation ? n - held_out : n);
      m_fit_records.push_back(records[i].head(m_split.back()));
      m_fit_samples += m_split.back();
    }
    // identify's window, against the fit parts it is applied to.
    detail::require_initialisation_window(m_fit_records, options.identify.initialisation_window);
    // The fit parts, parts of the checked records, once for every candidate. An empty one fails every
    // candidate, with the reason, rather than the selection.
    try {
      m_fit_checked.emplace(m_checked->heads(m_split));
    } catch (const std::invalid_argument& error) {
      m_fit_error = error.what();
    }
  }

  /// All the records
  /// \return views of the records given
  const Records<Scalar>& records() const noexcept { return m_records; }
  /// Their fit parts
  /// \return views of the records' first parts
  const Records<Scalar>& fit_records() const noexcept { return m_fit_records; }
  /// All the records, checked
  /// \return the records given, as CheckedRecords
  const CheckedRecords<Scalar>& checked_records() const noexcept { return *m_checked; }
  /// The fit parts, checked; none where one is empty (fit_error() says which)
  /// \return the fit parts as CheckedRecords, or none
  const std::optional<CheckedRecords<Scalar>>& checked_fit_records() const noexcept { return m_fit_checked; }
  /// Why the fit parts cannot be identified on (a fit part is empty); "" where they can
  /// \return the reason, or ""
  const std::string& fit_error() const noexcept { return m_fit_error; }
  /// Where each record's held-out part starts (its length under AIC and BIC).
  /// \return one sample index per record
  const std::vector<Eigen::Index>& split() const noexcept { return m_split; }
  /// The fit parts' samples together
  /// \return the number of samples
  Eigen::Index fit_samples() const noexcept { return m_fit_samples; }
  /// The options, checked
  /// \return the options given
  const SelectOptions& options() const noexcept { return m_options; }
  /// CrossValidation: the folds, each with its fit parts and held-out blocks; otherwise none
  /// \return the folds
  const std::vector<SelectionFold<Scalar>>& folds() const noexcept { return m_folds; }
  /// CrossValidation: identify's options for the folds' fits (initialisation window at least
  /// kFoldFitWindow)
  /// \return the options
  const IdentifyOptions& fold_identify() const noexcept { return m_fold_identify; }
  /// identify's options for the refit on all the records (refit()): the options', with under
  /// CrossValidation an initialisation window at least the selection's window
  /// \return the options
  const IdentifyOptions& refit_identify() const noexcept { return m_refit_identify; }

 private:
  /// The folds of a blocked cross-validation: every record's blocks [round(f n / folds),
  /// round((f + 1) n / folds)); a fit part not longer than the fit window is left out.
  void make_folds() {
    m_fold_identify = m_options.identify;
    m_fold_identify.initialisation_window =
        std::max({m_options.identify.initialisation_window, m_options.window, kFoldFitWindow});
    m_fold_identify.initial_state = m_options.fold_initial_state;
    const Eigen::Index fit_window = m_fold_identify.initialisation_window;
    const auto edge = [&](Eigen::Index n, int f) {
      return static_cast<Eigen::Index>(std::llround(static_cast<double>(n) * f / m_options.folds));
    };
    for (std::size_t i = 0; i < m_records.size(); ++i) {
      const Eigen::Index n = m_records[i].u.size();
      const Eigen::Index shortest = edge(n, 1);
      detail::require(shortest > m_options.window, "select: records[" + std::to_string(i) + "]'s " +
                                                       std::to_string(m_options.folds) + " cross-validation blocks (" +
                                                       std::to_string(shortest) +
                                                       " samples the shortest) must be longer than the window (" +
                                                       std::to_string(m_options.window) + ")");
    }
    m_folds.resize(static_cast<std::size_t>(m_options.folds));
    for (int f = 0; f < m_options.folds; ++f) {
      SelectionFold<Scalar>& fold = m_folds[static_cast<std::size_t>(f)];
      for (const auto& record : m_records) {
        const Eigen::Index n = record.u.size();
        const Eigen::Index begin = edge(n, f), end = edge(n, f + 1);
        fold.begin.push_back(begin);
        fold.end.push_back(end);
        for (const auto& part : {record.head(begin), record.segment(end, n - end)}) {
          if (part.u.size() <= fit_window) continue;
          fold.fit.push_back(part);
          fold.fit_samples += part.u.size();
        }
      }
      if (fold.fit.empty()) {
        fold.fit_error = "bonl: select: fold " + std::to_string(f) + " has no part longer than the fit window (" +
                         std::to_string(fit_window) + " samples) to fit on";
        continue;
      }
      try {
        fold.fit_checked.emplace(fold.fit, 0);
      } catch (const std::invalid_argument& error) {
        fold.fit_error = error.what();
      }
    }
  }

  Records<Scalar> m_records;
  Records<Scalar> m_fit_records;
  std::optional<CheckedRecords<Scalar>> m_checked;
  std::optional<CheckedRecords<Scalar>> m_fit_checked;
  std::string m_fit_error;
  std::vector<Eigen::Index> m_split;
  Eigen::Index m_fit_samples = 0;
  SelectOptions m_options;
  std::vector<SelectionFold<Scalar>> m_folds;
  IdentifyOptions m_fold_identify;
  IdentifyOptions m_refit_identify;
};

namespace detail {

/// Mean squared free-run error of each record over its samples from start[i] on: the record simulated
/// whole from rest, or, with a window, its samples from start[i] on simulated after their first
/// `window` samples (measured, Model::simulate's past) and scored after them. Infinity where a
/// simulation diverges.
template <class Model>
double tail_simulation_mse(const Model& model, const Records<typename Model::Scalar>& records,
                           const std::vector<Eigen::Index>& start, Eigen::Index window) {
  double squared = 0.0;
  double count = 0.0;
  typename Model::VectorX simulated;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const Eigen::Index first = start[i] + window;
    const Eigen::Index n = records[i].y.size() - first;
    if (window > 0) {
      try {
        simulated = model.simulate(records[i].u.tail(n), records[i].u.segment(start[i], window),
                                   records[i].y.segment(start[i], window));
      } catch (const NumericalError&) {
        return std::numeric_limits<double>::infinity();
      }
    } else if (model.try_simulate(records[i].u, simulated)) {
      simulated = simulated.tail(n).eval();
    } else {
      return std::numeric_limits<double>::infinity();
    }
    squared += static_cast<double>((records[i].y.tail(n) - simulated).squaredNorm());
    count += static_cast<double>(n);
  }
  const double mse = count > 0.0 ? squared / count : std::numeric_limits<double>::infinity();
  return std::isfinite(mse) ? mse : std::numeric_limits<double>::infinity();
}

/// Squared free-run error and count of one record's block [begin, end): the record simulated from rest
/// up to the block's end and scored on the block, or, with a window, the block simulated after its
/// first `window` samples (measured) and scored after them. False where a simulation diverges.
template <class Model>
bool block_simulation_error(const Model& model, const RecordView<typename Model::Scalar>& record, Eigen::Index begin,
                            Eigen::Index end, Eigen::Index window, double& squared, double& count) {
  typename Model::VectorX simulated;
  const Eigen::Index first = begin + window;
  if (window > 0) {
    try {
      simulated = model.simulate(record.u.segment(first, end - first), record.u.segment(begin, window),
                                 record.y.segment(begin, window));
    } catch (const NumericalError&) {
      return false;
    }
  } else if (model.try_simulate(record.u.head(end), simulated)) {
    simulated = simulated.tail(end - first).eval();
  } else {
    return false;
  }
  const double error = static_cast<double>((record.y.segment(first, end - first) - simulated).squaredNorm());
  if (!std::isfinite(error)) return false;
  squared += error;
  count += static_cast<double>(end - first);
  return true;
}

/// Why `model`'s free run is not bounded on the records (the file's header says what bounded is), or
/// "" where it is.
template <class Model>
std::string unbounded_free_run(const Model& model, const Records<typename Model::Scalar>& records) {
  using Scalar = typename Model::Scalar;
  typename Model::VectorX input, simulated;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const double low = static_cast<double>(records[i].y.minCoeff());
    const double high = static_cast<double>(records[i].y.maxCoeff());
    const double middle = 0.5 * (low + high);
    const double half_range = 0.5 * (high - low);
    for (const bool stretched : {false, true}) {
      const Scalar u0 = static_cast<Scalar>(model.u0());
      input = stretched ? ((records[i].u.array() - u0) * static_cast<Scalar>(kFreeRunStretch) + u0).matrix().eval()
                        : records[i].u.eval();
      const std::string where = "records[" + std::to_string(i) + "]'s input" +
                                (stretched ? " stretched " + format_number(kFreeRunStretch) + " times about u0" : "");
      if (!model.try_simulate(input, simulated)) return "its free run diverges on " + where;
      const double furthest = static_cast<double>((simulated.array() - static_cast<Scalar>(middle)).abs().maxCoeff());
      // A constant measured output has no range to measure the run by: finite is all that is asked.
      if (half_range > 0.0 && furthest > kFreeRunEnvelope * half_range) {
        return "its free run on " + where + " goes " + format_number(furthest / half_range) +
               " half-ranges of the measured output from its middle (at most " + format_number(kFreeRunEnvelope) + ")";
      }
    }
  }
  return "";
}

}  // namespace detail

/// The structure identified on all the records of `data`, if its free run there is bounded (the
/// file's header): what select() makes of its best candidate. Otherwise none, and `why` says why (an
/// identification that throws NumericalError, or the free run's bound). Under CrossValidation with a
/// window it is fitted after that window too (SelectionData::refit_identify()), as its folds were
/// and as it is scored: fitted from rest, a model learns a start its use never sees.
/// \param structure the candidate
/// \param data the checked records and options
/// \param why set to the reason where there is no model
/// \return the model, or none
template <class Model>
std::optional<Model> refit(const Model& structure, const SelectionData<typename Model::Scalar>& data,
                           std::string& why) {
  try {
    Model model = identify(structure, data.checked_records(), data.refit_identify());
    why = detail::unbounded_free_run(model, data.records());
    if (why.empty()) return model;
  } catch (const NumericalError& error) {
    why = error.what();
  }
  return std::nullopt;
}

namespace detail {

/// score_candidate() under CrossValidation: each fold's model identified on its fit parts, bounded
/// on all the records, and scored on its held-out blocks; the row's model is the last fold's.
template <class Model>
void cross_validate(SelectionCandidate<Model>& row, const SelectionData<typename Model::Scalar>& data) {
  const Eigen::Index p = row.structure.num_params();
  const Eigen::Index fit_window = data.fold_identify().initialisation_window;
  double squared = 0.0, count = 0.0, fit_squared = 0.0, fit_count = 0.0;
  std::vector<double> fold_mse;
  for (std::size_t f = 0; f < data.folds().size(); ++f) {
    const auto& fold = data.folds()[f];
    const std::string which = "fold " + std::to_string(f) + ": ";
    const Eigen::Index scored = fold.fit_samples - static_cast<Eigen::Index>(fold.fit.size()) * fit_window;
    if (scored <= p) {
      row.error = "bonl: select: " + which + std::to_string(p) + " parameters cannot be fitted on the " +
                  std::to_string(scored) + " samples of its fit parts after their window";
      return;
    }
    if (!fold.fit_checked) {
      row.error = fold.fit_error;
      return;
    }
    try {
      row.model = identify(row.structure, *fold.fit_checked, data.fold_identify());
    } catch (const std::exception& error) {
      row.error = which + error.what();
      return;
    }
    row.error = unbounded_free_run(*row.model, data.records());
    if (!row.error.empty()) {
      row.error = which + row.error;
      return;
    }
    const double fit_mse =
        tail_simulation_mse(*row.model, fold.fit, std::vector<Eigen::Index>(fold.fit.size(), 0), fit_window);
    fit_squared += fit_mse * static_cast<double>(scored);
    fit_count += static_cast<double>(scored);
    double fold_squared = 0.0, fold_count = 0.0;
    for (std::size_t i = 0; i < data.records().size(); ++i) {
      if (!block_simulation_error(*row.model, data.records()[i], fold.begin[i], fold.end[i], data.options().window,
                                  fold_squared, fold_count)) {
        fold_squared = std::numeric_limits<double>::infinity();
        break;
      }
    }
    fold_mse.push_back(fold_count > 0.0 ? fold_squared / fold_count : std::numeric_limits<double>::infinity());
    squared += fold_squared;
    count += fold_count;
  }
  row.fit_mse = fit_count > 0.0 ? fit_squared / fit_count : std::numeric_limits<double>::infinity();
  const double mse = count > 0.0 ? squared / count : std::numeric_limits<double>::infinity();
  row.validation_mse = std::isfinite(mse) ? mse : std::numeric_limits<double>::infinity();
  row.score = row.validation_mse;
  row.fold_mse = std::move(fold_mse);
}

}  // namespace detail

/// Identifies one candidate structure on the data's fit parts and scores it by the data's criterion:
/// its row of the selection's table. A candidate with more parameters than the fit parts have samples,
/// or whose identification throws, gets an infinite score, no model and the reason in `error`.
/// \param structure the candidate
/// \param data the checked records and options
/// \return the candidate's row, scored
template <class Model>
SelectionCandidate<Model> score_candidate(const Model& structure, const SelectionData<typename Model::Scalar>& data) {
  SelectionCandidate<Model> row(structure);
  const SelectOptions& options = data.options();
  if (options.criterion == SelectionCriterion::CrossValidation) {
    detail::cross_validate(row, data);
    return row;
  }
  const Eigen::Index p = structure.num_params();
  if (data.fit_samples() <= p) {  // identify would refuse it: a failed candidate, not bad input
    row.error = "bonl: select: " + std::to_string(p) + " parameters cannot be fitted on the " +
                std::to_string(data.fit_samples()) + " samples of the fit part";
    return row;
  }
  if (!data.checked_fit_records()) {
    row.error = data.fit_error();
    return row;
  }
  try {
    row.model = identify(structure, *data.checked_fit_records(), options.identify);
  } catch (const std::exception& error) {  // NumericalError; or a structure this data cannot fit
    row.error = error.what();
    return row;
  }
  row.error = detail::unbounded_free_run(*row.model, data.records());
  if (!row.error.empty()) return row;
  // The free run as it was fitted: from rest, or after identify's initialisation window.
  row.fit_mse =
      detail::tail_simulation_mse(*row.model, data.fit_records(), std::vector<Eigen::Index>(data.records().size(), 0),
                                  options.identify.initialisation_window);
  if (options.criterion == SelectionCriterion::Validation) {
    row.validation_mse = detail::tail_simulation_mse(*row.model, data.records(), data.split(), options.window);
    row.score = row.validation_mse;
    return row;
  }
  const double samples = static_cast<double>(data.fit_samples() - static_cast<Eigen::Index>(data.records().size()) *
                                                                      options.identify.initialisation_window);
  const double parameters = static_cast<double>(p);
  if (row.fit_mse == 0.0) {
    row.score = -std::numeric_limits<double>::infinity();
  } else if (std::isfinite(row.fit_mse)) {
    row.score = samples * std::log(row.fit_mse) +
                (options.criterion == SelectionCriterion::AIC ? 2.0 * parameters : parameters * std::log(samples));
  }
  return row;
}

/// Scores every candidate structure (score_candidate(), on data.options().threads threads), ranks them
/// best first and refits the best on all the records (refit(): where its free run is not bounded, the
/// next, its row given the reason). Throws std::invalid_argument for no candidates, NumericalError if
/// no candidate with a finite score has a bounded free run.
/// \param candidates the structures to compare, at least one
/// \param data the checked records and options
/// \return the ranked table and the best structure identified on all the records
template <class Model>
Selection<Model> select(const std::vector<Model>& candidates, const SelectionData<typename Model::Scalar>& data) {
  detail::require(!candidates.empty(), "select: candidates is empty");
  std::vector<SelectionCandidate<Model>> rows(candidates.size(), SelectionCandidate<Model>(candidates.front()));
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i = next++; i < candidates.size(); i = next++) rows[i] = score_candidate(candidates[i], data);
  };
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const unsigned asked = data.options().threads;
  const std::size_t threads = std::min<std::size_t>(asked == 0 ? hardware : asked, candidates.size());
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& thread : pool) thread.join();

  std::vector<std::size_t> order(rows.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return rows[a].score < rows[b].score; });
  std::vector<SelectionCandidate<Model>> table;
  for (std::size_t i : order) table.push_back(rows[i]);
  std::optional<Model> best;
  for (auto& row : table) {
    if (!row.error.empty() || !(row.score < std::numeric_limits<double>::infinity())) break;  // the rest are worse
    std::string why;
    best = refit(row.structure, data, why);
    if (best) break;
    row.error = "refitted on all the records: " + why;
    row.score = std::numeric_limits<double>::infinity();
  }
  if (!best) {
    throw NumericalError(
        "bonl: select: every candidate failed: none has a finite score and a bounded free run; the first: " +
        (table.front().error.empty() ? "its score is infinite" : table.front().error));
  }
  // Rows whose refit was refused go down with the failed ones.
  std::stable_sort(table.begin(), table.end(), [](const auto& a, const auto& b) { return a.score < b.score; });
  return {data.options().criterion, std::move(table), std::move(*best)};
}

/// select() on the records with the options, checked here (std::invalid_argument for bad options or
/// bad records).
/// \param candidates the structures to compare, at least one
/// \param records the records, each an input u and measured output y of equal length
/// \param options the criterion, held-out fraction, window, threads and identification options
/// \return the ranked table and the best structure identified on all the records
template <class Model>
Selection<Model> select(const std::vector<Model>& candidates, const Records<typename Model::Scalar>& records,
                        const SelectOptions& options = {}) {
  return select(candidates, SelectionData<typename Model::Scalar>(records, options));
}

}  // namespace bonl
