// The ball-mill breakage rates named after papers (docs/models.md eq. S5–S8, docs/pbm.md): Capece
// et al.'s rate computes the paper's equation; the rates standing for Tuzcu & Rajamani and Datta &
// Rajamani are this code's variants and are named so. Each is built through the registry from case
// text, as `comminute pbm` builds it, and compared with values computed here by another route.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/pbm/capece_rate.hpp"
#include "comminute/pbm/selection_function.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using namespace comminute::pbm;

namespace {
const double kv = 0.5235987755982988;

// The rate of `[rate]` in `text`, the data files written into `dir` beforehand.
std::unique_ptr<SelectionFunction> rate_from(const std::filesystem::path& dir,
                                             const std::string& text) {
  std::ofstream(dir / "case.toml") << text;
  const auto file = CaseFile::load(dir / "case.toml");
  const auto grid = SizeGrid::geometric(4e-3, std::sqrt(2.0), 8, GridCoordinate::size, kv);
  const CaseTable t = file.root().table("rate");
  auto r = SelectionFunctionRegistry::create(t.string("model"), t, ModelContext{grid, 2700.0});
  file.reject_unknown();
  return r;
}

const char* capece_case = R"([rate]
model = "capece"
impact_frequency = 50.0        # 1/s
specific_energy_file = "impacts.csv"
f_mat = 2.0                    # kg/(J m)
threshold_product = 0.01       # J m/kg
)";
}  // namespace

TEST(CapeceRate, PaperEquationByHand) {
  // S_i = f_mat x_i ω Σ_k p_k (E_m,k − (xE_min)/x_i)⁺ (Capece, Bilgili & Davé 2014, eq. 13).
  const comminute::testing::TestDir dir;
  std::ofstream(dir / "impacts.csv")
      << "specific_energy_J_per_kg,probability\n5,0.5\n20,0.3\n1000,0.2\n";
  const auto r = rate_from(dir, capece_case);
  ASSERT_NE(r, nullptr);
  // x = 1 mm: E_min = 0.01/1e−3 = 10 J/kg; Σ p (E − 10)⁺ = 0.3·10 + 0.2·990 = 201 J/kg;
  // S = 2 · 1e−3 · 50 · 201 = 20.1 1/s. The top class alone has f_mat x (E − E_min) = 1.98 > 1:
  // capping it at P = 1 (the code before this test) would give 2e−3 · 50 · (0.3·10 + 0.2·500)
  // = 10.3 1/s instead. Tolerance: round-off of a three-term sum of exact decimals (a few ulp
  // of 20.1).
  EXPECT_NEAR(r->rate(1e-3, 0), 20.1, 1e-12);
  // x = 4 mm: E_min = 2.5 J/kg; Σ = 0.5·2.5 + 0.3·17.5 + 0.2·997.5 = 206; S = 2·4e−3·50·206.
  EXPECT_NEAR(r->rate(4e-3, 0), 82.4, 1e-12);
  // x = 2 µm: E_min = 5000 J/kg, no impact exceeds it.
  EXPECT_EQ(r->rate(2e-6, 0), 0.0);
}

TEST(CapeceRate, ContinuousSpectrumAgainstClosedForm) {
  // Exponential distribution of mass-specific impact energies p(E) = e^(−E/Ē)/Ē: the paper's sum
  // becomes ∫ (E − E_min)⁺ p(E) dE = Ē e^(−E_min/Ē), so S = f_mat x ω Ē e^(−E_min/Ē). The model is
  // given the distribution in midpoint bins of width h on [0, 40Ē], probabilities normalised.
  const double mean = 10.0, h = mean / 200, f_mat = 0.5, omega = 3.0, x = 1e-2, tp = 0.05;
  SpecificEnergyDistribution d;
  double sum = 0;
  for (int k = 0; k < 8000; ++k) {
    d.energy.push_back((k + 0.5) * h);
    d.probability.push_back(std::exp(-d.energy.back() / mean) * h / mean);
    sum += d.probability.back();
  }
  for (double& p : d.probability) p /= sum;
  const CapeceRate r({f_mat, tp}, omega, d);
  const double emin = tp / x;  // 5 J/kg, on a bin edge: each bin's integrand is smooth
  const double exact = f_mat * x * omega * mean * std::exp(-emin / mean);
  // Tolerance: the midpoint rule's error, h²/24 · |g'(E_min⁺)| / (Ē e^(−E_min/Ē)) = h²/(24 Ē)
  // ≈ 1.0e−5 relative for the excess and h²/(24 Ē²) ≈ 1e−6 for the normalisation; the tail beyond
  // 40Ē is e^(−40). Five times the estimate.
  EXPECT_NEAR(r.rate(x, 0), exact, 5e-5 * exact);
  // Without a threshold S is linear in x at a fixed spectrum (the notes' oracle (ii)).
  const CapeceRate lin({f_mat, 0.0}, omega, d);
  EXPECT_NEAR(lin.rate(2e-3, 0) / lin.rate(1e-3, 0), 2.0, 1e-14);  // round-off of one product
}

