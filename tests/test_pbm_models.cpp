// Size grids, breakage functions, rates and the assembled method-of-classes operator.
#include <gtest/gtest.h>

#include <boost/math/special_functions/beta.hpp>
#include <cmath>

#include "comminute/core/error.hpp"
#include "comminute/pbm/austin_breakage_function.hpp"
#include "comminute/pbm/energy_spectrum_rate.hpp"
#include "comminute/pbm/method_of_classes.hpp"
#include "comminute/pbm/population_split.hpp"
#include "comminute/pbm/power_law_rate.hpp"
#include "comminute/pbm/product_function.hpp"
#include "comminute/pbm/stress_rate.hpp"
#include "comminute/pbm/t10_breakage_function.hpp"
#include "comminute/pbm/tabulated_breakage_function.hpp"

using namespace comminute::pbm;

namespace {
const double kv = 0.5235987755982988;

// The same function without the homogeneity shortcut.
class Opaque : public BreakageFunction {
 public:
  explicit Opaque(const BreakageFunction& f) : f_(f) {}
  double cumulative_mass(double v, double y) const override { return f_.cumulative_mass(v, y); }
  std::optional<double> cumulative_number(double v, double y) const override {
    return f_.cumulative_number(v, y);
  }

 private:
  const BreakageFunction& f_;
};
}  // namespace

