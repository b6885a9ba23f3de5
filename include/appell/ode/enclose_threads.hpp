// appell/ode/enclose_threads.hpp -- how many threads one enclose may use (ode/enclose.hpp),
// apart, so that a command sets it without the integrator's templates.
#pragma once

#include <algorithm>

namespace appell::ode {

/// How many threads one enclose may use (this thread's setting; 1: none besides the caller).
/// With 2 and interval<double>, a step's slopes (the first q coefficients' slopes about the
/// centre) are computed on a second thread while this one finds the a priori enclosure: the same
/// operations on the same numbers, so the same enclosure bit for bit (tests/cli.cpp compares the
/// files of the two).  1 unless set: `appell enclose` sets it from --jobs (by default 2 where the
/// machine has two cores); validity's pieces, which fill the cores with whole runs, leave it at 1.
/// Other scalars run on one thread (mpfr's and mpfi's values re-aim their limbs' pointer on every
/// read, also of a constant both would share).
inline thread_local int enclose_threads = 1;

/// Sets enclose_threads for a scope.
class enclose_threads_scope {
 public:
  explicit enclose_threads_scope(int n) : saved_(enclose_threads) { enclose_threads = std::max(1, n); }
  ~enclose_threads_scope() { enclose_threads = saved_; }
  enclose_threads_scope(const enclose_threads_scope&) = delete;
  enclose_threads_scope& operator=(const enclose_threads_scope&) = delete;

 private:
  int saved_;
};

}  // namespace appell::ode