TEST(CapeceRate, BadInputNamesFileLineAndKey) {
  const comminute::testing::TestDir dir;
  // Probabilities that do not sum to 1: the data file, the key and the last row's line.
  std::ofstream(dir / "impacts.csv")
      << "specific_energy_J_per_kg,probability\n5,0.5\n20,0.3\n1000,0.1\n";
  try {
    rate_from(dir, capece_case);
    FAIL() << "a distribution summing to 0.9 was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "rate.specific_energy_file");
    EXPECT_EQ(e.line(), 4);
    EXPECT_NE(e.file().find("impacts.csv"), std::string::npos) << e.file();
  }
  // A key of the energy-spectrum skeleton (the old capece keys): named with its line.
  std::ofstream(dir / "impacts.csv")
      << "specific_energy_J_per_kg,probability\n5,0.5\n20,0.3\n1000,0.2\n";
  try {
    rate_from(dir, std::string(capece_case) + "holdup = 0.5\n");
    FAIL() << "holdup was accepted by capece";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "rate.holdup");
    EXPECT_EQ(e.line(), 7);
    EXPECT_NE(std::string(e.what()).find("impact_frequency"), std::string::npos) << e.what();
  }
}

namespace {
// A `_variant` rate on the skeleton with one collision class: E = 0.01 J, λ = 500 1/s, H = 2 kg,
// m* = 1 g, η = 0.5 (so e = ηE/m* = 5 J/kg and λ m*/H = 0.25 1/s), plus the model's own keys.
std::unique_ptr<SelectionFunction> variant_rate(const std::filesystem::path& dir,
                                                const std::string& model, const std::string& keys) {
  // The paper's equations are not implemented, so the name says "variant" (docs/pbm.md).
  EXPECT_TRUE(SelectionFunctionRegistry::contains(model + "_variant"));
  EXPECT_FALSE(SelectionFunctionRegistry::contains(model));
  std::ofstream(dir / "spectrum.csv") << "energy_J,frequency_per_s\n0.01,500\n";
  return rate_from(dir, "[rate]\nmodel = \"" + model + "_variant\"\n" +
                            "spectrum_file = \"spectrum.csv\"\nholdup = 2.0\n" +
                            "captured_mass = 1.0e-3\nenergy_share = 0.5\n" + keys);
}
}  // namespace

TEST(TuzcuRajamaniVariant, NamedAsThisCodesVariantAndComputesItsSkeletonByHand) {
  // The paper's E_k weighting is not implemented.
  const comminute::testing::TestDir dir;
  const auto r = variant_rate(dir, "tuzcu_rajamani", "f_mat = 2.0\nthreshold_product = 1e-3\n");
  ASSERT_NE(r, nullptr);
  // e = ηE/m* = 0.5·0.01/1e−3 = 5 J/kg; x = 1 mm: E_min = 1 J/kg; f_mat x (e − E_min) = 0.008;
  // P = 1 − e^(−0.008) = 0.008 − 0.008²/2 + 0.008³/6 − 0.008⁴/24 + … = 0.00796808516293937;
  // S = λ m*/H · P = 500 · 1e−3 / 2 · P = 0.25 P. Tolerance: the code forms 1 − exp(−a), whose
  // cancellation leaves an absolute error up to ulp(1) = 2.2e−16 in P; times 0.25, doubled.
  EXPECT_NEAR(r->rate(1e-3, 0), 0.25 * 0.00796808516293937, 1.1e-16);
}

TEST(DattaRajamaniVariant, NamedAsThisCodesVariantAndComputesItsSkeletonByQuadrature) {
  // The paper's broken-mass function and b_ij(E_k) are not implemented.
  const comminute::testing::TestDir dir;
  const auto r = variant_rate(dir, "datta_rajamani", "e_inf = 2.0\nd0 = 1e-3\nsigma = 0.5\n");
  ASSERT_NE(r, nullptr);
  // x = 1 mm: E50 = E∞ (1 + d0/x) = 4 J/kg; e = 5 J/kg; P = F(e), the lognormal cdf, here by
  // Simpson's rule on its density in u = ln E from ln E50 − 12σ to ln e (not the erf the code
  // uses).
  const double mu = std::log(4.0), s = 0.5, a = mu - 12 * s, b = std::log(5.0);
  const int n = 2000;
  const double h = (b - a) / n;
  const auto pdf = [&](double u) {
    return std::exp(-0.5 * std::pow((u - mu) / s, 2)) / (s * std::sqrt(2 * std::numbers::pi));
  };
  double p = pdf(a) + pdf(b);
  for (int k = 1; k < n; ++k) p += (k % 2 ? 4 : 2) * pdf(a + k * h);
  p *= h / 3;
  // Tolerance: Simpson's error h⁴/180 · |f‴(b) − f‴(a)| ≈ 9.4e−11/180 · 7.2 ≈ 4e−12 (h = 3.1e−3),
  // the cut at −12σ ~ 1e−33, round-off of 2000 terms ~ 1e−13: 1e−10 of P, 25 times the sum.
  EXPECT_NEAR(r->rate(1e-3, 0), 0.25 * p, 0.25 * 1e-10);
}
