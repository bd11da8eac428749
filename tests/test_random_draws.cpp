// The engine's seeded draws (engine/random_draws.hpp): uniform, the same on
// every toolchain, and, under libstdc++, the draws std:: makes, so that the
// figures measured before them still hold.
#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "engine/random_draws.hpp"

using namespace loom;

TEST_CASE("multiply_wide gives both halves of the 128-bit product") {
  const auto p = engine::multiply_wide(UINT64_MAX, UINT64_MAX);  // 2^128 - 2^65 + 1
  CHECK(p.high == UINT64_MAX - 1);
  CHECK(p.low == 1);
  const auto q = engine::multiply_wide(std::uint64_t{1} << 40, (std::uint64_t{1} << 30) + 3);
  CHECK(q.high == 64);
  CHECK(q.low == std::uint64_t{3} << 40);
}

TEST_CASE("uniform_below stays below n and reaches every value about equally often") {
  std::mt19937_64 rng(3);
  for (std::uint64_t n : {1ull, 2ull, 3ull, 7ull, 1000ull}) {
    std::vector<std::size_t> seen(n, 0);
    const std::size_t draws = 2000 * n;
    for (std::size_t i = 0; i < draws; ++i) {
      const std::uint64_t x = engine::uniform_below(rng, n);
      REQUIRE(x < n);
      ++seen[x];
    }
    const auto [least, most] = std::minmax_element(seen.begin(), seen.end());
    CHECK(*least > 1700);  // 2,000 expected each; 6.7 standard deviations
    CHECK(*most < 2300);
  }
  // Close to 2^64 most draws land in the biased part: they are redrawn.
  const std::uint64_t huge = (std::uint64_t{1} << 63) + 1;
  for (int i = 0; i < 100; ++i) CHECK(engine::uniform_below(rng, huge) < huge);
}

TEST_CASE("shuffle permutes, and every position takes every element") {
  std::mt19937_64 rng(5);
  for (std::size_t n : {0u, 1u, 2u, 5u, 6u}) {
    std::vector<std::size_t> at(n * n, 0);
    for (int round = 0; round < 3000; ++round) {
      std::vector<std::size_t> v(n);
      std::iota(v.begin(), v.end(), 0);
      engine::shuffle(v.begin(), v.end(), rng);
      std::vector<std::size_t> sorted = v;
      std::sort(sorted.begin(), sorted.end());
      for (std::size_t i = 0; i < n; ++i) REQUIRE(sorted[i] == i);
      for (std::size_t i = 0; i < n; ++i) ++at[i * n + v[i]];
    }
    for (std::size_t c : at) CHECK(c > 3000 / n * 3 / 4);
  }
}

TEST_CASE("the draws are fixed by the seed alone") {
  // Golden values: they hold on any standard library, since only the raw
  // output of std::mt19937_64, which the standard fixes, is used.
  std::mt19937_64 rng(42);
  std::vector<std::uint64_t> draws;
  for (std::uint64_t n : {10ull, 1000ull, 3ull, 1'000'000ull}) draws.push_back(engine::uniform_below(rng, n));
  std::vector<int> v(9);
  std::iota(v.begin(), v.end(), 0);
  engine::shuffle(v.begin(), v.end(), rng);
  CHECK(draws == std::vector<std::uint64_t>{7, 639, 2, 136272});
  CHECK(v == std::vector<int>{3, 4, 7, 6, 1, 0, 5, 2, 8});
}

#ifdef __GLIBCXX__
TEST_CASE("under libstdc++ the draws are those of std::uniform_int_distribution and std::shuffle") {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    std::mt19937_64 ours(seed), theirs(seed);
    for (std::size_t n = 1; n < 300; n += 7) {
      CHECK(engine::uniform_below(ours, n) == std::uniform_int_distribution<std::size_t>(0, n - 1)(theirs));
      std::vector<std::size_t> a(n), b(n);
      std::iota(a.begin(), a.end(), 0);
      std::iota(b.begin(), b.end(), 0);
      engine::shuffle(a.begin(), a.end(), ours);
      std::shuffle(b.begin(), b.end(), theirs);
      CHECK(a == b);
    }
  }
}
#endif
