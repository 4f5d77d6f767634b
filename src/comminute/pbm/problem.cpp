#include "comminute/pbm/problem.hpp"

#include "comminute/pbm/batch_grinding.hpp"
#include "comminute/pbm/method_of_classes.hpp"
#include "comminute/pbm/solve.hpp"

namespace comminute::pbm {

std::unique_ptr<Integrator> make_integrator(const TimeIntegration& t) {
  if (t.scheme == Scheme::rk4) return std::make_unique<Rk4>(t.time_step);
  return std::make_unique<DormandPrince>(t.adaptive);
}

namespace {
// Mass-based solvers: particles of class i have the pivot volume.
Eigen::VectorXd mass_of(const Problem& p, Eigen::VectorXd n) {
  for (Eigen::Index i = 0; i < n.size(); ++i)
    n[i] *= p.density * p.grid.pivot_volume(static_cast<std::size_t>(i));
  return n;
}
Eigen::VectorXd number_of(const Problem& p, Eigen::VectorXd m) {
  for (Eigen::Index i = 0; i < m.size(); ++i)
    m[i] /= p.density * p.grid.pivot_volume(static_cast<std::size_t>(i));
  return m;
}
}  // namespace

Solution solve(const Problem& p) {
  Solution s;
  s.times = p.times;
  auto integrator = make_integrator(p.integration);
  if (p.method == Method::classes) {
    const MethodOfClasses moc(p.grid, *p.rate, *p.function, p.kumar_correction);
    s.rates = moc.rates();
    for (std::size_t i = 0; i < p.grid.classes(); ++i) s.rate_sizes.push_back(p.grid.pivot_size(i));
    s.number = solve(moc.system(), *integrator, p.initial_number, p.times);
  } else if (p.method == Method::mill) {
    s.rates = p.mill->virgin_rates();
    for (std::size_t i = 0; i < p.grid.classes(); ++i) s.rate_sizes.push_back(p.grid.pivot_size(i));
    const auto states =
        solve(*p.mill, *integrator, p.mill->initial_state(mass_of(p, p.initial_number)), p.times);
    for (const auto& st : states) {
      s.number.push_back(number_of(p, p.mill->class_mass(st)));
      s.median_fracture_energy.push_back(p.mill->median_fracture_energy(st));
      s.fracture_energy.push_back(p.mill->fracture_energy_distribution(st));
    }
  } else {
    // Austin's balance is in mass; particles of class i have the pivot volume.
    const BatchGrinding mill = BatchGrinding::from_models(p.grid, *p.rate, *p.function);
    s.rates = mill.rates();
    for (std::size_t i = 0; i < p.grid.classes(); ++i)
      s.rate_sizes.push_back(p.grid.size_edge(i + 1));  // Austin: S_i at the upper size
    for (const auto& m : solve(mill.system(), *integrator, mass_of(p, p.initial_number), p.times))
      s.number.push_back(number_of(p, m));
  }
  s.stats = integrator->stats();
  return s;
}

}  // namespace comminute::pbm
