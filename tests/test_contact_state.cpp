// The engine's per-contact state store: slots declared by the sub-models, carried with their
// swap rules when the neighbour list is rebuilt, gathered on in-place updates, checkpointed.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "comminute/contact/contact_state.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/engine/contact_pipeline.hpp"

using namespace comminute;

namespace {
// A store with a displacement-like slot (negates on swap) and a magnitude (kept), 4 contacts
// holding recognisable values.
struct Filled {
  ContactStateStore s;
  SlotId spring, overlap;
  Filled() {
    spring = s.declare_vec3("spring", SwapRule::negate);
    overlap = s.declare_f32("overlap", SwapRule::keep);
    s.carry({}, {}, {}, 4);
    for (std::size_t k = 0; k < 4; ++k) {
      s.at(k).vec3(spring) = {1.0 + static_cast<double>(k), 2.0, 3.0};
      s.at(k).f32(overlap) = 0.5f + static_cast<float>(k);
      s.active[k] = 1;
    }
  }
};

// A store with a spring (negated on swap) and a stiffness (kept) and room for 54 contacts (later
// lists of up to 54 are carried or gathered in place), holding 40 active contacts whose values
// name them: contact k has spring_of(k) and stiffness 100 + k.
struct Forty {
  static constexpr std::size_t n = 40;
  ContactStateStore s;
  SlotId spring, stiff;
  static Vec3 spring_of(double k) { return {1.0 + k, -0.5 * k, 7.0}; }
  // Contact k is fresh (old = none) or holds old contact `old`, its spring negated if reversed.
  void expect_holds(std::size_t k, std::uint32_t old, bool reversed, int trial) const {
    if (old == ContactStateStore::none) {
      EXPECT_EQ(s.at(k).vec3(spring), Vec3{}) << trial << " " << k;
      EXPECT_EQ(s.at(k).f64(stiff), 0.0) << trial << " " << k;
      EXPECT_EQ(s.active[k], 0) << trial << " " << k;
      return;
    }
    const Vec3 v = spring_of(static_cast<double>(old));
    EXPECT_EQ(s.at(k).vec3(spring), reversed ? -v : v) << trial << " " << k;
    EXPECT_EQ(s.at(k).f64(stiff), 100.0 + static_cast<double>(old)) << trial << " " << k;
    EXPECT_EQ(s.active[k], 1) << trial << " " << k;
  }
  Forty() {
    spring = s.declare_vec3("spring", SwapRule::negate);
    stiff = s.declare_f64("stiffness", SwapRule::keep);
    s.carry({}, {}, {}, 48);  // reserves 48 + 48 / 8 = 54
    s.carry({}, {}, {}, n);
    for (std::size_t k = 0; k < n; ++k) {
      s.at(k).vec3(spring) = spring_of(static_cast<double>(k));
      s.at(k).f64(stiff) = 100.0 + static_cast<double>(k);
      s.active[k] = 1;
    }
  }
};
}  // namespace

TEST(ContactState, CarryAppliesEachSlotsSwapRule) {
  Filled f;
  // old 2 -> new 0 (listed the other way round), old 3 -> new 4; the rest is new
  f.s.carry({2, 3}, {0, 4}, {1, 0}, 6);
  ASSERT_EQ(f.s.size(), 6u);
  EXPECT_EQ(f.s.at(0).vec3(f.spring), (Vec3{-3.0, -2.0, -3.0}));  // negated: i and j swapped
  EXPECT_EQ(f.s.at(0).f32(f.overlap), 2.5f);                      // a magnitude is kept
  EXPECT_EQ(f.s.at(4).vec3(f.spring), (Vec3{4.0, 2.0, 3.0}));
  for (std::size_t k : {1, 2, 3, 5}) {
    EXPECT_EQ(f.s.at(k).vec3(f.spring), Vec3{}) << k;
    EXPECT_EQ(f.s.at(k).f32(f.overlap), 0.0f) << k;
    EXPECT_EQ(f.s.active[k], 0) << k;
  }
  EXPECT_EQ(f.s.active[0] + f.s.active[4], 2);
}

