// The studies' runs in a scalar named at run time (studies/scalar_runs.hpp).
#include "appell/studies/scalar_runs.hpp"

#include <chrono>
#include <memory>

#include "appell/scalar/standard_scalars.hpp"

namespace appell::studies {

namespace {

template <class T>
scalar_outcome evaluate_in(const scene_input& scene, const std::vector<mpfr_value>* ref, double cap) {
  scalar_outcome o;
  o.bits = scalar_traits<T>::precision_bits();
  try {
    const evaluation<T> e = evaluate<T>(scene);
    if (ref) {
      const accuracy a = measure_accuracy(e, *ref, cap);
      o.digits = a.digits;
      o.rel_width = a.rel_width;
    }
    for (const auto& c : e.checks)
      if (c.name == "error_amplification") o.amplification = approx_double(c.values[0]);
  } catch (const input_error& x) {
    o.status = "bad input";
    o.why = x.what();
  } catch (const std::exception& x) {
    o.status = "refused";
    o.why = x.what();
  }
  return o;
}

// Inside with_scalar: for mpfr and mpfi the precision is already set.
template <class T>
timed_scalar timing_in(const scene_input& scene, const std::vector<mpfr_value>& ref, double cap) {
  timed_scalar c;
  c.scalar = scalar_traits<T>::name;
  c.bits = scalar_traits<T>::precision_bits();
  const unsigned bits = scalar_traits<T>::runtime_precision ? mp_precision_bits() : 0;
  try {
    auto prepared = std::make_shared<prepared_scene<T>>(prepare<T>(scene));
    const accuracy a = measure_accuracy(compute<T>(*prepared), ref, cap);
    c.digits = a.digits;
    c.rel_width = a.rel_width;
    auto run = [prepared, bits](long n) {
      std::optional<mp_precision_scope> s;
      if (bits) s.emplace(bits);
      for (long i = 0; i < n; ++i) (void)compute<T>(*prepared);
    };
    // batch size: enough evaluations for >= 1 ms (shorter batches, run right after a
    // heavy scalar's, paid for cold caches: interval/double read 3.9-4.0 at 100 us
    // against 3.3-3.5 in appell_bench's long runs)
    using clock = std::chrono::steady_clock;
    long batch = 1;
    for (;;) {
      const auto t0 = clock::now();
      run(batch);
      const double us = std::chrono::duration<double, std::micro>(clock::now() - t0).count();
      if (us >= 1000 || batch >= (1 << 20)) break;
      batch *= 2;
    }
    run(3 * batch);  // warm-up
    c.batch = batch;
    c.run_batch = [run, batch] { run(batch); };
  } catch (const std::exception& e) {
    c.note = e.what();
  }
  return c;
}

}  // namespace

scalar_outcome evaluate_against(const scene_input& scene, const std::vector<mpfr_value>* ref, double cap,
                                const std::string& scalar, std::optional<unsigned> bits) {
  return with_scalar(scalar, bits, [&]<class T>(std::type_identity<T>) { return evaluate_in<T>(scene, ref, cap); });
}

timed_scalar prepare_timing(const scene_input& scene, const std::vector<mpfr_value>& ref, double cap,
                            const std::string& scalar, std::optional<unsigned> bits) {
  return with_scalar(scalar, bits, [&]<class T>(std::type_identity<T>) { return timing_in<T>(scene, ref, cap); });
}

}  // namespace appell::studies
