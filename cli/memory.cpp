#include "cli/memory.h"

#include <gmp.h>
#include <malloc.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>

namespace contactcert::cli {
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

}  // namespace

void use_pooled_gmp_memory() { mp_set_memory_functions(allocate, reallocate, release); }

void keep_heap_until_exit() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
}

}  // namespace contactcert::cli
