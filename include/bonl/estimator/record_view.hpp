#pragma once
// Several records (experiments) of one system identify one model: each record is simulated from rest
// and no history is carried across a record's boundaries. A RecordView refers to a record's u and y
// without copying them; it is made from vectors that outlive it (a temporary, such as the result of
// an expression, is refused at compile time rather than left dangling). CheckedRecords are records
// that passed the checks once, where they entered; the functions that take them check nothing again.

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "../detail/validate.hpp"
#include "../error.hpp"
#include "initial_state.hpp"

namespace bonl {

/// One record: the input u and the measured output y of one experiment, as references.
template <typename Scalar = double>
struct RecordView {
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;  ///< the vectors a record is viewed in
  /// Views input and output (the caller keeps them alive; temporaries are refused at compile time).
  /// \param input the input u
  /// \param output the measured output y, as long as input
  RecordView(const Vector& input, const Vector& output)
      : u(input.data(), input.size()), y(output.data(), output.size()) {}
  RecordView(Vector&&, const Vector&) = delete;
  RecordView(const Vector&, Vector&&) = delete;
  RecordView(Vector&&, Vector&&) = delete;

  /// The first `samples` samples of this record (at most all of them).
  /// \param samples how many samples, >= 0
  /// \return a view of the same vectors
  RecordView head(Eigen::Index samples) const {
    const Eigen::Index n = samples < u.size() ? samples : u.size();
    return RecordView(u.data(), y.data(), n);
  }
  /// The `samples` samples of this record from `start` on (clipped to the record).
  /// \param start the first sample, >= 0
  /// \param samples how many samples, >= 0
  /// \return a view of the same vectors
  RecordView segment(Eigen::Index start, Eigen::Index samples) const {
    const Eigen::Index first = start < u.size() ? start : u.size();
    const Eigen::Index n = samples < u.size() - first ? samples : u.size() - first;
    return RecordView(u.data() + first, y.data() + first, n);
  }

  Eigen::Map<const Vector> u;  ///< the input u
  Eigen::Map<const Vector> y;  ///< the measured output y

 private:
  RecordView(const Scalar* input, const Scalar* output, Eigen::Index samples) : u(input, samples), y(output, samples) {}
};

/// Several records of one system (experiments, segments), identified together.
template <typename Scalar = double>
using Records = std::vector<RecordView<Scalar>>;

namespace detail {

/// Records for identification: at least one; in each, u and y of equal length (at least one sample)
/// and finite; together longer than the number of parameters. Returns the total number of samples.
template <typename Scalar>
Eigen::Index require_records(const Records<Scalar>& records, Eigen::Index num_params) {
  require(!records.empty(), "records must hold at least one record (u, y)");
  Eigen::Index total = 0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::string name = "records[" + std::to_string(i) + "]";
    const std::string u_name = name + ".u";
    const std::string y_name = name + ".y";
    require_same_length(records[i].u, u_name.c_str(), records[i].y, y_name.c_str());
    require(records[i].u.size() > 0, name + " is empty");
    require_finite(records[i].u, u_name.c_str());
    require_finite(records[i].y, y_name.c_str());
    total += records[i].u.size();
  }
  require(total > num_params, "the records must be longer together than the number of parameters (" +
                                  std::to_string(num_params) + "), got " + std::to_string(total) + " samples");
  return total;
}

}  // namespace detail

/// Records checked once, where they enter the library: at least one; in each, u and y of equal length
/// and finite; together longer than the number of parameters of the structure they were checked for.
/// Only the constructors below make one, and they check, so the functions that take CheckedRecords
/// (identify(), estimate_recursively(), refine_output_error(), the starts, excitation_shortfall())
/// check nothing of the records again. Like Records it views vectors that must outlive it.
template <typename Scalar = double>
class CheckedRecords {
 public:
  using Vector = typename RecordView<Scalar>::Vector;  ///< the vectors a record is viewed in

  /// Checks several records for a structure of `num_params` parameters; std::invalid_argument naming
  /// the bad record ("records[1].u has a non-finite value at index 7") otherwise.
  /// \param records the records, each an input u and measured output y of equal length
  /// \param num_params the number of parameters the records must be longer than, together
  CheckedRecords(const Records<Scalar>& records, Eigen::Index num_params)
      : m_records(records), m_samples(detail::require_records(records, num_params)) {}

  /// Checks one record (u, y) for a structure of `num_params` parameters; std::invalid_argument naming
  /// u or y otherwise ("u has a non-finite value at index 3"). Temporaries are refused at compile time.
  /// \param u the input
  /// \param y the measured output, as long as u
  /// \param num_params the number of parameters the record must be longer than
  CheckedRecords(const Vector& u, const Vector& y, Eigen::Index num_params) : m_samples(u.size()) {
    detail::require_record(u, y, num_params);
    m_records.emplace_back(u, y);
  }
  CheckedRecords(Vector&&, const Vector&, Eigen::Index) = delete;
  CheckedRecords(const Vector&, Vector&&, Eigen::Index) = delete;
  CheckedRecords(Vector&&, Vector&&, Eigen::Index) = delete;

