#pragma once
// Fixed-capacity history of past samples, newest first. Storage is allocated once, when the
// capacity is set; push and lag access never allocate, which keeps per-sample updates
// allocation-free even when the delay nk is only known at run time.

#include <Eigen/Core>

namespace bonl::detail {

template <typename Scalar>
class History {
 public:
  History() = default;
  explicit History(Eigen::Index capacity) : m_data(Eigen::Matrix<Scalar, Eigen::Dynamic, 1>::Zero(capacity)) {}

  /// Back to rest: every stored past value is zero.
  void clear() noexcept {
    m_data.setZero();
    m_head = 0;
  }

  void push(Scalar value) noexcept {
    if (m_data.size() == 0) return;
    m_head = (m_head + 1 == m_data.size()) ? 0 : m_head + 1;
    m_data[m_head] = value;
  }

  /// Value pushed `lag` pushes ago (0 = newest). Requires lag < capacity().
  Scalar operator[](Eigen::Index lag) const noexcept {
    const Eigen::Index i = m_head - lag;
    return m_data[i < 0 ? i + m_data.size() : i];
  }

  Eigen::Index capacity() const noexcept { return m_data.size(); }

 private:
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> m_data;
  Eigen::Index m_head = 0;
};

}  // namespace bonl::detail
