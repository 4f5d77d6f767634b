// Diemer–Olson product function: normalisation, uniform binary limit, and the two z50 medians
// (MODELS-pbm-notes.md §3).
#include <gtest/gtest.h>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <cmath>
#include <iostream>

#include "comminute/pbm/product_function.hpp"

using comminute::pbm::ProductFunction;

namespace {
struct QNu {
  double q, nu;
};
// The three parameter sets of the carbon-black study plus the uniform binary kernel and a q < 1,
// small-ν case (integrable singularity at z = 0).
const QNu cases[] = {{1.0, 2.0}, {3.8, 27.6}, {2.1, 46.8}, {0.2, 158.2}, {0.7, 3.0}};
}  // namespace

TEST(ProductFunction, IntegratesToNuFragmentsAndUnitMass) {
  boost::math::quadrature::tanh_sinh<double> integrator;
  for (const auto& c : cases) {
    const ProductFunction p(c.q, c.nu);
    const double n = integrator.integrate([&](double z) { return p.theta(z); }, 0.0, 1.0);
    const double m = integrator.integrate([&](double z) { return z * p.theta(z); }, 0.0, 1.0);
    // tanh-sinh reaches ~1e−12 on these smooth-inside, power-singular-at-ends integrands;
    // 1e−9 relative leaves room for the z^(−0.8) singularity of q = 0.2.
    EXPECT_NEAR(n / c.nu, 1.0, 1e-9) << "q=" << c.q << " nu=" << c.nu;
    EXPECT_NEAR(m, 1.0, 1e-9) << "q=" << c.q << " nu=" << c.nu;
    // The closed forms used by the method of classes agree with the integrals.
    EXPECT_NEAR(*p.cumulative_number(1.0, 1.0), c.nu, 1e-12 * c.nu);
    EXPECT_NEAR(p.cumulative_mass(1.0, 1.0), 1.0, 1e-14);
    const double half = integrator.integrate([&](double z) { return p.theta(z); }, 0.0, 0.3);
    EXPECT_NEAR(*p.cumulative_number(0.3, 1.0), half, 1e-9 * c.nu);
  }
}

TEST(ProductFunction, QOneNuTwoIsTheUniformBinaryKernel) {
  const ProductFunction p(1.0, 2.0);
  for (double z : {0.01, 0.2, 0.5, 0.77, 0.99}) {
    EXPECT_NEAR(p.theta(z), 2.0, 1e-14);                      // p(x, y) = 2/y
    EXPECT_NEAR(*p.cumulative_number(z, 1.0), 2 * z, 1e-14);  // 2z fragments below z
    EXPECT_NEAR(p.cumulative_mass(z, 1.0), z * z, 1e-14);     // ∫ 2ζ dζ
  }
  EXPECT_NEAR(p.z50_number(), 0.5, 1e-14);
  EXPECT_NEAR(p.z50_volume(), std::sqrt(0.5), 1e-14);
}

TEST(ProductFunction, BothMediansMatchTheirDefinitionsAndTheNotesTable) {
  // Notes §3 table (independent Python/scipy computation), 4 significant digits except 6.68e−4
  // and 2.78e−2 (3): tolerances are half a unit in the last quoted digit.
  struct Row {
    double q, nu, quoted, number, volume, tol_n, tol_v;
  };
  const Row rows[] = {{3.8, 27.6, 3.08e-2, 3.332e-2, 4.249e-2, 0.5e-5, 0.5e-5},
                      {2.1, 46.8, 1.68e-2, 1.821e-2, 2.813e-2, 0.5e-5, 0.5e-5},
                      {0.2, 158.2, 9.86e-4, 6.68e-4, 2.78e-2, 0.5e-6, 0.5e-4}};
  for (const auto& r : rows) {
    const ProductFunction p(r.q, r.nu);
    const double zn = p.z50_number(), zv = p.z50_volume();
    EXPECT_NEAR(boost::math::ibeta(r.q, p.r(), zn), 0.5, 1e-12);
    EXPECT_NEAR(boost::math::ibeta(r.q + 1, p.r(), zv), 0.5, 1e-12);
    EXPECT_NEAR(zn, r.number, r.tol_n);
    EXPECT_NEAR(zv, r.volume, r.tol_v);
    // Reported in docs/pbm.md: how close each definition comes to the published z50. Neither
    // matches (notes §3); the number median is within 10 % for the two carbon blacks only.
    std::cout << "q=" << r.q << " nu=" << r.nu << " published z50 " << r.quoted << " number median "
              << zn << " (published/number " << r.quoted / zn << ")"
              << " volume median " << zv << " (published/volume " << r.quoted / zv << ")\n";
  }
}