// The neighbour list's carries (rising sources) run in place along chains when the columns have
// room: swaps, cycles, chains, a shorter and a longer list, both directions of listing. Each must
// give exactly what the copying carry gives: new contact to[e] holds old from[e] (negated for the
// spring when reversed), every other contact is fresh. Exact comparisons: values are only moved.
TEST(ContactState, CarryInPlaceEqualsTheCopyForAnyPlan) {
  std::mt19937 gen(12345);
  for (int trial = 0; trial < 200; ++trial) {
    Forty f;
    const std::size_t n_old = Forty::n;
    const std::size_t n_new = 30 + gen() % 25;  // 30..54: shorter and longer lists
    std::vector<std::uint32_t> sources(n_old), targets(n_new);
    std::iota(sources.begin(), sources.end(), 0u);
    std::iota(targets.begin(), targets.end(), 0u);
    std::shuffle(sources.begin(), sources.end(), gen);
    std::shuffle(targets.begin(), targets.end(), gen);
    const std::size_t m = gen() % 31;  // up to 30 carried
    std::vector<std::uint32_t> from(sources.begin(), sources.begin() + m);
    std::sort(from.begin(), from.end());  // rising, as the neighbour list plans them
    std::vector<std::uint32_t> to(targets.begin(), targets.begin() + m);
    std::vector<std::uint8_t> reversed(m);
    for (auto& r : reversed) r = static_cast<std::uint8_t>(gen() % 2);
    f.s.carry(from, to, reversed, n_new);
    ASSERT_EQ(f.s.size(), n_new);
    std::vector<int> carried_from(n_new, -1);
    for (std::size_t e = 0; e < m; ++e) carried_from[to[e]] = static_cast<int>(e);
    for (std::size_t k = 0; k < n_new; ++k) {
      const int e = carried_from[k];
      const auto ue = static_cast<std::size_t>(e);
      f.expect_holds(k, e < 0 ? ContactStateStore::none : from[ue], e >= 0 && reversed[ue] != 0,
                     trial);
    }
  }
}

// A neighbour list's carry at the size of a dense bed (tens of thousands of contacts) runs on all
// threads: the chains of in-place moves are followed from their starts in parallel, closed cycles
// after. Plans like a rebuild's (slots drift a little, local reorderings make chains and cycles;
// a longer and a shorter list) must give exactly the copy's result on one and on two threads.
TEST(ContactState, CarryOnAllThreadsEqualsTheCopyForLargePlans) {
  const int saved = omp_get_max_threads();
  std::mt19937 gen(777);
  for (int trial = 0; trial < 4; ++trial) {
    const std::size_t n_old = 60000, n_new = trial % 2 == 0 ? 64000 : 56000;
    ContactStateStore s;
    const SlotId spring = s.declare_vec3("spring", SwapRule::negate);
    const SlotId stiff = s.declare_f64("stiffness", SwapRule::keep);
    s.carry({}, {}, {}, 64000);  // room for the longer list: the in-place path
    s.carry({}, {}, {}, n_old);
    auto spring_of = [](double k) { return Vec3{1.0 + k, -0.5 * k, 7.0}; };
    for (std::size_t k = 0; k < n_old; ++k) {
      s.at(k).vec3(spring) = spring_of(static_cast<double>(k));
      s.at(k).f64(stiff) = 100.0 + static_cast<double>(k);
      s.active[k] = 1;
    }
    // half the old contacts carried, in rising order, to the same share of the new slots in the
    // same order, then shuffled within windows of 8 (chains and cycles of moves)
    std::vector<std::uint32_t> from, to;
    for (std::uint32_t k = 0; k < n_old; ++k)
      if (gen() % 2 == 0) from.push_back(k);
    std::vector<std::uint32_t> slots(n_new);
    std::iota(slots.begin(), slots.end(), 0u);
    std::shuffle(slots.begin(), slots.end(), gen);
    to.assign(slots.begin(), slots.begin() + static_cast<std::ptrdiff_t>(from.size()));
    std::sort(to.begin(), to.end());
    for (std::size_t w = 0; w + 8 <= to.size(); w += 8)
      std::shuffle(to.begin() + static_cast<std::ptrdiff_t>(w),
                   to.begin() + static_cast<std::ptrdiff_t>(w + 8), gen);
    ASSERT_GE(from.size(), 16384u);  // large enough to run on all threads
    std::vector<std::uint8_t> reversed(from.size());
    for (auto& r : reversed) r = static_cast<std::uint8_t>(gen() % 2);
    omp_set_num_threads(1 + trial / 2);
    s.carry(from, to, reversed, n_new);
    omp_set_num_threads(saved);
    ASSERT_EQ(s.size(), n_new);
    std::vector<std::int64_t> carried_from(n_new, -1);
    for (std::size_t e = 0; e < from.size(); ++e)
      carried_from[to[e]] = static_cast<std::int64_t>(e);
    std::size_t wrong = 0;
    for (std::size_t k = 0; k < n_new; ++k) {
      const std::int64_t e = carried_from[k];
      if (e < 0) {
        wrong += s.at(k).vec3(spring) != Vec3{} || s.at(k).f64(stiff) != 0.0 || s.active[k] != 0;
        continue;
      }
      const auto ue = static_cast<std::size_t>(e);
      const Vec3 v = spring_of(static_cast<double>(from[ue]));
      wrong += s.at(k).vec3(spring) != (reversed[ue] ? -v : v) ||
               s.at(k).f64(stiff) != 100.0 + static_cast<double>(from[ue]) || s.active[k] != 1;
    }
    EXPECT_EQ(wrong, 0u) << "trial " << trial;
  }
}

