// In-place update of the neighbour list after breakage (compaction, then fragments appended): the
// appended particles' rows are searched on all threads, yet the list must be exactly the one of
// a serial insertion one by one: the kept pairs remapped in their old order, then for each
// appended slot s in turn the partners j < s within r_s + r_j + skin, ascending. Checked pair by
// pair (order included, which the contact-state carry and the force sums depend on) on one and
// on two threads, on a polydisperse bed (large particles in their own grid).
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "comminute/core/rng.hpp"
#include "comminute/neighbor/neighbor_list.hpp"

using namespace comminute;

namespace {

struct Lists {
  std::vector<std::uint32_t> first, second, kept_from;
};

ParticleStore bed(Rng& rng, int n, double box) {
  ParticleStore p;
  for (int k = 0; k < n; ++k) {
    ParticleInit init;
    init.radius = k % 40 == 0 ? 0.004 : 0.0005 * rng.uniform(0.5, 1.0);
    init.x = {rng.uniform(0, box), rng.uniform(0, box), rng.uniform(0, box)};
    init.density = 1000;
    p.add(init);
  }
  return p;
}

constexpr double skin = 0.0002, box = 0.04;

// A bed of n spheres and its list, built with `threads` threads (left set: the caller restores
// `saved`); `rng` goes on drawing the changes.
struct Built {
  Rng rng;
  ParticleStore p;
  NeighborList nl;
  int saved;
};
Built built_bed(std::uint64_t seed, int n, int threads) {
  Built b{Rng(seed), {}, {}, omp_get_max_threads()};
  b.p = bed(b.rng, n, box);
  omp_set_num_threads(threads);
  b.nl.build(b.p, skin);
  return b;
}

// Two rounds of removal and insertion with `threads` threads; the lists after each round.
std::vector<Lists> updated(int threads, std::vector<Lists>* expected) {
  auto [rng, p, nl, saved] = built_bed(17, 4000, threads);
  std::vector<Lists> out;
  for (int round = 0; round < 2; ++round) {
    for (std::size_t i = 0; i < p.size(); ++i)
      if (rng.uniform() < 0.2) p.flags[i] |= pflag::remove;
    p.compact();
    const std::vector<std::uint32_t> to_new = nl.slots_after_removal(p);
    EXPECT_FALSE(to_new.empty());
    const std::size_t n_kept = p.size();
    for (int k = 0; k < 400; ++k) {  // fragments, some larger than any kept particle
      ParticleInit init;
      init.radius = k % 100 == 0 ? 0.005 : 0.0004 * rng.uniform(0.3, 1.0);
      init.x = {rng.uniform(0, box), rng.uniform(0, box), rng.uniform(0, box)};
      init.density = 1000;
      p.add(init);
    }
    if (expected) {  // the serial definition, from the list before the update
      Lists e;
      for (std::size_t k = 0; k < nl.size(); ++k) {
        const std::uint32_t a = to_new[nl.first[k]], b = to_new[nl.second[k]];
        if (a == NeighborList::none || b == NeighborList::none) continue;
        e.first.push_back(a);
        e.second.push_back(b);
        e.kept_from.push_back(static_cast<std::uint32_t>(k));
      }
      for (std::size_t s = n_kept; s < p.size(); ++s)
        for (std::size_t j = 0; j < s; ++j) {
          const double cut = p.radius[s] + p.radius[j] + skin;
          if (norm2(p.x[s] - p.x[j]) < cut * cut) {
            e.first.push_back(static_cast<std::uint32_t>(s));
            e.second.push_back(static_cast<std::uint32_t>(j));
            e.kept_from.push_back(NeighborList::none);
          }
        }
      expected->push_back(std::move(e));
    }
    nl.update_in_place(p, to_new, p.x, p.radius);
    out.push_back({nl.first, nl.second, nl.kept_from()});
  }
  omp_set_num_threads(saved);
  return out;
}

}  // namespace

TEST(InPlaceRows, EqualTheSerialInsertionOnOneAndTwoThreads) {
  std::vector<Lists> expected;
  const auto one = updated(1, &expected);
  const auto two = updated(2, nullptr);
  ASSERT_EQ(expected.size(), 2u);
  for (std::size_t r = 0; r < expected.size(); ++r) {
    // the appended rows hold many pairs (else the threaded search would go untested)
    EXPECT_GT(
        std::count(expected[r].kept_from.begin(), expected[r].kept_from.end(), NeighborList::none),
        100);
    EXPECT_EQ(one[r].first, expected[r].first) << "round " << r;
    EXPECT_EQ(one[r].second, expected[r].second) << "round " << r;
    EXPECT_EQ(one[r].kept_from, expected[r].kept_from) << "round " << r;
    EXPECT_EQ(two[r].first, expected[r].first) << "round " << r;
    EXPECT_EQ(two[r].second, expected[r].second) << "round " << r;
    EXPECT_EQ(two[r].kept_from, expected[r].kept_from) << "round " << r;
  }
}

