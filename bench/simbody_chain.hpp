// bench/simbody_chain.hpp -- the planar N-link pendulum of chain.cpp in Simbody.
// Simbody 3.7's headers do not compile as C++20 (ambiguous reversed operator==),
// so simbody_chain.cpp is compiled as C++17 and this interface uses neither
// Simbody's types nor appell's.
#pragma once

#include <memory>
#include <vector>

class simbody_chain {
 public:
  /// N links of mass 1 and length 1 on Pin mobilizers, central inertia 1/12,
  /// gravity 9.81 along -y; joint angles q and rates u.
  simbody_chain(int n, const std::vector<double>& q, const std::vector<double>& u);
  ~simbody_chain();
  /// Forward dynamics from the positions up (positions invalidated each call): the n accelerations.
  const double* accelerations();

 private:
  struct impl;
  std::unique_ptr<impl> p_;
};
