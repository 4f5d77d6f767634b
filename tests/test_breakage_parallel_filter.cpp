// breakage::parallel_filter, which the replacement's scans and the strength draws use: the hits
// must come back in ascending order, the same list as a serial scan, for any thread count (the
// energy booking and the RNG draws that follow run in that order).
#include <gtest/gtest.h>
#include <omp.h>

#include "comminute/breakage/parallel_filter.hpp"
#include "comminute/core/rng.hpp"

using namespace comminute;

TEST(BreakageParallelFilter, HitsInSlotOrderForAnyThreadCount) {
  const std::size_t n = 100003;  // above the threshold, not a multiple of the thread count
  Rng rng(7);
  std::vector<std::uint8_t> hit(n);
  for (auto& h : hit) h = rng.uniform(0, 1) < 0.01 ? 1 : 0;
  std::vector<std::uint32_t> serial;
  for (std::size_t k = 0; k < n; ++k)
    if (hit[k]) serial.push_back(static_cast<std::uint32_t>(k));
  ASSERT_GT(serial.size(), 500u);  // the draw gives ~1000 hits: the comparison has content
  const int saved = omp_get_max_threads();
  for (int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    EXPECT_EQ(breakage::parallel_filter(n, [&](std::size_t k) { return hit[k] != 0; }), serial)
        << threads << " threads";
  }
  omp_set_num_threads(saved);
  // a small scan runs serially and gives the same
  EXPECT_EQ(breakage::parallel_filter(10, [](std::size_t k) { return k % 3 == 0; }),
            (std::vector<std::uint32_t>{0, 3, 6, 9}));
}

// parallel_select (the growing fragments' pairs and slots): dense hits in no pattern, the same list
// as a serial scan for any thread count, also when the kept parts are left over from a longer or
// denser scan.
TEST(BreakageParallelFilter, SelectGivesTheSerialListWithPartsKeptBetweenCalls) {
  Rng rng(11);
  std::vector<std::vector<std::uint32_t>> parts;
  std::vector<std::uint32_t> out;
  const int saved = omp_get_max_threads();
  for (const std::size_t n : {std::size_t{200003}, std::size_t{100001}, std::size_t{150000}})
    for (const double share : {0.9, 0.4}) {
      std::vector<std::uint8_t> hit(n);
      for (auto& h : hit) h = rng.uniform(0, 1) < share ? 1 : 0;
      std::vector<std::uint32_t> serial;
      for (std::size_t k = 0; k < n; ++k)
        if (hit[k]) serial.push_back(static_cast<std::uint32_t>(k));
      for (int threads : {1, 2, 3}) {
        omp_set_num_threads(threads);
        breakage::parallel_select(
            n, [&](std::size_t k) { return hit[k] != 0; }, out, parts);
        EXPECT_EQ(out, serial) << n << " slots, " << threads << " threads";
      }
    }
  omp_set_num_threads(saved);
  breakage::parallel_select(
      10, [](std::size_t k) { return k % 3 == 0; }, out, parts);
  EXPECT_EQ(out, (std::vector<std::uint32_t>{0, 3, 6, 9}));
}
