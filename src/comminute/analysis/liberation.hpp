#pragma once
// Liberation of mineral phases from particle compositions (docs/models.md eq. L1-L4; the standard
// definitions of mineral processing, e.g. King, Modeling and Simulation of Mineral Processing
// Systems, 2001, ch. 1). A particle's composition is the volume fraction phi_k of each phase
// (its texture's voxel fractions); with the phase densities rho_k its mass fractions are
// w_k = phi_k rho_k / sum_l phi_l rho_l.
#include <cstddef>
#include <vector>

namespace comminute::analysis {

struct ParticleComposition {
  double mass = 0;                      // kg
  double diameter = 0;                  // m
  std::vector<double> volume_fraction;  // phi_k, one per phase, summing to 1
};

// w_k of a particle.
std::vector<double> mass_fractions(const std::vector<double>& phi,
                                   const std::vector<double>& densities);

// Degree of liberation of `phase` at threshold theta: the mass of the phase in particles with
// phi_phase >= theta over the phase's total mass, L(theta) = sum_p m_p w_p 1[phi_p >= theta] /
// sum_p m_p w_p (eq. L1). 0 when the phase is absent.
double liberation_degree(const std::vector<ParticleComposition>& particles,
                         const std::vector<double>& densities, std::size_t phase, double theta);

// Composition classes of a liberation spectrum: {0}, (0, 10 %], (10, 20 %], ..., (80, 90 %],
// (90, 100 %), {100 %} of the phase's volume fraction: 12 classes.
inline constexpr std::size_t spectrum_classes = 12;
std::size_t spectrum_class(double phi);
// Lower and upper bound (-) of class c, for the table.
double spectrum_lower(std::size_t c);
double spectrum_upper(std::size_t c);

// Liberation spectrum (eq. L2): mass (kg) per size class (edges in m, ascending; particles outside
// the edges are left out) and composition class of `phase`; [size class][composition class].
std::vector<std::vector<double>> liberation_spectrum(
    const std::vector<ParticleComposition>& particles, std::size_t phase,
    const std::vector<double>& size_edges);

// One point of the ideal grade-recovery curve (eq. L3-L4): particles sorted by grade (mass
// fraction of the target phase), richest first; the concentrate holds the first k of them.
struct GradeRecoveryPoint {
  double yield = 0;            // -, concentrate mass over feed mass
  double grade = 0;            // -, target-phase mass fraction of the concentrate
  double recovery = 0;         // -, target-phase mass in the concentrate over that in the feed
  double gangue_recovery = 0;  // -, the same for every other phase together
};
std::vector<GradeRecoveryPoint> grade_recovery(const std::vector<ParticleComposition>& particles,
                                               const std::vector<double>& densities,
                                               std::size_t phase);

}  // namespace comminute::analysis
