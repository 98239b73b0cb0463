#pragma once
// Order selection: identify every candidate structure of a grid and rank them, as Python's
// bonl.select does (python/bonl/selection.py).
// - SelectionCriterion::Validation (the default) fits each candidate on the first part of every record
//   and scores the mean squared free-run simulation error on the held-out last part (each record
//   simulated whole, from rest, and scored on its tail only);
// - AIC and BIC fit on all the data and score N log(mse) + 2 p or N log(mse) + p log(N) of the
//   free-run simulation error.
// The candidates run on `threads` threads; the best is refitted on all the data. A candidate whose
// identification breaks down (NumericalError) is kept in the table with its message and an infinite
// score; the others are unaffected.

#include <Eigen/Core>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <exception>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "../detail/validate.hpp"
#include "../error.hpp"
#include "identify.hpp"
#include "record_view.hpp"

namespace bonl {

/// How select() ranks the candidate structures: by the free-run MSE on held-out data (Validation), or
/// by Akaike's or the Bayesian information criterion on the fitted data (AIC, BIC).
enum class SelectionCriterion { Validation, AIC, BIC };

/// What select() is told: the criterion, the held-out fraction, the threads, the identification's
/// options.
struct SelectOptions {
  SelectionCriterion criterion = SelectionCriterion::Validation;  ///< how the candidates are ranked
  double validation_fraction = 0.25;  ///< the held-out last part of every record, in (0, 1)
  unsigned threads = 0;               ///< 0: one per hardware thread
  IdentifyOptions identify;           ///< for every identification
};

/// One row of a selection's ranked table.
template <class Model>
struct SelectionCandidate {
  /// A row for candidate, not yet identified (infinite score).
  explicit SelectionCandidate(const Model& candidate) : structure(candidate) {}

  Model structure;                 ///< the candidate as given
  double score = std::numeric_limits<double>::infinity();  ///< lower is better; infinity when it failed
  double fit_mse = std::numeric_limits<double>::infinity();  ///< free-run MSE on the data it was fitted on
  double validation_mse = std::numeric_limits<double>::quiet_NaN();  ///< held-out MSE (Validation only)
  std::string error;               ///< why the identification failed; empty when it did not
  std::optional<Model> model;      ///< the identified model (none when it failed)
};

/// What select() returns: the ranked table of the candidates and the best structure identified on all
/// the records.
template <class Model>
struct Selection {
  SelectionCriterion criterion;  ///< the criterion the table is ranked by
  std::vector<SelectionCandidate<Model>> table;  ///< best first; ties keep the candidates' order
  Model best;                                    ///< the best structure identified on all the records
};

namespace detail {

/// Mean squared free-run error of each record simulated whole from rest, over its samples from
/// start[i] on; infinity where the simulation diverges.
template <class Model>
double tail_simulation_mse(const Model& model, const Records<typename Model::Scalar>& records,
                           const std::vector<Eigen::Index>& start) {
  double squared = 0.0;
  double count = 0.0;
  typename Model::VectorX simulated;
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (!model.try_simulate(records[i].u, simulated)) return std::numeric_limits<double>::infinity();
    const Eigen::Index n = records[i].y.size() - start[i];
    squared += static_cast<double>((records[i].y.tail(n) - simulated.tail(n)).squaredNorm());
    count += static_cast<double>(n);
  }
  const double mse = count > 0.0 ? squared / count : std::numeric_limits<double>::infinity();
  return std::isfinite(mse) ? mse : std::numeric_limits<double>::infinity();
}

template <class Model>
SelectionCandidate<Model> fit_candidate(const Model& structure, const Records<typename Model::Scalar>& records,
                                        const SelectOptions& options) {
  SelectionCandidate<Model> row(structure);
  const bool validation = options.criterion == SelectionCriterion::Validation;
  std::vector<Eigen::Index> split, zeros(records.size(), 0);
  Records<typename Model::Scalar> fit_records;
  for (const auto& record : records) {
    const Eigen::Index n = record.u.size();
    const Eigen::Index held_out =
        std::max<Eigen::Index>(1, static_cast<Eigen::Index>(std::lround(options.validation_fraction * double(n))));
    split.push_back(validation ? n - held_out : n);
    fit_records.push_back(record.head(split.back()));
  }
  try {
    row.model = identify(structure, fit_records, options.identify);
  } catch (const std::exception& error) {  // NumericalError; or a record's first part too short for it
    row.error = error.what();
    return row;
  }
  row.fit_mse = tail_simulation_mse(*row.model, fit_records, zeros);
  if (validation) {
    row.validation_mse = tail_simulation_mse(*row.model, records, split);
    row.score = row.validation_mse;
    return row;
  }
  double samples = 0.0;
  for (const auto& record : fit_records) samples += static_cast<double>(record.u.size());
  const double p = static_cast<double>(structure.num_params());
  if (row.fit_mse == 0.0) {
    row.score = -std::numeric_limits<double>::infinity();
  } else if (std::isfinite(row.fit_mse)) {
    row.score = samples * std::log(row.fit_mse) +
                (options.criterion == SelectionCriterion::AIC ? 2.0 * p : p * std::log(samples));
  }
  return row;
}

}  // namespace detail

/// Identifies every candidate structure on the records, ranks them by options.criterion and
/// refits the best on all the records. Throws std::invalid_argument for no candidates, bad options
/// or bad records, NumericalError if every candidate failed.
template <class Model>
Selection<Model> select(const std::vector<Model>& candidates, const Records<typename Model::Scalar>& records,
                        const SelectOptions& options = {}) {
  detail::require(!candidates.empty(), "select: candidates is empty");
  detail::require(options.validation_fraction > 0.0 && options.validation_fraction < 1.0,
                  "select: validation_fraction must be in (0, 1), got " +
                      detail::format_number(options.validation_fraction));
  options.identify.validate();
  detail::require_records(records, 0);
  for (std::size_t i = 0; i < records.size(); ++i) {
    detail::require(records[i].u.size() > 1, "records[" + std::to_string(i) + "] must have at least 2 samples");
  }

  std::vector<SelectionCandidate<Model>> rows(candidates.size(), SelectionCandidate<Model>(candidates.front()));
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i = next++; i < candidates.size(); i = next++) {
      rows[i] = detail::fit_candidate(candidates[i], records, options);
    }
  };
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t threads =
      std::min<std::size_t>(options.threads == 0 ? hardware : options.threads, candidates.size());
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
  if (!table.front().model) {
    throw NumericalError("bonl: select: every candidate failed; the first: " + table.front().error);
  }
  Model best = identify(candidates[order.front()], records, options.identify);
  return {options.criterion, std::move(table), std::move(best)};
}

}  // namespace bonl
