// Pages made resident before they are written (core/memory.hpp): prefault() populates exactly the
// whole pages inside its range and changes no byte; make_resident() keeps a vector's elements and
// grows it as push_back would. Residency is read back from the kernel (mincore).
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <numeric>
#include <vector>

#include "comminute/core/memory.hpp"

using namespace comminute;

namespace {

const std::size_t kPage = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));

// Fresh anonymous pages: none resident until touched.
struct FreshPages {
  explicit FreshPages(std::size_t n) : size(n * kPage) {
    void* p = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    base = p == MAP_FAILED ? nullptr : static_cast<unsigned char*>(p);
  }
  ~FreshPages() {
    if (base) ::munmap(base, size);
  }
  std::vector<bool> resident() const {
    std::vector<unsigned char> v(size / kPage);
    EXPECT_EQ(::mincore(base, size, v.data()), 0);
    std::vector<bool> r;
    for (unsigned char c : v) r.push_back((c & 1) != 0);
    return r;
  }
  std::size_t size;
  unsigned char* base = nullptr;
};

// Whether this kernel populates pages on request (Linux 5.14 and later).
bool kernel_populates() {
  FreshPages probe(1);
  return probe.base && ::madvise(probe.base, kPage, MADV_POPULATE_WRITE) == 0;
}

}  // namespace

TEST(Prefault, PopulatesTheWholePagesInsideTheRangeOnly) {
  if (!kernel_populates()) GTEST_SKIP() << "this kernel has no MADV_POPULATE_WRITE";
  FreshPages m(8);
  ASSERT_NE(m.base, nullptr);
  for (const bool r : m.resident()) ASSERT_FALSE(r);  // nothing touched yet
  // from the middle of page 1 to the middle of page 6: pages 2..5 lie wholly inside
  prefault(m.base + kPage + kPage / 2, 5 * kPage);
  const std::vector<bool> expected{false, false, true, true, true, true, false, false};
  EXPECT_EQ(m.resident(), expected);
  for (std::size_t b = 0; b < m.size; ++b) ASSERT_EQ(m.base[b], 0) << "byte " << b;
}

TEST(Prefault, ChangesNoByteOfPagesAlreadyWritten) {
  FreshPages m(4);
  ASSERT_NE(m.base, nullptr);
  for (std::size_t b = 0; b < 2 * kPage; ++b) m.base[b] = static_cast<unsigned char>(b * 7 + 3);
  prefault(m.base, m.size);
  for (std::size_t b = 0; b < 2 * kPage; ++b)
    ASSERT_EQ(m.base[b], static_cast<unsigned char>(b * 7 + 3)) << "byte " << b;
  for (std::size_t b = 2 * kPage; b < m.size; ++b) ASSERT_EQ(m.base[b], 0) << "byte " << b;
}

TEST(Prefault, LessThanAPageIsLeftAlone) {
  FreshPages m(2);
  ASSERT_NE(m.base, nullptr);
  prefault(m.base + 1, kPage);  // no whole page inside
  prefault(m.base, 0);
  EXPECT_EQ(m.resident(), (std::vector<bool>{false, false}));
}

TEST(MakeResident, KeepsTheElementsAndGrowsAsPushBackDoes) {
  std::vector<std::uint64_t> v(1000);
  std::iota(v.begin(), v.end(), 17u);
  v.shrink_to_fit();
  const std::size_t c = v.capacity();
  make_resident(v, c + 1);  // just over: doubled, as push_back grows it
  EXPECT_EQ(v.capacity(), 2 * c);
  make_resident(v, 10 * c);  // far over: exactly what is asked
  EXPECT_EQ(v.capacity(), 10 * c);
  ASSERT_EQ(v.size(), 1000u);
  for (std::size_t k = 0; k < v.size(); ++k) ASSERT_EQ(v[k], 17u + k);
  const std::uint64_t* data = v.data();
  make_resident(v, 5 * c);  // room enough: the same block
  EXPECT_EQ(v.data(), data);
  EXPECT_EQ(v.capacity(), 10 * c);
}

TEST(MakeResident, MakesTheNewElementsPagesResident) {
  if (!kernel_populates()) GTEST_SKIP() << "this kernel has no MADV_POPULATE_WRITE";
  // 64 MiB: a block of its own pages (mmap), none touched after reserve
  std::vector<double> v;
  v.reserve((64u << 20) / sizeof(double));
  v.resize(10);
  const std::size_t n = v.capacity() / 2;
  make_resident(v, n);
  const auto first = (reinterpret_cast<std::uintptr_t>(v.data()) + kPage - 1) & ~(kPage - 1);
  const auto last = reinterpret_cast<std::uintptr_t>(v.data() + n) & ~(kPage - 1);
  std::vector<unsigned char> in((last - first) / kPage);
  ASSERT_EQ(::mincore(reinterpret_cast<void*>(first), last - first, in.data()), 0);
  for (std::size_t k = 0; k < in.size(); ++k) ASSERT_TRUE(in[k] & 1) << "page " << k;
  // beyond the n elements: still untouched
  const auto end = reinterpret_cast<std::uintptr_t>(v.data() + v.capacity()) & ~(kPage - 1);
  const std::uintptr_t tail = last + kPage;
  ASSERT_LT(tail, end);
  std::vector<unsigned char> out((end - tail) / kPage);
  ASSERT_EQ(::mincore(reinterpret_cast<void*>(tail), end - tail, out.data()), 0);
  for (std::size_t k = 0; k < out.size(); ++k) ASSERT_FALSE(out[k] & 1) << "page " << k;
}
