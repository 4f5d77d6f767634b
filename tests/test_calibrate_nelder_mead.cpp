// Nelder–Mead against the reference run of MODELS-pbm-notes.md §7 (SciPy 1.10.1 and MATLAB's
// fminsearch agree on it), and the preconditioned, bounded multi-start driver.
#include <gtest/gtest.h>

#include <cmath>

#include "comminute/calibrate/multistart.hpp"
#include "comminute/calibrate/nelder_mead.hpp"

using namespace comminute::calibrate;

namespace {
double rosenbrock(const Point& x) {
  return 100 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]) + (1 - x[0]) * (1 - x[0]);
}
}  // namespace

TEST(NelderMead, RosenbrockFromMinus1p2And1MatchesTheReferenceRun) {
  // fminsearch simplex, stable sort, x_tol = f_tol = 1e−4: the reference counts are exact
  // integers (any change in simplex, ties or the stopping test changes them), f to the 7 digits
  // quoted, x to the 10 quoted.
  const auto r = nelder_mead(rosenbrock, fminsearch_simplex({-1.2, 1.0}));
  EXPECT_EQ(r.iterations, 85u);
  EXPECT_EQ(r.evaluations, 159u);
  EXPECT_NEAR(r.f, 8.177661e-10, 0.5e-16);
  EXPECT_NEAR(r.x[0], 1.0000220218, 1e-10);
  EXPECT_NEAR(r.x[1], 1.0000422198, 1e-10);
  EXPECT_EQ(r.reflections, 24u);
  EXPECT_EQ(r.expansions, 18u);
  EXPECT_EQ(r.outside_contractions, 12u);
  EXPECT_EQ(r.inside_contractions, 30u);
  EXPECT_EQ(r.shrinks, 0u);
  EXPECT_TRUE(r.converged);
}

TEST(NelderMead, TighterTolerancesReachTheMinimum) {
  // Notes §7: SciPy with x_tol = f_tol = 1e−8 gives nit 117, nfev 219, f 1.10e−18.
  NelderMeadOptions o;
  o.x_tolerance = o.f_tolerance = 1e-8;
  const auto r = nelder_mead(rosenbrock, fminsearch_simplex({-1.2, 1.0}), o);
  EXPECT_EQ(r.iterations, 117u);
  EXPECT_EQ(r.evaluations, 219u);
  EXPECT_LT(r.f, 2e-18);
}

TEST(NelderMead, AdaptiveCoefficientsAlsoReachTheMinimum) {
  // Gao & Han (2012) coefficients for n = 2: χ = 2, ψ = 0.5, σ = 0.5 — the standard ones, so
  // the run must be the reference run; for n = 6 they differ (χ = 4/3, ψ = 2/3, σ = 5/6).
  const auto o2 = NelderMeadOptions::adaptive(2);
  EXPECT_EQ(o2.chi, 2.0);
  EXPECT_EQ(o2.psi, 0.5);
  EXPECT_EQ(o2.sigma, 0.5);
  const auto o6 = NelderMeadOptions::adaptive(6);
  EXPECT_NEAR(o6.chi, 4.0 / 3, 1e-15);
  EXPECT_NEAR(o6.psi, 2.0 / 3, 1e-15);
  EXPECT_NEAR(o6.sigma, 5.0 / 6, 1e-15);
  // Ill-scaled 6-D quadratic Σ i·(x_i − i)², start 0: the adaptive variant reaches the
  // minimum. Tolerance 1e−5 in x: a best vertex with f ≤ 1e−10 (the f-based stop) has
  // |x_i − i| ≤ √(1e−10/i) ≤ 1e−5.
  auto f = [](const Point& x) {
    double s = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double k = static_cast<double>(i + 1);
      s += k * (x[i] - k) * (x[i] - k);
    }
    return s;
  };
  auto o = o6;
  o.x_tolerance = o.f_tolerance = 1e-10;
  o.max_evaluations = o.max_iterations = 20000;
  const auto r = nelder_mead(f, fminsearch_simplex(Point(6, 0.0)), o);
  ASSERT_TRUE(r.converged);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_NEAR(r.x[i], static_cast<double>(i + 1), 1e-5);
}

TEST(MultiStart, BoundsAreHonouredAndResultsRepeatFromTheSeed) {
  // Minimum of the shifted Rosenbrock at (3, 9) lies outside the box [−2, 2] × [0.01, 100]:
  // the best point must sit on the boundary x = 2 (the constrained minimum is at (2, 4)) and
  // every evaluated point must lie inside the bounds.
  ParameterSpace space({{"x", -2, 2, Scale::linear}, {"y", 0.01, 100, auto_scale(0.01, 100)}});
  EXPECT_EQ(space[1].scale, Scale::log);
  bool outside = false;
  auto f = [&](const std::vector<double>& p) {
    if (p[0] < -2 || p[0] > 2 || p[1] < 0.01 || p[1] > 100) outside = true;
    const double a = p[0] / 3, b = p[1] / 9;
    return 100 * (b - a * a) * (b - a * a) + (1 - a) * (1 - a);
  };
  MultiStartOptions o;
  o.starts = 15;
  o.seed = 7;
  o.nelder_mead.x_tolerance = 1e-9;
  o.nelder_mead.f_tolerance = 1e-14;
  o.nelder_mead.max_evaluations = 4000;
  const auto r1 = multistart(space, f, o);
  o.threads = 1;
  const auto r2 = multistart(space, f, o);
  EXPECT_FALSE(outside);
  ASSERT_EQ(r1.starts.size(), 15u);
  const auto& best = r1.starts[r1.best].best;
  EXPECT_NEAR(best[0], 2.0, 1e-6);        // on the bound (x_tol 1e−9 in u, ×4 range)
  EXPECT_NEAR(best[1], 4.0, 1e-3);        // a = 2/3 ⇒ b = a² = 4/9 ⇒ y = 4
  for (std::size_t k = 0; k < 15; ++k) {  // same seed, other thread count: identical numbers
    EXPECT_EQ(r1.starts[k].start, r2.starts[k].start);
    EXPECT_EQ(r1.starts[k].best, r2.starts[k].best);
    EXPECT_EQ(r1.starts[k].f, r2.starts[k].f);
  }
}
