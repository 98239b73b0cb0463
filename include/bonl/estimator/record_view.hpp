#pragma once
// Several records (experiments) of one system identify one model: each record is simulated from rest
// and no history is carried across a record's boundaries. A RecordView refers to a record's u and y
// without copying them; it is made from vectors that outlive it (a temporary, such as the result of
// an expression, is refused at compile time rather than left dangling).

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "../detail/validate.hpp"

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

  Eigen::Map<const Vector> u;  ///< the input u
  Eigen::Map<const Vector> y;  ///< the measured output y

 private:
  RecordView(const Scalar* input, const Scalar* output, Eigen::Index samples)
      : u(input, samples), y(output, samples) {}
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

/// The records' outputs one after another.
template <typename Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, 1> stacked_outputs(const Records<Scalar>& records) {
  Eigen::Index total = 0;
  for (const auto& record : records) total += record.y.size();
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> out(total);
  Eigen::Index start = 0;
  for (const auto& record : records) {
    out.segment(start, record.y.size()) = record.y;
    start += record.y.size();
  }
  return out;
}

/// The free run of each record from rest, one after another into `out`; false as soon as one leaves
/// the finite numbers. `buffer` is scratch space for more than one record.
template <class Model>
bool simulate_records(const Model& model, const Records<typename Model::Scalar>& records,
                      typename Model::VectorX& out, typename Model::VectorX& buffer) {
  if (records.size() == 1) return model.try_simulate(records[0].u, out);
  Eigen::Index total = 0;
  for (const auto& record : records) total += record.u.size();
  out.resize(total);
  Eigen::Index start = 0;
  for (const auto& record : records) {
    if (!model.try_simulate(record.u, buffer)) return false;
    out.segment(start, buffer.size()) = buffer;
    start += buffer.size();
  }
  return true;
}

}  // namespace detail
}  // namespace bonl
