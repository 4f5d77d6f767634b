#pragma once
// Units: SI everywhere (m, kg, s, N, J, Pa). Specific energies are mass-specific, J/kg.
namespace comminute::units {
inline constexpr double pi = 3.14159265358979323846;
inline constexpr double kWh_per_t = 3600.0;  // 1 kWh/t = 3600 J/kg
inline constexpr double mm = 1e-3;
inline constexpr double um = 1e-6;
inline double sphere_volume(double r) {
  return 4.0 / 3.0 * pi * r * r * r;
}
}  // namespace comminute::units
