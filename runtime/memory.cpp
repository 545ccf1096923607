#include "runtime/memory.h"

#include <gmp.h>
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>

// GMP's default memory functions (exported by libgmp, declared in its internal gmp-impl.h only).
extern "C" {
void* __gmp_default_allocate(std::size_t);
void* __gmp_default_reallocate(void*, std::size_t, std::size_t);
void __gmp_default_free(void*, std::size_t);
}

namespace contactcert::runtime {
namespace {

constexpr std::size_t kGrain = sizeof(mp_limb_t);         // block sizes are whole limbs
constexpr std::size_t kClasses = kPooledBytes / kGrain;   // one free list per size in limbs
constexpr std::size_t kSlabBytes = std::size_t{1} << 16;  // carved into blocks, never returned

/// The free blocks of one thread, linked through their first word, and the unused tail of its current slab.
struct Pool {
  void* free_list[kClasses] = {};
  char* next = nullptr;
  char* end = nullptr;
};
thread_local Pool pool;

bool pooled(std::size_t n) { return n > 0 && n <= kPooledBytes; }
std::size_t class_of(std::size_t n) { return (n - 1) / kGrain; }  // n in [1, kPooledBytes]

void* checked(void* p) {
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

void* allocate(std::size_t n) {
  if (!pooled(n)) return checked(std::malloc(n));
  Pool& p = pool;
  void*& head = p.free_list[class_of(n)];
  if (head != nullptr) {
    void* block = head;
    head = *static_cast<void**>(block);
    return block;
  }
  const std::size_t bytes = (class_of(n) + 1) * kGrain;
  if (static_cast<std::size_t>(p.end - p.next) < bytes) {  // a new slab; the old one's tail (< 64 bytes) is left
    p.next = static_cast<char*>(checked(std::malloc(kSlabBytes)));
    p.end = p.next + kSlabBytes;
  }
  void* block = p.next;
  p.next += bytes;
  return block;
}

void release(void* block, std::size_t n) {
  if (!pooled(n)) return std::free(block);
  void*& head = pool.free_list[class_of(n)];
  *static_cast<void**>(block) = head;
  head = block;
}

void* reallocate(void* block, std::size_t old_n, std::size_t n) {
  if (!pooled(old_n) && !pooled(n)) return checked(std::realloc(block, n));
  if (pooled(old_n) && pooled(n) && class_of(old_n) == class_of(n)) return block;
  void* moved = allocate(n);
  std::memcpy(moved, block, std::min(old_n, n));
  release(block, old_n);
  return moved;
}

/// The heap's next kSpan bytes on transparent huge pages. madvise marks only mapped memory that no fault has touched
/// yet (a small page already in a 2 MiB range keeps that range small), so: move the break to one page below a 2 MiB
/// boundary, let malloc extend the heap by a block of kSpan + a page, whose header lands on that page and whose
/// successor's header lands past the span, mark the span, and free the block back into the top of the heap.
void heap_on_huge_pages() {
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  constexpr std::uintptr_t kSpan = 8 * kHuge;
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  void* const failed = reinterpret_cast<void*>(-1);
  void* const top = sbrk(0);
  if (top == failed) return;
  const auto brk = reinterpret_cast<std::uintptr_t>(top);
  const std::uintptr_t first = (brk + page + kHuge - 1) & ~(kHuge - 1);
  if (sbrk(static_cast<std::intptr_t>(first - page - brk)) == failed) return;
  void* block = std::malloc(kSpan + page);
  const auto at = reinterpret_cast<std::uintptr_t>(block);
  if (block != nullptr && at < first && at + kSpan + page <= reinterpret_cast<std::uintptr_t>(sbrk(0)))
    madvise(reinterpret_cast<void*>(first), kSpan, MADV_HUGEPAGE);  // only where malloc put the block: the heap
  std::free(block);
}

}  // namespace

void use_pooled_gmp_memory() { mp_set_memory_functions(allocate, reallocate, release); }

bool use_pooled_gmp_memory_if_default() {
  void* (*a)(std::size_t) = nullptr;
  void* (*r)(void*, std::size_t, std::size_t) = nullptr;
  void (*f)(void*, std::size_t) = nullptr;
  mp_get_memory_functions(&a, &r, &f);
  if (a == allocate && r == reallocate && f == release) return true;
  if (a != __gmp_default_allocate || r != __gmp_default_reallocate || f != __gmp_default_free) return false;
  use_pooled_gmp_memory();
  return true;
}

void keep_heap_until_exit() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
  heap_on_huge_pages();
}

}  // namespace contactcert::runtime
