#pragma once
// Fragment sizes of one breakage event, drawn so that their masses add up to the parent's mass
// exactly (docs/models.md eq. P4). Stratified sampling: the size range is cut into classes at the
// t_n sizes d/2, d/4, d/10, d/25, d/50, d/75 and below d/75 on a sqrt2 series down to the minimum
// fragment size; each class receives the parent mass times its share of the progeny distribution
// and is filled with fragments whose sizes are drawn from the class's number distribution
// (mass density / x^3) until the class mass is used: the last fragment of a class closes its mass
// (two equal fragments when one would fall below the class, or one fragment a little above the
// class when halves would fall below it: no fragment is smaller than the minimum fragment size,
// even where the last class is narrower than 2^(1/3)); a class too small for one fragment
// passes its mass on to the next finer class. Mass below the minimum fragment size is fines.
#include <vector>

#include "comminute/core/rng.hpp"
#include "comminute/fracture/progeny_distribution.hpp"

namespace comminute::breakage {

using fracture::ProgenyDistribution;

enum class FinesRule {
  particles,  // fines become non-breakable particles of about the minimum size
  mass        // fines are booked as mass (per event and per material), not simulated
};

struct Fragment {
  double mass = 0;      // kg
  double diameter = 0;  // m, of a solid sphere of that mass at the parent's density
  bool fines = false;   // a fines particle (non-breakable)
};

struct Progeny {
  std::vector<Fragment> fragments;  // resolved fragments, largest first, then fines particles
  double fines_mass = 0;            // kg booked as mass (FinesRule::mass), 0 otherwise
};

// Parent of mass `mass` (kg), density `density` (kg/m3); fragments smaller than `min_size` (m)
// become fines by `rule`. Sum of fragment masses + fines_mass == mass (the last fragment is
// computed as the remainder, so the equality holds to one rounding).
Progeny draw_progeny(const ProgenyDistribution& dist, double mass, double density, double min_size,
                     FinesRule rule, Rng& rng);

// Diameter (m) of a solid sphere of mass m (kg) and density rho (kg/m3).
double sphere_diameter(double m, double rho);

}  // namespace comminute::breakage
