#pragma once
// The bilinear mixed-mode traction–separation law of Camanho & Dávila (NASA/TM-2002-211737) with
// the Benzeggagh–Kenane (BK) fracture criterion (Compos. Sci. Technol. 56 (1996) 439), one penalty
// stiffness K for both modes, maximum-stress initiation. Plain functions of the separations so
// that the law can be checked by hand.
namespace comminute::bonds {

struct CohesiveParameters {
  double penalty = 0;          // K, Pa/m
  double normal_strength = 0;  // N, Pa
  double shear_strength = 0;   // S, Pa
  double toughness_I = 0;      // G_Ic, J/m2
  double toughness_II = 0;     // G_IIc, J/m2
  double bk_exponent = 0;      // η
};

// The mode of one separation state (normal opening dn, shear slip magnitude ds >= 0).
struct MixedMode {
  double effective = 0;    // δ_m = sqrt(<δn>² + δs²), m
  double shear_ratio = 0;  // B = G_shear / G_T = β² / (1 + β²) (1 in compression or pure shear)
  double onset = 0;        // δ_m0, m
  double toughness = 0;    // G_c, J/m2
  double final = 0;        // δ_mf, m
};

MixedMode mixed_mode(const CohesiveParameters& p, double dn, double ds);
// Damage of the effective separation for this mode (not yet made irreversible), in [0, 1].
double bilinear_damage(const MixedMode& m);
// Energy dissipated per unit area (J/m2) at damage d along a path of this mode:
// D(d) = ½ d K δ_m0 δ_m(d), which is G_c at d = 1.
double dissipated_per_area(const CohesiveParameters& p, const MixedMode& m, double d);

}  // namespace comminute::bonds
