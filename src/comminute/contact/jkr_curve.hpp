#pragma once
// The JKR force-overlap curve of two elastic spheres with adhesion (Johnson, Kendall & Roberts,
// Proc. R. Soc. Lond. A 324 (1971) 301, eqs. for P(a) and delta(a) in Maugis's notation):
//   F(a)     = 4 E* a^3 / (3 R*) - sqrt(8 pi Gamma E* a^3)      (repulsive > 0)
//   delta(a) = a^2 / R* - sqrt(2 pi Gamma a / E*)
// Gamma is the work of adhesion (J/m^2), so that the pull-off force under load control is
// F = -1.5 pi Gamma R* (at a^3 = 9 pi Gamma R*^2 / (8 E*), overlap -a^2/(3 R*)), and the curve at
// zero overlap gives -4/3 pi Gamma R*.
namespace comminute {

struct JkrPoint {
  double contact_radius = 0;  // a (m)
  double force = 0;           // F (N), > 0 repulsive
};

// The stable branch (d delta / d a > 0) at overlap `delta` (m): delta >= -3 a_c^2 / R*, the
// separation overlap under displacement control (a_c^3 = pi Gamma R*^2 / (8 E*)); below it the
// contact has separated and the force is 0. Newton's method on u = sqrt(a), where
// u^4 - sqrt(2 pi Gamma / E*) R* u - R* delta = 0 is convex, from a start above the root.
JkrPoint jkr_point(double delta, double effective_radius, double effective_modulus,
                   double work_of_adhesion);

// Integral of F from overlap 0 to `delta` along the curve (J): the elastic-plus-adhesive energy
// relative to the just-touching state.
double jkr_energy(double delta, double effective_radius, double effective_modulus,
                  double work_of_adhesion);

}  // namespace comminute
