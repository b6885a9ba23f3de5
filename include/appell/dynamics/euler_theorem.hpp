// appell/dynamics/euler_theorem.hpp -- Cotton's eq. (6): u' . P = 2 S2 + S1.
//
// From equations of motion obtained any other way (Newton-Euler, Lagrange),
// given as P(u') affine in u', the useful part of the acceleration energy
// follows: in u' . P double the first-degree terms and drop the rest; that is
// 2 (S2 + S1).  rebuild_energy() extracts the quadratic form and the linear
// part of u' . P by evaluating P at 0 and at the unit vectors (exact for an
// affine P), so it needs nothing but the function.
#pragma once

#include <functional>

#include "appell/dynamics/gibbs_appell.hpp"

namespace appell {

/// S2 + S1 = 1/2 u'.K u' + c.u', rebuilt from P(u') (K symmetrised).
template <Scalar T>
struct rebuilt_energy {
  matrix_t<T> K;  ///< the quadratic form of 2 S2 (symmetric part of dP/du')
  vector_t<T> c;  ///< S1 = c . u'
  T operator()(const vector_t<T>& udot) const {
    T s = T(0);
    for (Eigen::Index i = 0; i < udot.size(); ++i) {
      T row = T(0);
      for (Eigen::Index j = 0; j < udot.size(); ++j) row += K(i, j) * udot(j);
      s += (row / T(2) + c(i)) * udot(i);
    }
    return s;
  }
};

template <Scalar T>
rebuilt_energy<T> rebuild_energy(const std::function<vector_t<T>(const vector_t<T>&)>& P, int k) {
  const vector_t<T> P0 = P(vector_t<T>::Zero(k));
  matrix_t<T> D(k, k);
  for (int j = 0; j < k; ++j) {
    vector_t<T> e = vector_t<T>::Zero(k);
    e(j) = T(1);
    D.col(j) = P(e) - P0;
  }
  rebuilt_energy<T> r{matrix_t<T>(k, k), P0};
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) r.K(i, j) = (D(i, j) + D(j, i)) / T(2);
  return r;
}

}  // namespace appell
