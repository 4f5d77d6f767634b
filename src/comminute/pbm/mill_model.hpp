#pragma once
// Mechanistic mill models: a population balance that tracks more than the mass per size class
// (e.g. the fracture energies of the unbroken material) and is driven by a collision energy
// spectrum. [solver] method = "<name>" picks one by name from MillRegistry; its factory reads the
// [mill] table.
#include <Eigen/Dense>
#include <vector>

#include "comminute/pbm/collision_spectrum.hpp"
#include "comminute/pbm/model_context.hpp"
#include "comminute/pbm/ode.hpp"
#include "comminute/pbm/progeny_fractions.hpp"

namespace comminute::pbm {

// A fracture-energy distribution per size class, binned: mass (kg) in bin j of class i is
// mass(j, i); edges(j, i) and edges(j + 1, i) bound it (J/kg).
struct FractureEnergyBins {
  Eigen::MatrixXd edges;
  Eigen::MatrixXd mass;
};

class MillModel : public OdeSystem {
 public:
  // State from mass per class (virgin material) and back.
  virtual Eigen::VectorXd initial_state(const Eigen::VectorXd& mass) const = 0;
  virtual Eigen::VectorXd class_mass(const Eigen::VectorXd& state) const = 0;
  // Median fracture energy (J/kg) of each class's unbroken material.
  virtual Eigen::VectorXd median_fracture_energy(const Eigen::VectorXd& state) const = 0;
  // The whole binned distribution of the unbroken material (empty for models without one).
  virtual FractureEnergyBins fracture_energy_distribution(const Eigen::VectorXd&) const {
    return {};
  }
  // Breakage rate of virgin material per class (1/s).
  virtual std::vector<double> virgin_rates() const = 0;
  // Progeny (cumulative mass passing against d/D) of class i stressed by energy class k.
  virtual ProgenyFractions progeny(std::size_t i, std::size_t k) const = 0;
  virtual const CollisionSpectrum& spectrum() const = 0;
};

using MillRegistry = Registry<MillModel, const CaseTable&, const ModelContext&>;

}  // namespace comminute::pbm
