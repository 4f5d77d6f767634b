// Austin batch grinding against Reid's analytical solution (Reid, Chem. Eng. Sci. 20 (1965)
// 953; MODELS-pbm-notes.md §4), and the b_ij conventions of BatchGrinding::from_models.
#include <gtest/gtest.h>

#include <cmath>

#include "comminute/pbm/austin_breakage_function.hpp"
#include "comminute/pbm/batch_grinding.hpp"
#include "comminute/pbm/integrator.hpp"
#include "comminute/pbm/power_law_rate.hpp"
#include "comminute/pbm/solve.hpp"

using namespace comminute::pbm;

namespace {

// Reid: w_i(t) = Σ_{j≤i} a_ij e^{−S_j t}, classes numbered from the top (i = 0 coarsest here),
// a_ij = (1/(S_i − S_j)) Σ_{k=j}^{i−1} b_ik S_k a_kj (i > j), a_ii = w_i(0) − Σ_{j<i} a_ij.
std::vector<double> reid(const std::vector<double>& s, const std::vector<std::vector<double>>& b,
                         const std::vector<double>& w0, double t) {
  const std::size_t n = s.size();
  std::vector<std::vector<double>> a(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0;
    for (std::size_t j = 0; j < i; ++j) {
      double acc = 0;
      for (std::size_t k = j; k < i; ++k) acc += b[i][k] * s[k] * a[k][j];
      a[i][j] = acc / (s[i] - s[j]);
      sum += a[i][j];
    }
    a[i][i] = w0[i] - sum;
  }
  std::vector<double> w(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j <= i; ++j) w[i] += a[i][j] * std::exp(-s[j] * t);
  return w;
}

}  // namespace

TEST(BatchGrinding, ReproducesReidsSolution) {
  // Stated set (top to sink, 1/s): S = 1.2, 0.8, 0.5, 0.3, 0.15, 0 — distinct, as Reid needs;
  // b_ij (i below j) from Austin's normalised B with Φ = 0.6, γ = 1.1, β = 4 on a √2 series:
  // b_ij = B(r^{−(i−j−1)}) − B(r^{−(i−j)}) for the classes above the sink, the rest to the sink.
  const std::vector<double> s_top{1.2, 0.8, 0.5, 0.3, 0.15, 0.0};
  const std::size_t n = s_top.size();
  const double r = std::sqrt(2.0);
  auto B = [](double x) { return 0.6 * std::pow(x, 1.1) + 0.4 * std::pow(x, 4.0); };
  std::vector<std::vector<double>> b_top(n, std::vector<double>(n, 0.0));
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = j + 1; i < n; ++i) {
      const double upper = std::pow(r, -static_cast<double>(i - j - 1));
      const double lower = i + 1 < n ? std::pow(r, -static_cast<double>(i - j)) : 0.0;
      b_top[i][j] = B(upper) - B(lower);
    }
  const std::vector<double> w0_top{1.0, 0, 0, 0, 0, 0};
  // Library ordering is fine to coarse: index n−1−i.
  std::vector<double> s(n);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(6, 6);
  Eigen::VectorXd w0(6);
  for (std::size_t i = 0; i < n; ++i) {
    s[n - 1 - i] = s_top[i];
    w0[static_cast<Eigen::Index>(n - 1 - i)] = w0_top[i];
    for (std::size_t j = 0; j < n; ++j)
      b(static_cast<Eigen::Index>(n - 1 - i), static_cast<Eigen::Index>(n - 1 - j)) = b_top[i][j];
  }
  const BatchGrinding mill(s, b);
  const std::vector<double> times{0.5, 2.0, 10.0};
  // Tolerances: DP5(4) at rtol 1e−12 and RK4 with h = 0.005 s (local error ~(hS)^5/120 ≈ 6e−15,
  // ×2000 steps) both sit three or more orders below the required 1e−8.
  DormandPrince dp({1e-12, 1e-15, 1000000});
  Rk4 rk4(0.005);
  const auto sol_dp = solve(mill.system(), dp, w0, times);
  const auto sol_rk = solve(mill.system(), rk4, w0, times);
  for (std::size_t k = 0; k < times.size(); ++k) {
    const auto w = reid(s_top, b_top, w0_top, times[k]);
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_NEAR(sol_dp[k][static_cast<Eigen::Index>(n - 1 - i)], w[i], 1e-8) << "t=" << times[k];
      EXPECT_NEAR(sol_rk[k][static_cast<Eigen::Index>(n - 1 - i)], w[i], 1e-8) << "t=" << times[k];
    }
    EXPECT_NEAR(sol_dp[k].sum(), 1.0, 1e-13);  // Σ_i b_ij = 1: mass is kept
  }
}

