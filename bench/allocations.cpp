// Heap allocations per evaluation (issue "speed without the heap", point 1: the profile before).
//
// For the scenes of appell_bench_generic, the heavy top, the system files of the same scenes, the
// Whipple bicycle and a URDF robot, in every scalar (mpfr and mpfi at 256 bits), counts the calls of
// malloc, calloc and realloc (replaced below, process-wide: operator new, std::vector,
// std::string, shared_ptr go through malloc, and so do Eigen's dynamic matrices, which a replaced
// operator new alone would miss) during one compute<T>() of the prepared scene, after one call not
// counted (statics made, caches filled), and the bytes asked for.  Prints one table:
//   scene  scalar  allocations  bytes
// Run: build/bench/appell_bench_allocations [SCENE.json ...]   (default: those ten)
// Not a timing: the counts are exact and the same from run to run.
#include <cstddef>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "appell/io/scene.hpp"

// glibc's own allocator under the names it exports for this purpose ("Replacing malloc", the
// GNU C Library manual: a program that defines malloc, free, calloc and realloc replaces them in
// the whole process, libraries included).
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void __libc_free(void*);
}

namespace {
thread_local bool counting = false;
thread_local long allocations = 0, bytes = 0;
void count(std::size_t n) {
  if (counting) {
    ++allocations;
    bytes += static_cast<long>(n);
  }
}
}  // namespace

extern "C" {
void* malloc(std::size_t n) noexcept {
  count(n);
  return __libc_malloc(n);
}
void* calloc(std::size_t k, std::size_t n) noexcept {
  count(k * n);
  return __libc_calloc(k, n);
}
void* realloc(void* p, std::size_t n) noexcept {
  count(n);
  return __libc_realloc(p, n);
}
void free(void* p) noexcept { __libc_free(p); }
}

using namespace appell;

int main(int argc, char** argv) {
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) files.emplace_back(argv[i]);
  if (files.empty())
    for (const char* f : {"euler_body.json", "rolling_sphere_plane.json", "rolling_sphere_bowl.json", "top_on_cone.json",
                          "heavy_top.json", "system_euler_body.json", "system_rolling_sphere_bowl.json",
                          "system_top_on_cone.json", "system_whipple_bicycle.json", "urdf_kr5.json"})
      files.push_back(std::string(APPELL_SOURCE_DIR "/data/scenes/") + f);
  std::printf("%-34s %-12s %12s %12s\n", "scene", "scalar", "allocations", "bytes");
  for (const std::string& file : files) {
    const scene_input scene = read_scene_file(file);
    for (const char* scalar : {"double", "long-double", "dd", "float128", "interval", "mpfr", "mpfi"}) {
      const bool mp = std::string(scalar) == "mpfr" || std::string(scalar) == "mpfi";
      // mpfr and mpfi at 256 bits (their default; the significands inside the values)
      with_scalar(scalar, mp ? std::optional<unsigned>(256) : std::nullopt, [&]<class T>(std::type_identity<T>) {
        const prepared_scene<T> prepared = prepare<T>(scene);
        (void)compute<T>(prepared);  // not counted: statics, caches
        allocations = bytes = 0;
        counting = true;
        const evaluation<T> e = compute<T>(prepared);
        counting = false;
        const std::string name = file.substr(file.find_last_of('/') + 1);
        std::printf("%-34s %-12s %12ld %12ld\n", name.c_str(), scalar, allocations, bytes);
        return e.results.size();
      });
    }
  }
}
