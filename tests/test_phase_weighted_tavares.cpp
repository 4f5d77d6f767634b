// The phase-weighted option of the Tavares criterion (issue 12 point 4; this project's extension,
// docs/models.md eq. C2b): E_eff = w E, w = sum_k C_k f_rel,k, i.e. the particle's fracture-energy
// distribution has E50 and E_max scaled by w.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "comminute/breakage/criteria/tavares.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"

using namespace comminute;
using namespace comminute::breakage;

namespace {

TavaresParameters parameters() {
  TavaresParameters tp;
  tp.size_effect = {100.0, 0.010, 1.0, 0.755541};
  tp.sigma = 0.8;
  tp.emax_ratio = 5.0;
  return tp;
}

// n particles of diameter d given their strengths by criterion c from one seed.
ParticleStore particles(std::size_t n, BreakageCriterion& c, double d) {
  ParticleStore p;
  c.attach(p);
  Rng rng(2026, rng_stream::breakage);
  for (std::size_t i = 0; i < n; ++i) {
    p.add({{}, {}, {}, d / 2, 2700.0, 0, 0});
    c.initialize(p, i, d, rng);
  }
  return p;
}

}  // namespace

// A texture with one phase gives every particle C_0 = 1 (the texture module writes the voxel
// fraction counts/total = 1 exactly), so w = 1 * f_rel,0 = 1: the weighted criterion must then be
// plain tavares bit for bit, through draws, breakage decisions and damage.
TEST(PhaseWeightedTavares, OnePhaseTextureEqualsPlainTavares) {
  Tavares plain(parameters());
  TavaresParameters tw = parameters();
  tw.phases = PhaseWeights({1.0});
  Tavares weighted(tw);
  const double d = 0.012;
  ParticleStore a = particles(200, plain, d), b = particles(200, weighted, d);
  ASSERT_TRUE(b.has_field("composition.0"));
  for (std::size_t i = 0; i < b.size(); ++i) b.field(b.field_index("composition.0"))[i] = 1.0;
  const double e50 = plain.median_fracture_energy(d);
  EXPECT_EQ(weighted.median_fracture_energy(d), e50);
  for (double ratio : {0.3, 0.7, 1.0, 1.6}) {
    const StressingEvent ev{ratio * e50, 0.0};
    EXPECT_EQ(weighted.probability(d, ev), plain.probability(d, ev));
    EXPECT_EQ(weighted.t10_median_energy(d, ev.specific_energy, fracture::E50bRule::breaking),
              plain.t10_median_energy(d, ev.specific_energy, fracture::E50bRule::breaking));
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(weighted.breaks(b, i, d, ev), plain.breaks(a, i, d, ev));
      if (!plain.breaks(a, i, d, ev)) {  // repeated sub-critical events damage both alike
        plain.survive(a, i, d, ev);
        weighted.survive(b, i, d, ev);
      }
      ASSERT_EQ(weighted.strength(b, i, d), plain.strength(a, i, d)) << i;
      ASSERT_EQ(weighted.damage(b, i), plain.damage(a, i)) << i;
    }
  }
}

// Binary composition C = (1 - 0.233, 0.233), f_rel = (1, f) for each f of the HPGR study: the
// particle's median E50 is E50(d) [(1 - C) + C f] and its strength is the same draw times that
// weight; a quarter of the particles tested statistically at the scaled median break as P says.
TEST(PhaseWeightedTavares, BinaryCompositionScalesTheMedian) {
  const double d = 0.02, c = 0.233;
  for (double f : {0.5, 1.0, 2.0, 4.0, 6.0, 13.21}) {
    Tavares plain(parameters());
    TavaresParameters tw = parameters();
    tw.phases = PhaseWeights({1.0, f});
    Tavares weighted(tw);
    ParticleStore a = particles(4000, plain, d), b = particles(4000, weighted, d);
    for (std::size_t i = 0; i < b.size(); ++i) {
      b.field(b.field_index("composition.0"))[i] = 1 - c;
      b.field(b.field_index("composition.1"))[i] = c;
    }
    const double w = (1 - c) * 1.0 + c * f;  // the binary formula
    const double e50 = plain.median_fracture_energy(d);
    // w is summed in the same order in the criterion; one product more: a few ulp (2.2e-16)
    EXPECT_NEAR(weighted.distribution(b, 0, d).e50(), e50 * w, 1e-15 * e50 * w) << "f " << f;
    for (std::size_t i = 0; i < b.size(); ++i)
      ASSERT_NEAR(weighted.strength(b, i, d), plain.strength(a, i, d) * w,
                  1e-15 * plain.strength(a, i, d) * w);
    // At the particle's own true median (E50 E_max/(E_max + E50), scaled) half of them break:
    // binomial 3-sigma band of 4000 draws (0.024).
    const double median = weighted.distribution(b, 0, d).median();
    EXPECT_NEAR(median, plain.distribution(d).median() * w, 1e-12 * median);
    int broken = 0;
    for (std::size_t i = 0; i < b.size(); ++i)
      broken += weighted.breaks(b, i, d, {median, 0}) ? 1 : 0;
    EXPECT_NEAR(broken / 4000.0, 0.5, 3 * std::sqrt(0.25 / 4000.0)) << "f " << f;
  }
}

// The option is read from the case table; without it tavares has no phases; an empty list is an
// input error.
TEST(PhaseWeightedTavares, ReadFromTheCaseTable) {
  Material m{"rock", 2700, 70e9, 0.25};
  const CaseFile with =
      CaseFile::parse("e_inf = 100\nsigma = 0.8\nrelative_strength = [1.0, 4.0]\n");
  auto c = CriterionRegistry::create("tavares", with.root(), m);
  ASSERT_NE(c->relative_strength(), nullptr);
  EXPECT_EQ(*c->relative_strength(), (std::vector<double>{1.0, 4.0}));
  const CaseFile without = CaseFile::parse("e_inf = 100\nsigma = 0.8\n");
  EXPECT_EQ(CriterionRegistry::create("tavares", without.root(), m)->relative_strength(), nullptr);
  const CaseFile empty = CaseFile::parse("e_inf = 100\nsigma = 0.8\nrelative_strength = []\n");
  EXPECT_THROW(CriterionRegistry::create("tavares", empty.root(), m), InputError);
}
