// Breakage criteria: the model-level tests 1 (breakage probability) and 4 (damage accumulation)
// of issue 3, the criteria registry. The shared physics (fracture-energy distribution, size
// effect, energy partition, damage) is tested in test_fracture.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <tuple>

#include "comminute/breakage/criteria/composition_peak_force.hpp"
#include "comminute/breakage/criteria/peak_force.hpp"
#include "comminute/breakage/criteria/tavares.hpp"
#include "comminute/breakage/criteria/vogel_peukert.hpp"
#include "comminute/breakage/progeny/progeny_model.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"

using namespace comminute;
using namespace comminute::breakage;

namespace {

ParticleStore identical_particles(std::size_t n, BreakageCriterion& c, double d, Rng& rng) {
  ParticleStore p;
  c.attach(p);
  for (std::size_t i = 0; i < n; ++i) {
    p.add({{}, {}, {}, d / 2, 2700.0, 0, 0});
    c.initialize(p, i, d, rng);
  }
  return p;
}
}  // namespace

// Issue 3, test 1: 1000 identical particles, each loaded once at E: the broken fraction lies in
// the binomial 3-sigma band around the model P(E), at three energies.
TEST(BreakageProbability, TavaresThousandParticlesWithinBinomialBand) {
  TavaresParameters tp;
  tp.size_effect = {100.0, 0.010, 1.0, 0.755541};
  tp.sigma = 0.8;
  tp.emax_ratio = 5.0;
  Tavares c(tp);
  const double d = 0.01;
  const double e50 = c.median_fracture_energy(d);
  Rng rng(2026, rng_stream::breakage);
  for (double ratio : {0.5, 1.0, 2.0}) {
    ParticleStore p = identical_particles(1000, c, d, rng);
    const StressingEvent ev{ratio * e50, 0.0};
    int broken = 0;
    for (std::size_t i = 0; i < p.size(); ++i) broken += c.breaks(p, i, d, ev) ? 1 : 0;
    const double pm = c.probability(d, ev);
    const double sd = std::sqrt(pm * (1 - pm) / 1000.0);
    EXPECT_NEAR(broken / 1000.0, pm, 3 * sd) << "E/E50 = " << ratio;
  }
}

TEST(BreakageProbability, VogelPeukertThousandParticlesWithinBinomialBand) {
  VogelPeukert c({3.6, 0.06});
  const double d = 0.002;
  // Hand-computed eq. C3: W = 50, 100, 200, 500 J/kg -> P = 0.1341, 0.3959, 0.7059, 0.9661.
  EXPECT_NEAR(c.probability(d, {50, 0}), 0.1341, 1e-4);
  EXPECT_NEAR(c.probability(d, {500, 0}), 0.9661, 1e-4);
  EXPECT_EQ(c.probability(d, {29, 0}), 0.0);
  Rng rng(7, rng_stream::breakage);
  for (double w : {50.0, 100.0, 200.0}) {
    ParticleStore p = identical_particles(1000, c, d, rng);
    int broken = 0;
    for (std::size_t i = 0; i < p.size(); ++i) broken += c.breaks(p, i, d, {w, 0}) ? 1 : 0;
    const double pm = c.probability(d, {w, 0});
    EXPECT_NEAR(broken / 1000.0, pm, 3 * std::sqrt(pm * (1 - pm) / 1000.0)) << "W = " << w;
  }
}

TEST(BreakageProbability, PeakForceRandomFactorWithinBinomialBand) {
  PeakForce c({2e7, 1.6, 0.0}, 0.4);
  const double d = 0.01;
  Rng rng(11, rng_stream::breakage);
  const double f50 = 2e7 * std::pow(d, 1.6);
  for (double ratio : {0.7, 1.0, 1.5}) {
    ParticleStore p = identical_particles(1000, c, d, rng);
    int broken = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      broken += c.breaks(p, i, d, {0, ratio * f50}) ? 1 : 0;
    const double pm = c.probability(d, {0, ratio * f50});
    EXPECT_NEAR(broken / 1000.0, pm, 3 * std::sqrt(pm * (1 - pm) / 1000.0)) << "F/F50 = " << ratio;
  }
}

