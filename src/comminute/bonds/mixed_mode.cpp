#include "comminute/bonds/mixed_mode.hpp"

#include <algorithm>
#include <cmath>

namespace comminute::bonds {

MixedMode mixed_mode(const CohesiveParameters& p, double dn, double ds) {
  MixedMode m;
  const double open = std::max(dn, 0.0);
  m.effective = std::sqrt(open * open + ds * ds);
  const double dn0 = p.normal_strength / p.penalty;
  const double ds0 = p.shear_strength / p.penalty;
  if (open > 0) {
    const double beta = ds / open;
    // Camanho & Dávila, NASA/TM-2002-211737 (2002), initiation, maximum-stress form:
    // δ_m0 = min(δ_n0 √(1+β²), δ_s0 √(1+β²)/β)
    const double root = std::sqrt(1.0 + beta * beta);
    m.onset = beta > 0 ? std::min(dn0 * root, ds0 * root / beta) : dn0;
    m.shear_ratio = beta * beta / (1.0 + beta * beta);
  } else {
    m.onset = ds0;
    m.shear_ratio = 1.0;
  }
  // Benzeggagh & Kenane, Compos. Sci. Technol. 56 (1996) 439: G_c = G_Ic + (G_IIc - G_Ic) B^η
  m.toughness =
      p.toughness_I + (p.toughness_II - p.toughness_I) * std::pow(m.shear_ratio, p.bk_exponent);
  // Camanho & Dávila, NASA/TM-2002-211737 (2002), linear softening: δ_mf = 2 G_c / (K δ_m0)
  m.final = 2.0 * m.toughness / (p.penalty * m.onset);
  return m;
}

double bilinear_damage(const MixedMode& m) {
  if (m.effective <= m.onset) return 0.0;
  if (m.effective >= m.final) return 1.0;
  // Camanho & Dávila, NASA/TM-2002-211737 (2002), damage: d = δ_mf (δ_m - δ_m0) / (δ_m (δ_mf -
  // δ_m0))
  return m.final * (m.effective - m.onset) / (m.effective * (m.final - m.onset));
}

double dissipated_per_area(const CohesiveParameters& p, const MixedMode& m, double d) {
  if (d <= 0) return 0.0;
  // the separation at which the bilinear law reaches damage d (the damage formula solved for δ_m)
  const double at = m.final * m.onset / (m.final - d * (m.final - m.onset));
  // work ∫t dδ minus what is stored, ½(1-d)Kδ_m², along the softening branch
  return 0.5 * d * p.penalty * m.onset * at;
}

}  // namespace comminute::bonds
