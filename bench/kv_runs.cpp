// bench/kv_runs.cpp -- kv's odelong_maffine on the benchmark's three problems (kv_runs.hpp).
// Compiled at C++17 (bench/CMakeLists.txt): kv's vectors are Boost.uBLAS ones.
#include "kv_runs.hpp"

#include <cfenv>
#include <chrono>
#include <stdexcept>

#include <kv/ode-maffine.hpp>

namespace ub = boost::numeric::ublas;
using itv = kv::interval<double>;

namespace appell::bench {
namespace {

// The equations by hand, each a functor templated on kv's arithmetic (psa, affine, interval).
struct euler_body_equations {
  template <class T>
  ub::vector<T> operator()(const ub::vector<T>& x, T) const {
    ub::vector<T> f(3);  // A, B, C = 1, 2, 3: (B - C) q r / A, (C - A) r p / B, (A - B) p q / C
    f(0) = T(-1.) * x(1) * x(2);
    f(1) = T(2.) * x(2) * x(0) / T(2.);
    f(2) = T(-1.) * x(0) * x(1) / T(3.);
    return f;
  }
};

// With the spin r = phi' + psi' cos theta:
//   A theta'' = A psi'^2 sin cos - C r psi' sin + m g l sin,
//   psi'' = (C r theta' - 2 A psi' theta' cos) / (A sin),   phi'' = -psi'' cos + psi' theta' sin.
struct heavy_top_equations {
  template <class T>
  ub::vector<T> operator()(const ub::vector<T>& x, T) const {
    using std::sin, std::cos;
    const T s = sin(x(1)), c = cos(x(1));
    const T r = x(5) + x(3) * c;
    const T th2 = x(3) * x(3) * s * c - T(2.) * r * x(3) * s + s;
    const T ps2 = (T(2.) * r * x(4) - T(2.) * x(3) * x(4) * c) / s;
    ub::vector<T> f(6);
    f(0) = x(3);
    f(1) = x(4);
    f(2) = x(5);
    f(3) = ps2;
    f(4) = th2;
    f(5) = x(3) * x(4) * s - ps2 * c;
    return f;
  }
};

struct pendulum_equations {
  template <class T>
  ub::vector<T> operator()(const ub::vector<T>& x, T) const {
    using std::sin;
    ub::vector<T> f(2);
    f(0) = x(1);
    f(1) = -sin(x(0));
    return f;
  }
};

kv_box box_of(const ub::vector<itv>& x) {
  kv_box b;
  for (std::size_t i = 0; i < x.size(); ++i) {
    b.lower.push_back(x(i).lower());
    b.upper.push_back(x(i).upper());
  }
  return b;
}

// Counts the steps and, when asked, keeps each step's end box.
struct step_record : kv::ode_callback<double> {
  kv_run* run;
  bool keep;
  step_record(kv_run* r, bool k) : run(r), keep(k) {}
  bool operator()(const itv&, const itv&, const ub::vector<itv>&, const ub::vector<itv>& x_e,
                  const ub::vector<kv::psa<itv>>&) const override {
    ++run->steps;
    if (keep) run->step_ends.push_back(box_of(x_e));
    return true;
  }
};

// kv switches the rounding mode itself (upward inside its operations, to nearest after them),
// where the caller may be inside an appell upward_rounding scope, whose interval operations rely on
// the mode staying upward: the caller's floating-point environment is restored on the way out.
struct saved_environment {
  std::fenv_t env;
  saved_environment() { std::fegetenv(&env); }
  ~saved_environment() { std::fesetenv(&env); }
};

template <class F>
kv_run integrate(const F& f, ub::vector<itv> x, double t_end, int order, bool keep_steps) {
  const saved_environment caller;
  kv_run run;
  itv end(t_end);
  kv::ode_param<double> p;
  p.set_order(order);
  const auto start = std::chrono::steady_clock::now();
  run.status = kv::odelong_maffine(f, x, itv(0.), end, p, step_record(&run, keep_steps));
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.t_reached = run.status == 2 ? t_end : end.lower();
  run.end = box_of(x);
  return run;
}

}  // namespace

kv_run run_kv(kv_problem problem, double t_end, int order, bool keep_steps) {
  switch (problem) {
    case kv_problem::euler_body: {
      ub::vector<itv> x(3);
      x(0) = 1.;
      x(1) = 1.;
      x(2) = 1.;
      return integrate(euler_body_equations{}, x, t_end, order, keep_steps);
    }
    case kv_problem::heavy_top: {
      ub::vector<itv> x(6);
      x(0) = 0.;
      x(1) = 1.;
      x(2) = 0.;
      x(3) = 0.5;
      x(4) = 0.;
      x(5) = 5.;
      return integrate(heavy_top_equations{}, x, t_end, order, keep_steps);
    }
    case kv_problem::pendulum: {
      ub::vector<itv> x(2);
      x(0) = 1.;
      x(1) = 0.;
      return integrate(pendulum_equations{}, x, t_end, order, keep_steps);
    }
  }
  throw std::logic_error("run_kv: unknown problem");
}

std::string kv_problem_name(kv_problem problem) {
  switch (problem) {
    case kv_problem::euler_body: return "euler_body";
    case kv_problem::heavy_top: return "heavy_top";
    case kv_problem::pendulum: return "pendulum";
  }
  return "?";
}

}  // namespace appell::bench
