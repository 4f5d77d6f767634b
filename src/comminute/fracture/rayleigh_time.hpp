#pragma once
// Rayleigh time of a sphere (Li, Xu & Thornton, Powder Technol. 160 (2005) 219;
// docs/models.md eq. R1): the time a Rayleigh surface wave takes to cross it,
//   t_R = pi R sqrt(rho/G) / (0.1631 nu + 0.8766),
// the usual bound for the DEM time step.
namespace comminute::fracture {

// t_R (s) of a sphere of diameter d (m), density rho (kg/m3), shear modulus g (Pa) and Poisson
// ratio nu.
double rayleigh_time(double d, double density, double shear_modulus, double poisson_ratio);

}  // namespace comminute::fracture