TEST(PeakForce, CompositionWeightsTheCriticalForce) {
  // Binary case (Cleary & Sinnott 2015; docs/models.md eq. C2): F = F_CS (1 - C_t) + F_CS C_t
  // f_rel,t with f_rel = (1, 4).
  CompositionPeakForce c({1e6, 1.5, 2.0}, 0.0, {1.0, 4.0});
  ParticleStore p;
  c.attach(p);
  p.add({{}, {}, {}, 0.005, 2700.0, 0, 0});
  Rng rng(1);
  c.initialize(p, 0, 0.01, rng);
  const double fcs = 1e6 * std::pow(0.01, 1.5) + 2.0;
  EXPECT_DOUBLE_EQ(c.strength(p, 0, 0.01), fcs);
  p.field(p.field_index("composition.0"))[0] = 0.767;
  p.field(p.field_index("composition.1"))[0] = 0.233;
  EXPECT_NEAR(c.strength(p, 0, 0.01), fcs * (1 - 0.233) + fcs * 0.233 * 4.0, 1e-12 * fcs);
  EXPECT_FALSE(c.breaks(p, 0, 0.01, {0, 1.69 * fcs}));
  EXPECT_TRUE(c.breaks(p, 0, 0.01, {0, 1.70 * fcs}));
}

// Issue 3, test 4: repeated sub-critical impacts weaken a particle exactly as iterating the
// damage equation by hand predicts, and it breaks on the impact the iteration says it should.
TEST(DamageAccumulation, RepeatedImpactsFollowHandIteration) {
  TavaresParameters tp;
  tp.size_effect = {100.0, 0.0, 1.0, 1.0};
  tp.sigma = 0.5;
  tp.damage = {3.0, comminute::fracture::DamageForm::no_factor};  // the hand iteration below is the
                                                                  // no_factor form
  Tavares c(tp);
  ParticleStore p;
  c.attach(p);
  p.add({{}, {}, {}, 0.005, 2700.0, 0, 0});
  const std::size_t fe = p.field_index("tavares.fracture_energy");
  p.field(fe)[0] = 100.0;      // J/kg, set by hand
  const double impact = 40.0;  // J/kg each impact (r = 0.4 at first)
  // Hand iteration, written independently of the library: plain fixed point of
  // D = [2g/(2g - 5D + 5) r]^(2g/5), E <- E(1 - D), until e E_k >= E.
  double e = 100.0;
  int predicted = 0;
  for (int k = 1; k < 100; ++k) {
    if (impact >= e) {
      predicted = k;
      break;
    }
    double dmg = 0;
    for (int it = 0; it < 200000; ++it)
      dmg = std::pow(6.0 / (6.0 - 5.0 * dmg + 5.0) * impact / e, 1.2);
    e *= 1 - dmg;
  }
  ASSERT_GT(predicted, 2);  // several sub-critical impacts before breakage for this choice
  double hand = 100.0;
  for (int k = 1; k <= predicted; ++k) {
    const StressingEvent ev{impact, 0.0};
    if (k < predicted) {
      ASSERT_FALSE(c.breaks(p, 0, 0.01, ev)) << "impact " << k;
      c.survive(p, 0, 0.01, ev);
      double dmg = 0;
      for (int it = 0; it < 200000; ++it)
        dmg = std::pow(6.0 / (6.0 - 5.0 * dmg + 5.0) * impact / hand, 1.2);
      hand *= 1 - dmg;
      EXPECT_NEAR(p.field(fe)[0], hand, 1e-10 * hand) << "impact " << k;
      EXPECT_NEAR(c.damage(p, 0), 1 - hand / 100.0, 1e-12);
    } else {
      EXPECT_TRUE(c.breaks(p, 0, 0.01, ev)) << "predicted breakage at impact " << k;
    }
  }
}

TEST(Criteria, RegistryBuildsEachByName) {
  const CaseFile good = CaseFile::parse(
      "e_inf = 100\nsigma = 0.8\na = 1e6\nb = 1.5\nf_mat = 1.0\nrelative_strength = [1.0, 2.0]\n");
  const CaseTable s = good.root();
  Material m{"rock", 2700, 70e9, 0.25};
  for (const char* n : {"tavares", "peak_force", "composition_peak_force", "vogel_peukert"}) {
    auto c = CriterionRegistry::create(n, s, m);
    ASSERT_TRUE(c) << n;
    EXPECT_EQ(c->name(), n);
  }
  EXPECT_FALSE(CriterionRegistry::create("nope", s, m));
  const CaseFile bad = CaseFile::parse("e_inf = -1\nsigma = 0.8\n");
  EXPECT_THROW(CriterionRegistry::create("tavares", bad.root(), m), Error);
  // Applied basis against steel: E50 carries the partition e = 0.755541 (70 GPa ore, eq. F5).
  auto t = CriterionRegistry::create("tavares", s, m);
  EXPECT_NEAR(t->median_fracture_energy(1e9), 100 * 0.755541, 1e-4);
}

