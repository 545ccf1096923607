#include "runtime/memory.h"

#include <gmp.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

namespace contactcert::runtime {
namespace {

void* other_allocate(std::size_t n) { return std::malloc(n); }
void* other_reallocate(void* p, std::size_t, std::size_t n) { return std::realloc(p, n); }
void other_free(void* p, std::size_t) { std::free(p); }

// The pool is installed over GMP's defaults, numbers made before it stay usable (freed into a free list), and a
// process whose GMP functions another library replaced keeps them.
TEST(PooledGmpMemory, OnlyOverTheDefaultFunctions) {
  mpz_t before;
  mpz_init_set_str(before, "123456789012345678901234567890", 10);  // allocated by GMP's default functions
  ASSERT_TRUE(use_pooled_gmp_memory_if_default());
  EXPECT_TRUE(use_pooled_gmp_memory_if_default());  // already installed
  mpz_t after;
  mpz_init(after);
  mpz_mul(after, before, before);
  mpz_mul(before, after, after);  // reallocates a default block with the pool's functions
  char* text = mpz_get_str(nullptr, 10, after);
  EXPECT_STREQ(text, "15241578753238836750495351562536198787501905199875019052100");
  void (*release)(void*, std::size_t) = nullptr;
  mp_get_memory_functions(nullptr, nullptr, &release);
  release(text, std::strlen(text) + 1);
  mpz_clear(before);
  mpz_clear(after);

  mp_set_memory_functions(other_allocate, other_reallocate, other_free);
  EXPECT_FALSE(use_pooled_gmp_memory_if_default());
  void* (*allocate)(std::size_t) = nullptr;
  mp_get_memory_functions(&allocate, nullptr, nullptr);
  EXPECT_EQ(allocate, &other_allocate);
}

}  // namespace
}  // namespace contactcert::runtime
