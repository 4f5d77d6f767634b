#pragma once
// A complete population-balance run in plain types (built from a case file by io/pbm_case), and
// its solution: the number of particles per class at each requested time.
#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "comminute/pbm/breakage_function.hpp"
#include "comminute/pbm/integrator.hpp"
#include "comminute/pbm/mill_model.hpp"
#include "comminute/pbm/selection_function.hpp"
#include "comminute/pbm/size_grid.hpp"

namespace comminute::pbm {

enum class Method { classes, batch_grinding, mill };
enum class Scheme { rk4, adaptive };

struct TimeIntegration {
  Scheme scheme = Scheme::adaptive;
  double time_step = 0.1;  // s, RK4 (the carbon-black study's Δt ≤ 0.1 s)
  DormandPrince::Options adaptive{};
};

struct Problem {
  explicit Problem(SizeGrid g) : grid(std::move(g)) {}
  SizeGrid grid;
  double density = 1000;           // kg/m³
  Eigen::VectorXd initial_number;  // particles per class
  std::shared_ptr<const SelectionFunction> rate;
  std::shared_ptr<const BreakageFunction> function;  // classes, batch_grinding
  std::shared_ptr<const MillModel> mill;             // mill (e.g. "ufrj")
  CollisionSpectrum mill_spectrum;                   // mill, for reports
  Method method = Method::classes;
  bool kumar_correction = true;
  TimeIntegration integration{};
  std::vector<double> times;  // s, non-decreasing
};

struct Solution {
  std::vector<double> times;
  std::vector<Eigen::VectorXd> number;  // particles per class at each time
  std::vector<double> rates;            // S_i used (1/s)
  std::vector<double> rate_sizes;       // size (m) each S_i was evaluated at
  IntegratorStats stats;
  std::vector<Eigen::VectorXd> median_fracture_energy;  // J/kg per class (ufrj only)
  std::vector<FractureEnergyBins> fracture_energy;      // whole distribution per time (ufrj)
};

std::unique_ptr<Integrator> make_integrator(const TimeIntegration& t);
Solution solve(const Problem& p);

}  // namespace comminute::pbm