TEST(Criteria, RenamedKeysNameTheirNewKey) {
  Material m{"rock", 2700, 70e9, 0.25};
  for (const auto& [text, old_key, new_key] :
       {std::tuple{"e50_inf = 100\nsigma = 0.8\n", "e50_inf", "e_inf"},
        std::tuple{"e_inf = 100\nsigma = 0.8\nmax_ratio = 5\n", "max_ratio", "emax_ratio"},
        std::tuple{"e_inf = 100\nsigma = 0.8\ngamma = 3\n", "gamma", "damage_gamma"}}) {
    const CaseFile f = CaseFile::parse(text, "case.toml");
    try {
      CriterionRegistry::create("tavares", f.root(), m);
      ADD_FAILURE() << old_key << " accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(std::string("'") + old_key + "' was renamed: use '" + new_key + "'"),
                std::string::npos)
          << what;
      EXPECT_NE(what.find("case.toml"), std::string::npos) << what;
    }
  }
}

// Issue 8, point 2: what DEM t10 evaluation asks for. The t10 progeny reads e50b ("breaking" by
// default) and the Tavares criterion answers E50b of eq. P1b for its own distribution, or E50(d)
// with e50b = "class"; criteria without a distribution keep median_fracture_energy(d).
TEST(Criteria, TavaresAnswersTheMedianOfTheParticlesThatBreak) {
  const char* t10 = "A = 50\nb_prime = 1\nalpha = [1, 1, 1, 1, 1]\nbeta = [2, 2, 1, 1, 1]\n";
  const CaseFile dflt = CaseFile::parse(t10);
  const CaseFile cls = CaseFile::parse(std::string(t10) + "e50b = \"class\"\n");
  EXPECT_EQ(ProgenyRegistry::create("t10", dflt.root())->e50b_rule(),
            comminute::fracture::E50bRule::breaking);
  EXPECT_EQ(ProgenyRegistry::create("t10", cls.root())->e50b_rule(),
            comminute::fracture::E50bRule::class_median);
  TavaresParameters tp;
  tp.size_effect = {100.0, 0.0, 1.0, 1.0};
  tp.sigma = 0.8;
  const Tavares c(tp);
  const double d = 0.01, e = 80.0;
  const auto dist = c.distribution(d);
  EXPECT_DOUBLE_EQ(c.t10_median_energy(d, e, comminute::fracture::E50bRule::breaking),
                   dist.quantile(dist.cdf(e) / 2));
  EXPECT_DOUBLE_EQ(c.t10_median_energy(d, e, comminute::fracture::E50bRule::class_median), 100.0);
}

// Issue 8, point 3: the DEM criterion reads damage_form through the shared reader; the default is
// the (1 - D) form (Tavares, KONA 2017, eq. 20), "no_factor" selects the former one.
TEST(Criteria, TavaresReadsTheDamageForm) {
  Material m{"rock", 2700, 70e9, 0.25};
  const CaseFile dflt = CaseFile::parse("e_inf = 100\nsigma = 0.8\n");
  const CaseFile old = CaseFile::parse("e_inf = 100\nsigma = 0.8\ndamage_form = \"no_factor\"\n");
  auto a = CriterionRegistry::create("tavares", dflt.root(), m);
  auto b = CriterionRegistry::create("tavares", old.root(), m);
  EXPECT_EQ(dynamic_cast<const Tavares&>(*a).parameters().damage.form,
            comminute::fracture::DamageForm::one_minus_d);
  EXPECT_EQ(dynamic_cast<const Tavares&>(*b).parameters().damage.form,
            comminute::fracture::DamageForm::no_factor);
  EXPECT_THROW(
      CriterionRegistry::create(
          "tavares", CaseFile::parse("e_inf = 100\nsigma = 0.8\ndamage_form = \"other\"\n").root(),
          m),
      InputError);
}
