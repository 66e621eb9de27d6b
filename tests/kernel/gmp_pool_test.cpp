// The number pool (kernel/gmp_pool.hpp): GMP's small blocks from slabs. The same numbers as
// with malloc, blocks freed on other threads reused safely, growth past the pool's largest
// block, and a free with a wrong size (the class follows from the address). ctest runs each
// test in its own process, so installing the pool here changes no other test.
#include <gmp.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "kernel/gmp_pool.hpp"
#include "kernel/number.hpp"

namespace hlr {
namespace {

// A reproducible walk through rational arithmetic: sums, products, quotients, numbers that
// grow from one limb to many and shrink again.
std::vector<std::string> arithmetic_walk() {
  std::vector<std::string> out;
  Rational x(1, 3), y = 7;
  for (int i = 1; i <= 300; ++i) {
    x = x * Rational(i, i + 2) + y / Rational(i * 7 + 1);
    y = y * 3 - Rational(1, i);
    if (i % 50 == 0) y = Rational(i, 11);  // shrink back to one limb
    out.push_back(x.get_str() + " " + y.get_str());
  }
  return out;
}

TEST(GmpPool, SameNumbersAsMalloc) {
  std::vector<std::string> before = arithmetic_walk();
  Rational made_before(22, 7);  // a malloc block, freed through the pool's free later
  ASSERT_TRUE(gmp_pool::install(false));
  EXPECT_TRUE(gmp_pool::installed());
  EXPECT_TRUE(gmp_pool::install(false));  // a second call changes nothing
  EXPECT_EQ(arithmetic_walk(), before);
  made_before = Rational(1, 2) + made_before;
  EXPECT_EQ(made_before.get_str(), "51/14");
  EXPECT_GT(gmp_pool::reserved_bytes(), 0u);
}

TEST(GmpPool, NumbersFreedOnOtherThreadsAreReusedSafely) {
  ASSERT_TRUE(gmp_pool::install(false));
  // Threads make numbers, the main thread frees them, the threads make more: every value
  // must survive the others' traffic.
  for (int round = 0; round < 3; ++round) {
    std::vector<std::vector<Rational>> made(4);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
      threads.emplace_back([&made, t] {
        for (int i = 0; i < 20000; ++i) made[t].push_back(Rational(i * 4 + t, 1 + (i % 9)));
      });
    for (auto& th : threads) th.join();
    for (int t = 0; t < 4; ++t)
      for (int i = 0; i < 20000; ++i) ASSERT_EQ(made[t][i], Rational(i * 4 + t, 1 + (i % 9)));
    made.clear();  // freed on this thread, into this thread's lists
    std::vector<Rational> again;
    for (int i = 0; i < 80000; ++i) again.push_back(Rational(i, 3));
    for (int i = 0; i < 80000; ++i) ASSERT_EQ(again[i] * 3, Rational(i));
  }
}

TEST(GmpPool, BlocksDoNotOverlapAfterAFreeWithTheWrongSize) {
  ASSERT_TRUE(gmp_pool::install(false));
  void* (*alloc)(size_t);
  void* (*realloc_fn)(void*, size_t, size_t);
  void (*free_fn)(void*, size_t);
  mp_get_memory_functions(&alloc, &realloc_fn, &free_fn);
  void* small = alloc(8);
  free_fn(small, 32);  // claims 32 bytes: must go back to the 8-byte blocks
  std::set<std::uintptr_t> starts;
  std::vector<void*> blocks;
  for (int i = 0; i < 64; ++i) {
    void* p = alloc(32);
    std::memset(p, 0xab, 32);
    blocks.push_back(p);
    starts.insert(reinterpret_cast<std::uintptr_t>(p));
  }
  std::uintptr_t last = 0;
  for (std::uintptr_t s : starts) {
    EXPECT_TRUE(last == 0 || s - last >= 32) << "32-byte blocks overlap";
    last = s;
  }
  // Growing a pool block past 32 bytes keeps its contents.
  auto* g = static_cast<unsigned char*>(alloc(16));
  for (int i = 0; i < 16; ++i) g[i] = static_cast<unsigned char>(i);
  g = static_cast<unsigned char*>(realloc_fn(g, 16, 4096));
  for (int i = 0; i < 16; ++i) EXPECT_EQ(g[i], i);
  free_fn(g, 4096);
  for (void* p : blocks) free_fn(p, 32);
}

TEST(GmpPool, NumbersOfThousandsOfDigits) {
  ASSERT_TRUE(gmp_pool::install(false));
  mpz_class f = 1;
  for (int i = 2; i <= 1000; ++i) f *= i;  // 1000!: 2,568 digits, grown one limb at a time
  EXPECT_EQ(f.get_str().size(), 2568u);
  mpz_class g = f;
  for (int i = 1000; i >= 2; --i) g /= i;
  EXPECT_EQ(g, 1);
}

}  // namespace
}  // namespace hlr