TEST(SizeGrid, ConvertsSizeAndVolumeAndKnowsGeometricGrids) {
  const auto g = SizeGrid::geometric(4e-3, std::sqrt(2.0), 10, GridCoordinate::size, kv);
  EXPECT_NEAR(g.size_edge(10), 4e-3, 1e-18);
  EXPECT_NEAR(g.size_edge(9), 4e-3 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(g.volume_edge(10), kv * 64e-9, 1e-22);
  EXPECT_TRUE(g.geometric_in_volume());
  EXPECT_FALSE(SizeGrid({0, 1, 2, 3}, GridCoordinate::volume, 1).geometric_in_volume());
  EXPECT_THROW(SizeGrid({1, 3, 2}, GridCoordinate::size, kv), comminute::Error);
}

TEST(PowerLawRate, SizeOrVolumeAndAustinsTurnDown) {
  const double d = 2e-3, v = kv * d * d * d;
  const PowerLawRate by_size({0.5, 1.2, GridCoordinate::size, 1e-3, std::nullopt, 2.0});
  const PowerLawRate by_volume({0.5, 1.2, GridCoordinate::volume, 1e-9, std::nullopt, 2.0});
  const PowerLawRate turned({0.5, 1.2, GridCoordinate::size, 1e-3, 3e-3, 2.5});
  EXPECT_NEAR(by_size.rate(d, v), 0.5 * std::pow(2.0, 1.2), 1e-14);
  EXPECT_NEAR(by_volume.rate(d, v), 0.5 * std::pow(v / 1e-9, 1.2), 1e-14);
  EXPECT_NEAR(turned.rate(d, v), 0.5 * std::pow(2.0, 1.2) / (1 + std::pow(2.0 / 3, 2.5)), 1e-14);
}

TEST(MethodOfClasses, GeometricShortcutEqualsDirectEvaluation) {
  // Same B_{i,k} whether each parent is evaluated directly or read from the shifted table;
  // 1e−13 relative: only the round-off of edge/pivot ratios differs.
  const auto g = SizeGrid::logarithmic(1e-6, 1e-3, 40, GridCoordinate::size, kv);
  const PowerLawRate rate({1.0, 1.0, GridCoordinate::size, 1e-3, std::nullopt, 2.0});
  const ProductFunction d(2.1, 46.8);
  const AustinBreakageFunction a({0.6, 1.1, 4.0, 0.0, 1e-3}, kv);
  for (const BreakageFunction* f :
       {static_cast<const BreakageFunction*>(&d), static_cast<const BreakageFunction*>(&a)}) {
    const MethodOfClasses fast(g, rate, *f), slow(g, rate, Opaque(*f));
    const double diff = (fast.birth_matrix() - slow.birth_matrix()).cwiseAbs().maxCoeff();
    EXPECT_LT(diff, 1e-13 * slow.birth_matrix().cwiseAbs().maxCoeff());
  }
}

TEST(MethodOfClasses, OperatorConservesMassAndCountsFragmentsExactly) {
  // Notes §2.1: column k of the operator gives d(ΣN)/dt = (ν_k − 1) S_k and d(Σ x N)/dt = 0 for
  // every parent above the finest class, on any grid (here an irregular one) and any kernel.
  std::vector<double> e{0.0};
  for (int i = 1; i <= 30; ++i) e.push_back(std::pow(1.3, i) * (1 + 0.2 * std::sin(i)));
  const SizeGrid g(e, GridCoordinate::volume, 1.0);
  const PowerLawRate rate({0.3, 0.7, GridCoordinate::volume, 1.0, std::nullopt, 2.0});
  const ProductFunction f(0.7, 5.0);
  const MethodOfClasses moc(g, rate, f);
  const Eigen::MatrixXd& a = moc.matrix();
  for (Eigen::Index k = 1; k < a.cols(); ++k) {
    const auto kk = static_cast<std::size_t>(k);
    double mass = 0, scale = 0;
    for (Eigen::Index i = 0; i <= k; ++i) {
      mass += g.pivot_volume(static_cast<std::size_t>(i)) * a(i, k);
      scale += std::abs(g.pivot_volume(static_cast<std::size_t>(i)) * a(i, k));
    }
    EXPECT_LT(std::abs(mass), 1e-13 * scale) << k;
    EXPECT_NEAR(a.col(k).sum(), (5.0 - 1) * moc.rates()[kk], 1e-12 * moc.rates()[kk]) << k;
    EXPECT_NEAR(moc.fragments()[kk], 5.0, 1e-12);
  }
  EXPECT_EQ(a(0, 0), 0.0);  // the finest class does not break
}

TEST(MethodOfClasses, MassDefinedFunctionsGetUnitWeights) {
  // Fragments lumped by mass at pivots already conserve mass and number: ω^b = ω^d = 1.
  const auto g = SizeGrid::geometric(2e-3, std::sqrt(2.0), 25, GridCoordinate::size, kv);
  const PowerLawRate rate({0.01, 1.0, GridCoordinate::size, 1e-3, std::nullopt, 2.0});
  const AustinBreakageFunction f({0.5, 0.9, 3.5, 0.0, 1e-3}, kv);
  const MethodOfClasses moc(g, rate, f);
  for (std::size_t k = 1; k < g.classes(); ++k) {
    EXPECT_NEAR(moc.birth_weights()[k], 1.0, 1e-11) << k;
    EXPECT_NEAR(moc.death_weights()[k], 1.0, 1e-11) << k;
  }
}

TEST(AustinBreakageFunction, NormalisedAndNonNormalised) {
  const AustinBreakageFunction n({0.6, 1.1, 4.0, 0.0, 1e-3}, kv);
  const AustinBreakageFunction nn({0.6, 1.1, 4.0, 0.5, 1e-3}, kv);
  const double y = kv * 8e-9;  // D = 2 mm
  const double v = y / 8;      // d/D = 1/2
  EXPECT_NEAR(n.cumulative_mass(v, y), 0.6 * std::pow(0.5, 1.1) + 0.4 * std::pow(0.5, 4.0), 1e-14);
  const double phi = 0.6 * std::pow(2.0, -0.5);  // Φ_D = Φ (D/D_ref)^−δ
  EXPECT_NEAR(nn.cumulative_mass(v, y), phi * std::pow(0.5, 1.1) + (1 - phi) * std::pow(0.5, 4.0),
              1e-14);
  EXPECT_NEAR(n.cumulative_mass(y, y), 1.0, 1e-15);
  EXPECT_TRUE(n.homogeneous());
  EXPECT_FALSE(nn.homogeneous());
}

TEST(T10BreakageFunction, PassesT10AtOneTenthAndTnAtOneNth) {
  comminute::fracture::T10Parameters fam;
  fam.a = 50;
  fam.b_prime = 1.2;
  // Illustrative family (no published default set): fitted to a typical t10–tn chart shape
  // (t10 = 20 % → t2 70, t4 45, t25 9, t50 5, t75 3.5 %).
  fam.alpha = {0.86, 1.0, 0.90, 0.93, 0.93};
  fam.beta = {4.59, 2.70, 0.333, 0.192, 0.134};
  const comminute::fracture::T10Model model(fam);
  const double t10 = model.t10(1000, 2000);
  EXPECT_NEAR(t10, 50 * (1 - std::exp(-0.6)), 1e-12);
  const auto tab = t10_progeny(model, t10);
  EXPECT_NEAR(tab.passing(0.1), t10 / 100, 1e-14);
  EXPECT_NEAR(tab.passing(0.5), boost::math::ibeta(0.86, 4.59, t10 / 100), 1e-14);
  EXPECT_NEAR(tab.passing(1.0 / 75), boost::math::ibeta(0.93, 0.134, t10 / 100), 1e-14);
  double prev = 0;
  for (double s = 1e-4; s <= 1; s *= 1.1) {  // monotone, below-table tail included
    const double p = tab.passing(s);
    EXPECT_GE(p, prev);
    prev = p;
  }
  const T10BreakageFunction f(
      model, 1000, [](double) { return 2000.0; }, kv);
  const double y = kv * 1e-9;
  EXPECT_NEAR(f.cumulative_mass(y / 1000, y), t10 / 100, 1e-14);  // d/D = 1/10
}

TEST(TabulatedBreakageFunction, InterpolatesItsPointsWithAPowerLawTail) {
  const TabulatedBreakageFunction f(
      CumulativeTable({0.05, 0.1, 0.3, 0.6, 1.0}, {0.04, 0.1, 0.35, 0.7, 1.0}));
  for (auto [s, p] : {std::pair{0.05, 0.04}, {0.1, 0.1}, {0.3, 0.35}, {0.6, 0.7}, {1.0, 1.0}})
    EXPECT_NEAR(f.cumulative_mass(s * s * s, 1.0), p, 1e-14);
  const double slope = std::log(0.1 / 0.04) / std::log(2.0);
  EXPECT_NEAR(f.cumulative_mass(1e-6, 1.0), 0.04 * std::pow(0.01 / 0.05, slope), 1e-14);
  EXPECT_THROW(CumulativeTable({0.1, 0.3, 0.2, 1.0}, {0.1, 0.2, 0.3, 1.0}), comminute::Error);
}

TEST(PopulationSplit, PicksTheFunctionByParentSize) {
  std::vector<PopulationSplit::Population> pops;
  pops.push_back({kv * 1e-12, std::make_unique<ProductFunction>(2.1, 46.8)});  // below 100 µm
  pops.push_back({0, std::make_unique<ProductFunction>(3.8, 27.6)});
  const PopulationSplit s(std::move(pops));
  const double small = kv * 0.5e-12, large = kv * 8e-12;
  EXPECT_NEAR(*s.cumulative_number(small, small), 46.8, 1e-10);
  EXPECT_NEAR(*s.cumulative_number(large, large), 27.6, 1e-10);
}

TEST(StressRate, IntegratesTheContactFrequencyAboveTheStrength) {
  // ṅ constant c on [0, σmax] ⇒ b = λ c (σmax − σcrit); σcrit = σ0 (d/d_ref)^(−1/m).
  const double c = 2e-3, smax = 1e5;
  const StressRate r(0.5, ContactFrequencySpectrum({0, 5e4, smax}, {c, c, c}),
                     std::make_unique<PowerLawStrength>(2e4, 2.0, 1e-3));
  const double d = 4e-3, sc = 2e4 * std::pow(4.0, -0.5);
  EXPECT_NEAR(r.rate(d, 0), 0.5 * c * (smax - sc), 1e-12);
  // σ50 model: no breakage at or below x_p; σ50 = σ∞(1 + x0/(x − x_p))^φ above it.
  const StressRate s(1.0, ContactFrequencySpectrum({0, smax}, {c, c}),
                     std::make_unique<Sigma50Strength>(3e4, 5e-5, 1.0, 2e-6));
  EXPECT_EQ(s.rate(2e-6, 0), 0.0);
  EXPECT_NEAR(s.rate(1e-4, 0), c * (smax - 3e4 * (1 + 5e-5 / (1e-4 - 2e-6))), 1e-12);
}

TEST(EnergySpectrumRate, LimitingCasesOfTheSkeleton) {
  // (i) one energy class, every stressed particle broken (P ≡ 1) ⇒ S = λ m*/H for every size.
  const CollisionSpectrum one{{0.01}, {500.0}};
  const EnergySpectrumRate all(one, 2.0, 1e-4, 1.0,
                               std::make_unique<VogelPeukertProbability>(1e9, 0.0));
  EXPECT_NEAR(all.rate(1e-4, 0), 500 * 1e-4 / 2.0, 1e-15);
  EXPECT_NEAR(all.rate(1e-3, 0), 500 * 1e-4 / 2.0, 1e-15);
  // (ii) the explicit sum (1/H) Σ λ m* [1 − exp(−f_mat x (η E/m* − xEmin/x)⁺)] with a threshold
  // that only the top class exceeds at x = 1e−4 m (E_min = 50 J/kg; e = 0.5, 5, 50.5 J/kg).
  const CollisionSpectrum spec{{1e-3, 1e-2, 1.01e-1}, {1000, 100, 10}};
  const EnergySpectrumRate thr(spec, 2.0, 1e-3, 0.5,
                               std::make_unique<VogelPeukertProbability>(0.05, 5e-3));
  // Only k = 2 counts: 10 · 1e−3 · (1 − exp(−0.05 · 1e−4 · 0.5)) / 2 = 5e−3 · P. Tolerance: the
  // code forms 1 − exp(−2.5e−6), whose cancellation leaves up to ulp(1) = 2.2e−16 in P; times
  // 5e−3, doubled (the classes below the threshold must add exactly 0).
  EXPECT_NEAR(thr.rate(1e-4, 0), 10 * 1e-3 * -std::expm1(-0.05 * 1e-4 * 0.5) / 2.0, 2.2e-18);
}
