// tests/counting_malloc.hpp -- counts the heap's calls in a window (tests/allocations.cpp,
// bench/allocations.cpp).  Include it in ONE translation unit of a program: it replaces malloc,
// calloc, realloc and free for the whole process ("Replacing malloc", the GNU C Library manual),
// so that operator new, std::vector, std::string, shared_ptr and Eigen's dynamic matrices (which
// call malloc directly, and a replaced operator new alone would miss) are all counted.  The
// replacements hand every call to glibc's allocator under the names it exports for the purpose.
#pragma once

#include <cstddef>

extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void __libc_free(void*);
}

namespace counting_malloc {
/// Counting is per thread: on while `counting` is true.
inline thread_local bool counting = false;
inline thread_local long allocations = 0, bytes = 0;
/// Called on each counted allocation (bench/allocations.cpp: records its callers); may be null.
inline void (*on_allocation)() = nullptr;
inline void count(std::size_t n) {
  if (!counting) return;
  ++allocations;
  bytes += static_cast<long>(n);
  if (on_allocation) on_allocation();
}
/// The allocations `f` makes on this thread.
template <class F>
long allocations_in(F&& f) {
  allocations = bytes = 0;
  counting = true;
  f();
  counting = false;
  return allocations;
}
}  // namespace counting_malloc

extern "C" {
void* malloc(std::size_t n) noexcept {
  counting_malloc::count(n);
  return __libc_malloc(n);
}
void* calloc(std::size_t k, std::size_t n) noexcept {
  counting_malloc::count(k * n);
  return __libc_calloc(k, n);
}
void* realloc(void* p, std::size_t n) noexcept {
  counting_malloc::count(n);
  return __libc_realloc(p, n);
}
void free(void* p) noexcept { __libc_free(p); }
}
