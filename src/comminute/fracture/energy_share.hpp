#pragma once
// Stiffness partition of a contact's work between two bodies (docs/models.md eq. F4-F5): in a
// Hertz contact each body's share of the approach, and so of the work, is proportional to its
// compliance (Tavares, KONA Powder Part. J. 34 (2017) 106; EDEM and Rocky implementations of the
// UFRJ model).
namespace comminute::fracture {

// Plane-strain modulus k = E/(1 - nu^2) of a body (Pa), eq. F4.
double plane_strain_modulus(double youngs_modulus, double poisson_ratio);
// Share of a contact's work absorbed by body p touching body o: e = 1/(1 + k_p/k_o), eq. F5
// (two identical bodies: 1/2).
double energy_share(double k_p, double k_o);

}  // namespace comminute::fracture