namespace {

struct Renewal {
  std::vector<std::uint32_t> first, second, fresh, rows;
  std::vector<std::uint64_t> ids;
};

// One round of renewal with `threads` threads on a bed of 16000: a tenth of the slots get a new,
// smaller particle inside the old one's sphere (as a fragment in its parent's slot), 400 particles
// are appended.
// The reach spheres passed are the build's, but the renewed slots' are the spheres about their new
// centres inside the old ones (as PairTracker::replace gives them).
Renewal renewed(int threads, Renewal* expected) {
  auto [rng, p, nl, saved] = built_bed(23, 16000, threads);
  std::vector<Vec3> x_build = p.x;
  std::vector<double> r_build = p.radius;
  const std::size_t n_old = p.size();
  std::vector<std::uint8_t> is_renewed(n_old, 0);
  for (std::size_t s = 0; s < n_old; ++s) {
    if (rng.uniform() >= 0.1) continue;
    is_renewed[s] = 1;
    ParticleInit init;
    init.radius = 0.5 * p.radius[s];
    init.x = p.x[s] + Vec3{0.4 * p.radius[s], 0, 0};
    init.density = 1000;
    p.renew(s, init, 1e-6);
    r_build[s] -= norm(p.x[s] - x_build[s]);
    x_build[s] = p.x[s];
  }
  for (int k = 0; k < 400; ++k) {
    ParticleInit init;
    init.radius = k % 100 == 0 ? 0.005 : 0.0004 * rng.uniform(0.3, 1.0);
    init.x = {rng.uniform(0, box), rng.uniform(0, box), rng.uniform(0, box)};
    init.density = 1000;
    p.add(init);
    x_build.push_back(init.x);
    r_build.push_back(init.radius);
  }
  if (expected) {  // the definition, from the list before the update
    Renewal e{nl.first, nl.second, {}, {}, p.id};
    for (std::size_t k = 0; k < nl.size(); ++k)
      if (is_renewed[nl.first[k]] || is_renewed[nl.second[k]])
        e.fresh.push_back(static_cast<std::uint32_t>(k));
    for (std::size_t s = n_old; s < p.size(); ++s)
      for (std::size_t j = 0; j < s; ++j) {
        const double cut = r_build[s] + r_build[j] + skin;
        if (norm2(x_build[s] - x_build[j]) < cut * cut) {
          e.first.push_back(static_cast<std::uint32_t>(s));
          e.second.push_back(static_cast<std::uint32_t>(j));
        }
      }
    for (std::size_t i = 0; i <= p.size(); ++i)  // first pair whose owner is >= i
      e.rows.push_back(static_cast<std::uint32_t>(
          std::lower_bound(e.first.begin(), e.first.end(), static_cast<std::uint32_t>(i)) -
          e.first.begin()));
    *expected = std::move(e);
  }
  Renewal out;
  out.fresh = nl.pairs_flagged(is_renewed);
  nl.renew_in_place(p, x_build, r_build);
  out.first = nl.first;
  out.second = nl.second;
  out.rows = nl.rows();
  out.ids = nl.ids_at_build();
  omp_set_num_threads(saved);
  return out;
}

}  // namespace

// Fragments in their parents' slots (NeighborList::renew_in_place): every pair stays where it is,
// the appended particles' rows follow as in a serial insertion (against the renewed slots' new
// reach spheres, which lie inside the old ones the index still holds), the pairs of the renewed
// slots are named in pair order (their contact state starts afresh), the rows and ids follow the
// store. The same on one and on two threads.
TEST(InPlaceRows, RenewedSlotsKeepTheirPairsOnOneAndTwoThreads) {
  Renewal expected;
  const Renewal one = renewed(1, &expected);
  const Renewal two = renewed(2, nullptr);
  // a list long enough to be scanned on all threads (16384 pairs or more), renewed pairs in every
  // thread's share of it, and appended rows to search
  EXPECT_GT(expected.first.size(), 20000u);
  EXPECT_GT(expected.fresh.size(), 100u);
  EXPECT_GT(expected.fresh.back(), 3 * expected.fresh.front());
  EXPECT_GT(std::count_if(expected.first.begin(), expected.first.end(),
                          [](std::uint32_t s) { return s >= 16000; }),
            100);
  for (const Renewal* r : {&one, &two}) {
    EXPECT_EQ(r->first, expected.first);
    EXPECT_EQ(r->second, expected.second);
    EXPECT_EQ(r->fresh, expected.fresh);
    EXPECT_EQ(r->rows, expected.rows);
    EXPECT_EQ(r->ids, expected.ids);
  }
}
