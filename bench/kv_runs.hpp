// bench/kv_runs.hpp -- the kv library's verified integrator (Kashiwagi's kv, vendored whole under
// bench/kv with its MIT licence) on the problems of bench/enclose_vs_kv.cpp, run in the same
// process as appell's enclose, so that every kv figure the benchmark prints is measured in the run
// that prints it.  kv is compiled in its own unit (kv_runs.cpp) at C++17: it stores its vectors in
// Boost.uBLAS, whose Boost 1.74 storage calls std::allocator members that C++20 removed.  The
// boundary is plain doubles, so nothing of kv's reaches appell's units.
#pragma once

#include <string>
#include <vector>

namespace appell::bench {

/// A problem kv integrates, its equations written out by hand (kv takes no other form):
/// euler_body  Euler's equations, moments (1, 2, 3), omega0 = (1, 1, 1);
/// heavy_top   Lagrange's equations of the heavy symmetric top in Euler angles, x = (psi, theta,
///             phi, psi', theta', phi'), A = 1 about O, C = 2, m g l = 1, x0 = (0, 1, 0, 0.5, 0, 5);
/// pendulum    theta'' = -sin theta, x0 = (1, 0).
enum class kv_problem { euler_body, heavy_top, pendulum };

struct kv_box {
  std::vector<double> lower, upper;  ///< each component's bounds (kv's own outward-rounded ones)
};

struct kv_run {
  int status = 0;              ///< odelong_maffine's answer: 2 reached T, 1 stopped before it, 0 failed
  double t_reached = 0;        ///< the time the enclosure reached (T when status is 2)
  double seconds = 0;          ///< wall time of the integration alone
  long steps = 0;              ///< accepted steps (one callback each)
  kv_box end;                  ///< the state enclosed at t_reached
  std::vector<kv_box> step_ends;  ///< the state at each step's end (keep_steps only)
};

/// odelong_maffine (affine wrapping, interval<double>) from t = 0 to t_end at the given Taylor order,
/// kv's other parameters at their defaults (epsilon the double's, 2 iterations).  The caller's
/// floating-point environment (its rounding mode) is the same on return.
kv_run run_kv(kv_problem problem, double t_end, int order, bool keep_steps);

/// The problem's name, as the benchmark's rows print it.
std::string kv_problem_name(kv_problem problem);

}  // namespace appell::bench
