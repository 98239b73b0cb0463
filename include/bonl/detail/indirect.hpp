#pragma once
// A value held on the heap with the value's own semantics: copied deeply, moved as a pointer, empty
// or not. For a member whose type is not complete where it is declared (the estimator's
// equation-error recursion is itself an Estimator), where std::optional cannot hold it.

#include <memory>
#include <utility>

namespace bonl::detail {

/// T on the heap, or nothing; copies copy the T.
template <class T>
class Indirect {
 public:
  Indirect() = default;
  Indirect(const Indirect& other) : m_value(other.m_value ? std::make_unique<T>(*other.m_value) : nullptr) {}
  Indirect(Indirect&&) noexcept = default;
  Indirect& operator=(const Indirect& other) {
    if (this != &other) m_value = other.m_value ? std::make_unique<T>(*other.m_value) : nullptr;
    return *this;
  }
  Indirect& operator=(Indirect&&) noexcept = default;
  ~Indirect() = default;

  /// A T constructed from `arguments` (allocates)
  template <class... Arguments>
  void emplace(Arguments&&... arguments) {
    m_value = std::make_unique<T>(std::forward<Arguments>(arguments)...);
  }
  explicit operator bool() const noexcept { return m_value != nullptr; }  ///< whether it holds a T
  T& operator*() noexcept { return *m_value; }                            ///< the T (it holds one)
  const T& operator*() const noexcept { return *m_value; }                ///< the T (it holds one)
  T* operator->() noexcept { return m_value.get(); }                      ///< the T (it holds one)
  const T* operator->() const noexcept { return m_value.get(); }          ///< the T (it holds one)

 private:
  std::unique_ptr<T> m_value;
};

}  // namespace bonl::detail
