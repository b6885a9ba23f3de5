// The library's evaluation in a program (its thread-local storage accessed as a program's, by the
// linker's single load), timed as bench/python_overhead.py times the Python module's (a shared
// object opened at run time: its scratch pools reached through TLS descriptors, the rounding flag
// through libappell_rounding.so's static TLS; docs/architecture.md, "Python"):
//   appell_bench_eval_loop SCENE SCALAR N   prints the seconds per evaluation, evaluate<T> then
//                                           printed<T>, as appell.Scene.eval does them
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "appell/io/scene.hpp"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: appell_bench_eval_loop SCENE SCALAR N\n");
    return 2;
  }
  using namespace appell;
  const scene_input scene = read_scene_file(argv[1]);
  const long n = std::atol(argv[3]);
  const double seconds = with_scalar(argv[2], std::nullopt, [&]<class T>(std::type_identity<T>) {
    std::size_t keep = printed<T>(scene, evaluate<T>(scene)).results.size();  // warm
    const auto t0 = std::chrono::steady_clock::now();
    for (long i = 0; i < n; ++i) keep += printed<T>(scene, evaluate<T>(scene)).results.size();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (keep == 0) std::abort();
    return s;
  });
  std::printf("%.9g\n", seconds / static_cast<double>(n));
}
