// Heap allocations per evaluation (issue "speed without the heap", point 1).
//
// For the scenes of appell_bench_generic, the heavy top, the system files of the same scenes, the
// Whipple bicycle and a URDF robot, in every scalar (mpfr and mpfi at 256 bits), counts the calls of
// malloc, calloc and realloc (replaced in tests/counting_malloc.hpp, process-wide: operator new,
// std::vector, std::string, shared_ptr go through malloc, and so do Eigen's dynamic matrices,
// which a replaced operator new alone would miss) during one compute<T>() of the prepared scene,
// a new evaluation, after one call not counted (statics made, caches filled, the thread's working
// storage sized: linalg/scratch.hpp), and the bytes asked for; then the same for one
// compute_into() written over that evaluation (what a warm thread allocates evaluating the scene
// again: its names' and values' storage reused).  Prints one table:
//   scene  scalar  allocations  bytes  warm  warm_bytes
// Run: build/bench/appell_bench_allocations [SCENE.json ...]   (default: those ten)
// Not a timing: the counts are exact and the same from run to run.
// Where they come from: build/bench/appell_bench_allocations --sites SCENE.json SCALAR [DEPTH]
// prints, for the warm compute_into, each distinct chain of DEPTH callers (default 3) above
// malloc with its count, most first: the profile that says which function to give storage of its
// own next (issue "speed without the heap", point 1).  Frames inlined into their caller do not appear; names come from
// the program's dynamic symbols (linked with -rdynamic).
#include <cxxabi.h>
#include <dlfcn.h>
#include <execinfo.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "program_paths.hpp"  // APPELL_SOURCE_DIR, APPELL_BINARY, ... (CMakeLists.txt)
#include "appell/io/scene.hpp"

#include "counting_malloc.hpp"  // tests/: malloc, calloc, realloc replaced, counting per thread

namespace {
using counting_malloc::allocations;
using counting_malloc::bytes;
using counting_malloc::counting;
// --sites: the return addresses above each counted call, kept in a fixed array (no allocation
// while counting); `inside` keeps backtrace's own first allocation out.
constexpr int max_frames = 16, max_records = 1 << 16;
struct record {
  void* frames[max_frames];
  int n;
};
bool recording = false, inside = false;
record records[max_records];
int recorded = 0;
void record_callers() {
  if (recording && !inside && recorded < max_records) {
    inside = true;
    records[recorded].n = backtrace(records[recorded].frames, max_frames);
    ++recorded;
    inside = false;
  }
}
std::string frame_name(void* address) {
  Dl_info info;
  if (!dladdr(address, &info) || !info.dli_sname) return "?";
  int status = 0;
  char* demangled = abi::__cxa_demangle(info.dli_sname, nullptr, nullptr, &status);
  std::string name = status == 0 && demangled ? demangled : info.dli_sname;
  std::free(demangled);
  if (name.size() > 150) name = name.substr(0, 147) + "...";
  return name;
}
}  // namespace

using namespace appell;

/// --sites: one compute<T>() of SCENE in SCALAR, its allocations grouped by their callers.
int sites(const std::string& file, const std::string& scalar, int depth) {
  void* warm[2];
  (void)backtrace(warm, 2);  // loads what backtrace needs before counting
  counting_malloc::on_allocation = record_callers;
  const scene_input scene = read_scene_file(file);
  const bool mp = scalar == "mpfr" || scalar == "mpfi";
  with_scalar(scalar, mp ? std::optional<unsigned>(256) : std::nullopt, [&]<class T>(std::type_identity<T>) {
    const prepared_scene<T> prepared = prepare<T>(scene);
    evaluation<T> e;
    compute_into<T>(prepared, e);  // not counted: statics, caches, working storage
    compute_into<T>(prepared, e);
    allocations = bytes = 0;
    recording = counting = true;
    compute_into<T>(prepared, e);  // over the last evaluation: what a warm thread allocates
    recording = counting = false;
    return e.results.size();
  });
  std::map<std::vector<std::string>, int> chains;
  for (int i = 0; i < recorded; ++i) {
    std::vector<std::string> chain;
    // the first frames: record_callers(), count(), the replaced malloc, the allocator's own
    // callers (left out); then the first caller of the library's
    for (int k = 0; k < records[i].n && static_cast<int>(chain.size()) < depth; ++k) {
      std::string name = frame_name(records[i].frames[k]);
      const bool allocator = name.find("operator new") != std::string::npos || name.find("allocate") != std::string::npos ||
                             name.find("aligned_malloc") != std::string::npos || name == "?" ||
                             name.find("record_callers") != std::string::npos ||
                             name.find("counting_malloc") != std::string::npos || name == "malloc" ||
                             name == "calloc" || name == "realloc";
      if (!allocator || !chain.empty()) chain.push_back(std::move(name));
    }
    ++chains[chain];
  }
  std::vector<std::pair<int, std::vector<std::string>>> sorted;
  for (auto& [chain, n] : chains) sorted.emplace_back(n, chain);
  std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::printf("%s in %s: %ld allocations, %ld bytes, in one compute_into over the last evaluation\n", file.c_str(),
              scalar.c_str(), allocations, bytes);
  for (const auto& [n, chain] : sorted) {
    std::printf("%6d  %s\n", n, chain.empty() ? "?" : chain[0].c_str());
    for (std::size_t k = 1; k < chain.size(); ++k) std::printf("          <- %s\n", chain[k].c_str());
  }
  return 0;
}

int main(int argc, char** argv) {
  if (argc >= 4 && std::string(argv[1]) == "--sites")
    return sites(argv[2], argv[3], argc >= 5 ? std::max(1, std::atoi(argv[4])) : 3);
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) files.emplace_back(argv[i]);
  if (files.empty())
    for (const char* f : {"euler_body.json", "rolling_sphere_plane.json", "rolling_sphere_bowl.json", "top_on_cone.json",
                          "heavy_top.json", "system_euler_body.json", "system_rolling_sphere_bowl.json",
                          "system_top_on_cone.json", "system_whipple_bicycle.json", "urdf_kr5.json"})
      files.push_back(std::string(APPELL_SOURCE_DIR + "/data/scenes/") + f);
  std::printf("%-34s %-12s %12s %12s %12s %12s\n", "scene", "scalar", "allocations", "bytes", "warm", "warm_bytes");
  for (const std::string& file : files) {
    const scene_input scene = read_scene_file(file);
    for (const char* scalar : {"double", "long-double", "dd", "float128", "interval", "mpfr", "mpfi"}) {
      const bool mp = std::string(scalar) == "mpfr" || std::string(scalar) == "mpfi";
      // mpfr and mpfi at 256 bits (their default; the significands inside the values)
      with_scalar(scalar, mp ? std::optional<unsigned>(256) : std::nullopt, [&]<class T>(std::type_identity<T>) {
        const prepared_scene<T> prepared = prepare<T>(scene);
        (void)compute<T>(prepared);  // not counted: statics, caches, working storage
        allocations = bytes = 0;
        counting = true;
        evaluation<T> e = compute<T>(prepared);  // a new evaluation
        counting = false;
        const long fresh = allocations, fresh_bytes = bytes;
        compute_into<T>(prepared, e);
        allocations = bytes = 0;
        counting = true;
        compute_into<T>(prepared, e);  // over the last one (warm: its storage reused)
        counting = false;
        const std::string name = file.substr(file.find_last_of('/') + 1);
        std::printf("%-34s %-12s %12ld %12ld %12ld %12ld\n", name.c_str(), scalar, fresh, fresh_bytes, allocations, bytes);
        return e.results.size();
      });
    }
  }
}