TEST(ContactState, GatherKeepsOrderAndStartsNewContactsFresh) {
  Filled f;
  f.s.gather({1, 3, ContactStateStore::none});
  ASSERT_EQ(f.s.size(), 3u);
  EXPECT_EQ(f.s.at(0).vec3(f.spring).x, 2.0);
  EXPECT_EQ(f.s.at(1).vec3(f.spring).x, 4.0);
  EXPECT_EQ(f.s.at(2).vec3(f.spring), Vec3{});
  EXPECT_EQ(f.s.active[2], 0);
  f.s.clear(0);
  EXPECT_EQ(f.s.at(0).f32(f.overlap), 0.0f);
  EXPECT_EQ(f.s.active[0], 0);
}

// Gathers of both kinds: forward plans (each carried contact k takes old from[k] >= k: breakage's
// in-place updates, pairs of removed particles dropped and new ones appended or interleaved), run
// in place, and any other order (a wall-candidate rebuild), copied. Each must give exactly contact
// k = old from[k], or fresh for none. A forward plan within the capacity must not move the arrays
// (no second column is allocated: the memory the in-place path exists for).
TEST(ContactState, GatherInPlaceEqualsTheCopyForAnyPlan) {
  constexpr std::uint32_t none = ContactStateStore::none;
  std::mt19937 gen(777);
  for (int trial = 0; trial < 300; ++trial) {
    Forty f;
    ContactStateStore& s = f.s;
    const std::size_t n_old = Forty::n;
    const bool forward = trial % 2 == 0;
    std::vector<std::uint32_t> from;
    if (forward) {
      // old contacts kept in order (about 3 in 4), a fresh one now and then where it keeps
      // from[k] >= k, and fresh ones appended, up to 54 in all
      for (std::uint32_t o = 0; o < n_old; ++o) {
        if (gen() % 4 == 0) continue;
        if (from.size() < o && gen() % 5 == 0) from.push_back(none);
        from.push_back(o);
      }
      const std::size_t extra = gen() % (55 - from.size());
      from.insert(from.end(), extra, none);
    } else {
      const std::size_t n_new = 1 + gen() % 54;
      for (std::size_t k = 0; k < n_new; ++k)
        from.push_back(gen() % 4 == 0 ? none : static_cast<std::uint32_t>(gen() % n_old));
    }
    const Vec3* before = s.slots().vec3[f.spring];
    s.gather(from);
    ASSERT_EQ(s.size(), from.size());
    if (forward) {
      EXPECT_EQ(s.slots().vec3[f.spring], before) << trial << ": the column moved";
    }
    for (std::size_t k = 0; k < from.size(); ++k) f.expect_holds(k, from[k], false, trial);
  }
}