TEST(BatchGrinding, Rk4IsFourthOrder) {
  // Two classes, S = (1, 0), b = 1: w_top = e^{−t}. Halving the RK4 step cuts the error at
  // t = 2 s by → 2⁴ = 16; from RK4's amplification polynomial 1 − h + h²/2 − h³/6 + h⁴/24 the
  // ratios are 17.396 (h 0.2 → 0.1) and 16.682 (0.1 → 0.05); required to 0.01 (the error
  // itself is far above round-off at these steps, ≥ 1.5e−8).
  const BatchGrinding m({0.0, 1.0}, (Eigen::MatrixXd(2, 2) << 0, 1, 0, 0).finished());
  Eigen::VectorXd w0(2);
  w0 << 0.0, 1.0;
  double err[3];
  const double h[3] = {0.2, 0.1, 0.05};
  for (int k = 0; k < 3; ++k) {
    Rk4 rk4(h[k]);
    err[k] = std::abs(solve(m.system(), rk4, w0, {2.0}).back()[1] - std::exp(-2.0));
  }
  EXPECT_NEAR(err[0] / err[1], 17.40, 0.01);
  EXPECT_NEAR(err[1] / err[2], 16.68, 0.01);
}

TEST(BatchGrinding, AdaptiveErrorFollowsTheTolerance) {
  // Same two-class problem: the global error of Dormand–Prince with local error control is of
  // the order of the tolerance; required below 10 × rtol for rtol = 1e−4 … 1e−10 and falling
  // with it (atol is kept negligible).
  const BatchGrinding m({0.0, 1.0}, (Eigen::MatrixXd(2, 2) << 0, 1, 0, 0).finished());
  Eigen::VectorXd w0(2);
  w0 << 0.0, 1.0;
  double prev = 1;
  for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    DormandPrince dp({rtol, 1e-16, 1000000});
    const double err =
        std::abs(solve(m.system(), dp, w0, {5.0}).back()[1] - std::exp(-5.0)) / std::exp(-5.0);
    EXPECT_LT(err, 10 * rtol) << rtol;
    EXPECT_LT(err, prev) << rtol;
    prev = err;
  }
}

TEST(BatchGrinding, FromModelsFollowsAustinsConventions) {
  // √2 series, 8 classes from 4 mm; Austin's normalised B: every column sums to 1 and the class
  // just below the parent receives 1 − B(1/√2) (B_{j+1,j} = 1).
  const SizeGrid g = SizeGrid::geometric(4e-3, std::sqrt(2.0), 8, GridCoordinate::size, 0.5236);
  const AustinBreakageFunction f({0.6, 1.1, 4.0, 0.0, 1e-3}, 0.5236);
  const PowerLawRate rate({0.5, 1.0, GridCoordinate::size, 1e-3, std::nullopt, 2.0});
  const BatchGrinding m = BatchGrinding::from_models(g, rate, f);
  const double s2 = 1 / std::sqrt(2.0);
  for (Eigen::Index j = 1; j < 8; ++j) {
    EXPECT_NEAR(m.breakage().col(j).sum(), 1.0, 1e-14);
    if (j >= 2) {  // (for j = 1 the class below is the sink, which takes everything)
      EXPECT_NEAR(m.breakage()(j - 1, j), 1 - (0.6 * std::pow(s2, 1.1) + 0.4 * std::pow(s2, 4)),
                  1e-14);
    }
    // S_i = k (x_i/x_ref)^α at the class's upper size.
    EXPECT_NEAR(m.rates()[static_cast<std::size_t>(j)],
                0.5 * g.size_edge(static_cast<std::size_t>(j) + 1) / 1e-3, 1e-12);
  }
  EXPECT_EQ(m.rates()[0], 0.0);  // the sink
}