  /// The records, as given
  /// \return their views
  const Records<Scalar>& records() const noexcept { return m_records; }
  /// The samples of all the records together
  /// \return the number of samples, > the number of parameters checked for
  Eigen::Index samples() const noexcept { return m_samples; }
  /// The number of records
  /// \return at least 1
  std::size_t size() const noexcept { return m_records.size(); }
  /// One record
  /// \param i its index, < size()
  /// \return its view
  const RecordView<Scalar>& operator[](std::size_t i) const noexcept { return m_records[i]; }
  /// The first record, for range-for
  /// \return an iterator to the first record
  auto begin() const noexcept { return m_records.begin(); }
  /// Past the last record, for range-for
  /// \return the end iterator
  auto end() const noexcept { return m_records.end(); }

  /// The first lengths[i] samples of each record i (at most all of them): parts of checked records,
  /// so not checked again but for being empty, which gives std::invalid_argument "records[i] is empty".
  /// They need not be longer than the number of parameters.
  /// \param lengths one length per record, >= 0
  /// \return the parts, as views of the same vectors
  CheckedRecords heads(const std::vector<Eigen::Index>& lengths) const {
    detail::require(lengths.size() == m_records.size(), "heads needs one length per record");
    CheckedRecords part;
    for (std::size_t i = 0; i < m_records.size(); ++i) {
      detail::require(lengths[i] > 0, "records[" + std::to_string(i) + "] is empty");
      part.m_records.push_back(m_records[i].head(lengths[i]));
      part.m_samples += part.m_records.back().u.size();
    }
    return part;
  }

  /// The first part of each record, each in proportion to its length and at least one sample, about
  /// `samples` samples together (heads()).
  /// \param samples about how many samples the parts hold together, <= samples()
  /// \return the parts, as views of the same vectors
  CheckedRecords first_part(Eigen::Index samples) const {
    std::vector<Eigen::Index> lengths;
    for (const auto& record : m_records) lengths.push_back(record.u.size() * samples / m_samples + 1);
    return heads(lengths);
  }

 private:
  CheckedRecords() = default;
  Records<Scalar> m_records;
  Eigen::Index m_samples = 0;
};

namespace detail {

/// A state-initialisation window checked against the records: >= 0 and shorter than every record
/// (std::invalid_argument naming the record otherwise). IdentifyOptions::initialisation_window.
template <typename Scalar>
void require_initialisation_window(const Records<Scalar>& records, Eigen::Index window) {
  require(window >= 0, "initialisation_window must be >= 0, got " + std::to_string(window));
  for (std::size_t i = 0; i < records.size(); ++i) {
    require(records[i].u.size() > window, "initialisation_window (" + std::to_string(window) +
                                              ") must be shorter than every record; records[" + std::to_string(i) +
                                              "] has " + std::to_string(records[i].u.size()) + " samples");
  }
}

/// An initial-state choice checked against the window it follows: Estimated needs one
/// (std::invalid_argument otherwise). IdentifyOptions::initial_state.
inline void require_initial_state(InitialState state, Eigen::Index window) {
  require(state == InitialState::Measured || window > 0,
          "initial_state 'estimated' needs an initialisation_window > 0 (with none, every record starts at rest)");
}

/// The records' outputs one after another, each from its sample `window` on (the samples a free run
/// after a state-initialisation window of that many samples is scored on; 0: all of them).
template <typename Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, 1> stacked_outputs(const Records<Scalar>& records, Eigen::Index window = 0) {
  Eigen::Index total = 0;
  for (const auto& record : records) total += record.y.size() - window;
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> out(total);
  Eigen::Index start = 0;
  for (const auto& record : records) {
    out.segment(start, record.y.size() - window) = record.y.tail(record.y.size() - window);
    start += record.y.size() - window;
  }
  return out;
}

/// The free run of one record into `out`: from rest, or with window > 0 its samples from `window` on
/// simulated after the first `window`, measured, which set the model's state (Model::simulate's
/// past); with `past_y` (window long), after those outputs in place of the measured ones (an
/// estimated initial state: InitialState::Estimated). False if it leaves the finite numbers.
template <class Model>
bool simulate_record(const Model& model, const RecordView<typename Model::Scalar>& record, Eigen::Index window,
                     typename Model::VectorX& out, const typename Model::VectorX* past_y = nullptr) {
  if (window == 0) return model.try_simulate(record.u, out);
  const Eigen::Index n = record.u.size() - window;
  try {
    if (past_y) {
      out = model.simulate(record.u.tail(n), record.u.head(window), *past_y);
    } else {
      out = model.simulate(record.u.tail(n), record.u.head(window), record.y.head(window));
    }
  } catch (const NumericalError&) {
    return false;
  }
  return true;
}

/// The free run of each record (simulate_record), one after another into `out`; false as soon as one
/// leaves the finite numbers. `buffer` is scratch space for more than one record. `past_y`: empty, or
/// each record's window outputs in place of the measured ones.
template <class Model>
bool simulate_records(const Model& model, const Records<typename Model::Scalar>& records, typename Model::VectorX& out,
                      typename Model::VectorX& buffer, Eigen::Index window = 0,
                      const std::vector<typename Model::VectorX>& past_y = {}) {
  const auto past = [&](std::size_t i) { return past_y.empty() ? nullptr : &past_y[i]; };
  if (records.size() == 1) return simulate_record(model, records[0], window, out, past(0));
  Eigen::Index total = 0;
  for (const auto& record : records) total += record.u.size() - window;
  out.resize(total);
  Eigen::Index start = 0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (!simulate_record(model, records[i], window, buffer, past(i))) return false;
    out.segment(start, buffer.size()) = buffer;
    start += buffer.size();
  }
  return true;
}

}  // namespace detail
}  // namespace bonl
