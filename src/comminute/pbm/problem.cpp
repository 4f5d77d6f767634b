#include "comminute/pbm/problem.hpp"

#include "comminute/pbm/batch_grinding.hpp"
#include "comminute/pbm/method_of_classes.hpp"
#include "comminute/pbm/solve.hpp"

namespace comminute::pbm {

std::unique_ptr<Integrator> make_integrator(const TimeIntegration& t) {
  if (t.scheme == Scheme::rk4) return std::make_unique<Rk4>(t.time_step);
  return std::make_unique<DormandPrince>(t.adaptive);
}

Solution solve(const Problem& p) {
  Solution s;
  s.times = p.times;
  auto integrator = make_integrator(p.integration);
  if (p.method == Method::classes) {
    const MethodOfClasses moc(p.grid, *p.rate, *p.function, p.kumar_correction);
    s.rates = moc.rates();
    for (std::size_t i = 0; i < p.grid.classes(); ++i) s.rate_sizes.push_back(p.grid.pivot_size(i));
    s.number = solve(moc.system(), *integrator, p.initial_number, p.times);
  } else {
    // Austin's balance is in mass; particles of class i have the pivot volume.
    const BatchGrinding mill = BatchGrinding::from_models(p.grid, *p.rate, *p.function);
    s.rates = mill.rates();
    for (std::size_t i = 0; i < p.grid.classes(); ++i)
      s.rate_sizes.push_back(p.grid.size_edge(i + 1));  // Austin: S_i at the upper size
    Eigen::VectorXd m0 = p.initial_number;
    for (Eigen::Index i = 0; i < m0.size(); ++i)
      m0[i] *= p.grid.pivot_volume(static_cast<std::size_t>(i));
    s.number = solve(mill.system(), *integrator, m0, p.times);
    for (auto& y : s.number)
      for (Eigen::Index i = 0; i < y.size(); ++i)
        y[i] /= p.grid.pivot_volume(static_cast<std::size_t>(i));
  }
  s.stats = integrator->stats();
  return s;
}

}  // namespace comminute::pbm