TEST(ContactState, ScratchCopiesOneContactAndLeavesTheStoreAlone) {
  Filled f;
  const ContactScratch copy(f.s, 1);
  copy.ref().vec3(f.spring) = {9, 9, 9};
  EXPECT_EQ(f.s.at(1).vec3(f.spring), (Vec3{2.0, 2.0, 3.0}));
  EXPECT_EQ(ContactScratch{}.ref().f32(f.overlap), 0.0f);
  // a scratch kept for many contacts is fresh again after clear() in every slot of the layout
  ContactScratch kept;
  kept.ref().vec3(f.spring) = {9, 9, 9};
  kept.ref().f32(f.overlap) = 5.0f;
  kept.clear(f.s);
  EXPECT_EQ(kept.ref().vec3(f.spring), Vec3{});
  EXPECT_EQ(kept.ref().f32(f.overlap), 0.0f);
}

TEST(ContactState, CheckpointRoundTripsAndRefusesAnotherListSize) {
  Filled f;
  Archive a;
  f.s.save(a, "pairs/state/");
  ContactStateStore back = f.s.same_layout();
  back.load(a, "pairs/state/", 4);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(back.at(k).vec3(f.spring), f.s.at(k).vec3(f.spring));
    EXPECT_EQ(back.at(k).f32(f.overlap), f.s.at(k).f32(f.overlap));
  }
  ContactStateStore wrong = f.s.same_layout();
  EXPECT_THROW(wrong.load(a, "pairs/state/", 5), Error);
}

TEST(ContactState, ADeclarationClashIsRefused) {
  ContactStateStore s;
  const SlotId a = s.declare_vec3("spring", SwapRule::negate);
  EXPECT_EQ(s.declare_vec3("spring", SwapRule::negate), a);  // the same slot, asked twice
  EXPECT_THROW(s.declare_vec3("spring", SwapRule::keep), Error);
  EXPECT_THROW(s.declare_f32("spring", SwapRule::negate), Error);
}

namespace {
// A module asking for the loading record (as breakage does) and, optionally, a slot of its own
// (as a bond law will: a stored bond force).
class AsksForState final : public Module {
 public:
  explicit AsksForState(bool own_slot) : own_slot_(own_slot) {}
  std::string name() const override { return "asks"; }
  void declare_contact_state(ContactPipeline& c) override {
    c.require_loading_record();
    if (own_slot_) c.module_layout().declare_vec3("bond_force", SwapRule::negate);
  }

 private:
  bool own_slot_;
};
}  // namespace

TEST(ContactState, BytesPerContactFollowTheSubModels) {
  // Hertz–Mindlin keeps its tangential spring (24 B), the stiffness of the last step (8 B, for
  // the rescaling on unloading) and the active flag (1 B); EPSD rolling adds
  // its spring (24 B); breakage's loading record three floats (12 B); a module's own Vec3 slot
  // 24 B. The history struct these replace held a fixed 64 B + 1 B flag in every contact.
  const CaseFile none = CaseFile::parse("");
  auto law = ContactLawRegistry::create("hertz_mindlin", none.root());
  auto rolling = RollingResistanceRegistry::create("epsd", none.root());
  std::vector<std::unique_ptr<Module>> no_modules, breakage, bonds;
  breakage.push_back(std::make_unique<AsksForState>(false));
  bonds.push_back(std::make_unique<AsksForState>(true));
  ContactPipeline plain;
  EXPECT_EQ(plain.assemble(*law, nullptr, nullptr, no_modules).bytes_per_contact(), 33u);
  EXPECT_EQ(plain.loading(), nullptr);
  ContactPipeline with_rolling;
  EXPECT_EQ(with_rolling.assemble(*law, rolling.get(), nullptr, no_modules).bytes_per_contact(),
            57u);
  ContactPipeline with_breakage;
  EXPECT_EQ(with_breakage.assemble(*law, nullptr, nullptr, breakage).bytes_per_contact(), 45u);
  EXPECT_NE(with_breakage.loading(), nullptr);
  EXPECT_EQ(with_breakage.layout().slot_names(),
            (std::vector<std::string>{"tangential_spring", "loading_max_overlap", "loading_work",
                                      "loading_normal_force", "tangential_stiffness"}));
  ContactPipeline with_bonds;
  EXPECT_EQ(with_bonds.assemble(*law, nullptr, nullptr, bonds).bytes_per_contact(), 69u);
  // slots are declared while the model is assembled, not after
  EXPECT_THROW(with_bonds.module_layout(), Error);
}
