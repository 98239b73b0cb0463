#pragma once
// Fixed-capacity history of past samples, newest first. Storage is allocated once, when the
// capacity is set; push and lag access never allocate, which keeps per-sample updates
// allocation-free even when the delay nk is only known at run time.
//
// With a capacity known at compile time (the model orders na, nb) the history is a shift register
// in place: a push moves Capacity - 1 values, and every lag is a load at a constant offset, with no
// ring index to carry from one sample to the next (the estimators read all lags every sample).
// A run-time capacity (the delay nk) is a ring stored twice over, each push writing both copies, so
// that a lag is read at head + capacity - lag without a wrap-around test.

#include <Eigen/Core>

namespace bonl::detail {

template <typename Scalar, int Capacity = Eigen::Dynamic>
class History {
  using Storage = Eigen::Matrix<Scalar, Capacity, 1>;

 public:
  History() : m_data(Storage::Zero(Capacity == Eigen::Dynamic ? 0 : Capacity)) {}
  /// `capacity` must equal Capacity when that is fixed.
  explicit History(Eigen::Index capacity)
      : m_data(Storage::Zero(Capacity == Eigen::Dynamic ? 2 * capacity : capacity)), m_capacity(capacity) {}

  /// Back to rest: every stored past value is zero.
  void clear() noexcept {
    m_data.setZero();
    m_head = 0;
  }

  void push(Scalar value) noexcept {
    if constexpr (Capacity == Eigen::Dynamic) {
      if (m_capacity == 0) return;
      m_head = (m_head + 1 == m_capacity) ? 0 : m_head + 1;
      m_data[m_head] = value;
      m_data[m_head + m_capacity] = value;
    } else if constexpr (Capacity > 0) {
      for (int i = Capacity - 1; i > 0; --i) m_data[i] = m_data[i - 1];
      m_data[0] = value;
    }
  }

  /// Value pushed `lag` pushes ago (0 = newest). Requires lag < capacity().
  Scalar operator[](Eigen::Index lag) const noexcept {
    if constexpr (Capacity == Eigen::Dynamic) {
      return m_data[m_head + m_capacity - lag];
    } else {
      return m_data[lag];
    }
  }

  Eigen::Index capacity() const noexcept { return Capacity == Eigen::Dynamic ? m_capacity : Capacity; }

 private:
  Storage m_data;
  Eigen::Index m_capacity = 0;  // run-time capacity only: m_data holds the ring twice
  Eigen::Index m_head = 0;      // newest entry (run-time capacity only)
};

}  // namespace bonl::detail
