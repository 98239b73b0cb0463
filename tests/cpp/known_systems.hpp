#pragma once
// The known systems the C++ tests, the soak test and the model tool identify. No test framework
// here, so that programs outside Catch2 can use them.

#include <bonl/bonl.hpp>

#include <initializer_list>

namespace bonl_test {

inline Eigen::VectorXd vec(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double value : values) v[i++] = value;
  return v;
}

// The known systems, at the paper's orders (na = 3, nb = 2, nk = 8, r = r1 = 3). The linear block
// has poles 0.7 and 0.5 +- 0.3i (a damped, slow response like a hydraulic drive sampled fast); the
// input block is asymmetric (different slopes and curvature for u < 0), with small offsets; the
// output polynomial is monotone; the backlash half-width is about 10% of the output's spread.
inline constexpr Eigen::Index kNk = 8;

template <class Model>
void set_known_front(Model& model) {
  model.set_f(vec({0.002, 0.06, 0.02, -0.01}));
  model.set_p(vec({-0.003, -0.02, -0.03, 0.015}));
  model.set_b(vec({1.0, 0.5, 0.2}));
  model.set_a(vec({-1.7, 1.04, -0.238}));
}

inline bonl::PaperARX known_arx() {
  bonl::PaperARX model(3, 2, kNk);
  model.set_b(vec({0.05, 0.03, 0.02}));
  model.set_a(vec({-1.7, 1.04, -0.238}));
  return model;
}
inline bonl::PaperHammerstein known_hammerstein() {
  bonl::PaperHammerstein model(3, 2, kNk, 3);
  set_known_front(model);
  return model;
}
inline bonl::PaperHammersteinWiener known_hammerstein_wiener() {
  bonl::PaperHammersteinWiener model(3, 2, kNk, 3, 3);
  set_known_front(model);
  model.set_q(vec({1.0, 0.2, 0.05}));
  return model;
}
inline bonl::PaperPseudoHammersteinWiener known_phw() {
  bonl::PaperPseudoHammersteinWiener model(3, 2, kNk, 3);
  set_known_front(model);
  model.set_c(0.1);
  return model;
}

}  // namespace bonl_test
