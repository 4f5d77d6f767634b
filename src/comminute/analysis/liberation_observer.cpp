#include "comminute/analysis/liberation_observer.hpp"

#include <algorithm>

#include "comminute/analysis/sieve_analysis.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::analysis {

LiberationObserver::LiberationObserver(const breakage::texture::TextureModule* texture,
                                       const OutletModule* outlets, LiberationOptions opt)
    : texture_(texture), outlets_(outlets), opt_(std::move(opt)) {}

std::vector<double> LiberationObserver::densities() const {
  std::vector<double> rho;
  for (const auto& ph : texture_->volume().phases()) rho.push_back(ph.density);
  return rho;
}

void LiberationObserver::setup(Simulation& sim) {
  if (!opt_.size_edges.empty()) {
    std::sort(opt_.size_edges.begin(), opt_.size_edges.end());
    return;
  }
  double top = 0;
  for (double r : sim.particles.radius) top = std::max(top, 2 * r);
  opt_.size_edges = sqrt2_series(top > 0 ? top : 1e-3, 0.0);
  opt_.size_edges.push_back(0.0);  // the finest class reaches down to zero
  std::sort(opt_.size_edges.begin(), opt_.size_edges.end());
}

Cadence LiberationObserver::output_cadence() const {
  return Cadence::interval_or_steps(opt_.interval, 2000);
}

std::vector<ParticleComposition> LiberationObserver::particles(const Simulation& sim) const {
  const std::size_t phases = texture_->volume().phases().size();
  std::vector<ParticleComposition> out;
  if (opt_.from_outlets) {
    if (!outlets_ || outlets_->composition_fields() < phases) return out;
    const auto& log = outlets_->log();
    const auto& c = outlets_->compositions();
    const std::size_t w = outlets_->composition_fields();
    const double from = opt_.window > 0 ? sim.time - opt_.window : -1.0;
    for (std::size_t n = 0; n < log.size(); ++n) {
      if (!(log[n].time > from)) continue;
      std::vector<double> phi(c.begin() + static_cast<std::ptrdiff_t>(n * w),
                              c.begin() + static_cast<std::ptrdiff_t>(n * w + phases));
      out.push_back({log[n].mass, log[n].diameter, std::move(phi)});
    }
    return out;
  }
  const auto& p = sim.particles;
  if (!p.has_field("texture.owner")) return out;
  const auto& owner = p.field(p.field_index("texture.owner"));
  std::vector<const std::vector<double>*> comp;
  for (std::size_t k = 0; k < phases; ++k)
    comp.push_back(&p.field(p.field_index("composition." + std::to_string(k))));
  const std::vector<double>* target = p.has_field("breakage.target_radius")
                                          ? &p.field(p.field_index("breakage.target_radius"))
                                          : nullptr;
  for (std::size_t i = 0; i < p.owned(); ++i) {
    if (owner[i] == 0) continue;  // no texture (untextured material)
    std::vector<double> phi(phases);
    for (std::size_t k = 0; k < phases; ++k) phi[k] = (*comp[k])[i];
    const double r = std::max(p.radius[i], target ? (*target)[i] : 0.0);
    out.push_back({p.physical_mass(i), 2 * r, std::move(phi)});
  }
  return out;
}

void LiberationObserver::sample(const Simulation& sim) {
  const auto all = particles(sim);
  const auto rho = densities();
  const std::size_t classes = opt_.size_edges.size() - 1;
  auto add = [&](const std::vector<ParticleComposition>& ps, std::int32_t size_class) {
    for (std::size_t k = 0; k < rho.size(); ++k) {
      double m = 0;
      for (const auto& q : ps) m += q.mass * mass_fractions(q.volume_fraction, rho)[k];
      rows_.push_back({sim.time, size_class, static_cast<std::uint32_t>(k), m,
                       liberation_degree(ps, rho, k, 1.0), liberation_degree(ps, rho, k, 0.95),
                       liberation_degree(ps, rho, k, 0.90)});
    }
  };
  add(all, -1);
  for (std::size_t s = 0; s < classes; ++s) {
    std::vector<ParticleComposition> in;
    for (const auto& q : all)
      if (q.diameter > opt_.size_edges[s] && q.diameter <= opt_.size_edges[s + 1]) in.push_back(q);
    if (!in.empty()) add(in, static_cast<std::int32_t>(s));
  }
}

std::vector<Table> LiberationObserver::tables(const Simulation& sim) const {
  const auto& phases = texture_->volume().phases();
  Table lib("liberation", {{"time", "s"},
                           {"size_lower", "m"},
                           {"size_upper", "m"},
                           {"phase", "-"},
                           {"phase_mass", "kg"},
                           {"liberation_100", "-"},
                           {"liberation_95", "-"},
                           {"liberation_90", "-"}});
  for (const auto& r : rows_) {
    const bool whole = r.size_class < 0;
    const auto s = static_cast<std::size_t>(whole ? 0 : r.size_class);
    lib.add_row({r.time, whole ? opt_.size_edges.front() : opt_.size_edges[s],
                 whole ? opt_.size_edges.back() : opt_.size_edges[s + 1], phases[r.phase].name,
                 r.mass, r.l100, r.l95, r.l90});
  }
  const auto now = particles(sim);
  const auto rho = densities();
  const std::size_t target = opt_.target_phase;
  Table spec("liberation_spectrum", {{"time", "s"},
                                     {"size_lower", "m"},
                                     {"size_upper", "m"},
                                     {"fraction_lower", "-"},
                                     {"fraction_upper", "-"},
                                     {"mass", "kg"},
                                     {"mass_fraction", "-"}});
  const auto m = liberation_spectrum(now, target, opt_.size_edges);
  for (std::size_t s = 0; s < m.size(); ++s) {
    double total = 0;
    for (double x : m[s]) total += x;
    for (std::size_t c = 0; c < spectrum_classes; ++c)
      spec.add_row({sim.time, opt_.size_edges[s], opt_.size_edges[s + 1], spectrum_lower(c),
                    spectrum_upper(c), m[s][c], total > 0 ? m[s][c] / total : 0.0});
  }
  Table gr(
      "grade_recovery",
      {{"time", "s"}, {"yield", "-"}, {"grade", "-"}, {"recovery", "-"}, {"gangue_recovery", "-"}});
  // At most ~1000 points of the curve: every k-th particle, and always the last one.
  const auto curve = grade_recovery(now, rho, target);
  const std::size_t every = curve.size() / 1000 + 1;
  for (std::size_t k = 0; k < curve.size(); ++k)
    if (k % every == every - 1 || k + 1 == curve.size()) {
      const auto& p = curve[k];
      gr.add_row({sim.time, p.yield, p.grade, p.recovery, p.gangue_recovery});
    }
  return {lib, spec, gr};
}

void LiberationObserver::save(Archive& a) const {
  a.put("liberation/size_edges", opt_.size_edges);
  a.put("liberation/rows", rows_);
}

void LiberationObserver::load(const Archive& a) {
  opt_.size_edges = a.get<double>("liberation/size_edges");
  rows_ = a.get<Row>("liberation/rows");
}

}  // namespace comminute::analysis
