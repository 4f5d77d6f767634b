#pragma once
// Coarse graining ([coarse_graining], docs/models.md "Coarse graining"): every particle of the
// case stands for a cluster of k³ primary particles of diameter d/k (k = `scale` ≥ 1). The
// contact parameters follow the exact scaling of Feng & Owen (Comp. Part. Mech. 1 (2014) 159,
// "exact scaling laws", length scale k with density and stress unchanged: forces scale as k²,
// energies as k³), which for Hertz–Mindlin is Bierwisch, Kraft, Riedel & Moseler's rule
// (J. Mech. Phys. Solids 57 (2009) 10): density, Young's modulus, Poisson ratio, restitution and
// friction (static, dynamic, rolling) are kept; the JKR work of adhesion Γ is multiplied by k, so
// that the pull-off force 1.5 π Γ R* scales as k² like every other contact force and the work of
// separation (∝ Γ^(5/3) R*^(4/3) E*^(-2/3)) as k³ like the kinetic energy. The SJKR cohesion
// energy density (force = density × contact area) is kept: its force scales as k² unscaled.
#include "comminute/particles/material.hpp"

namespace comminute {

struct CoarseGraining {
  double scale = 1.0;  // k: coarse diameter / primary diameter
  // contact frequency per primary particle = contact frequency per coarse particle × k^exponent
  // (docs/models.md "Coarse graining": 0 for dense, shear-driven flow)
  double frequency_exponent = 0.0;

  bool active() const { return scale != 1.0; }
  // The parameters of a pair of coarse particles from those of the primary particles.
  PairInput scaled(const PairInput& primary) const;
  double primary_diameter(double coarse_diameter) const { return coarse_diameter / scale; }
  double primaries_per_particle() const { return scale * scale * scale; }
  // factor k^exponent from a coarse particle's contact frequency to a primary particle's
  double frequency_factor() const;
};

}  // namespace comminute
