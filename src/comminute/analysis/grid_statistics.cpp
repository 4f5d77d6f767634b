#include "comminute/analysis/grid_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "comminute/analysis/stress_measures.hpp"
#include "comminute/core/error.hpp"
#include "comminute/engine/contact_pipeline.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::analysis {

namespace {
// field offsets within a cell's accumulators
constexpr std::size_t kCount = 0, kMass = 1, kVolume = 2, kMv = 3, kMvv = 6, kMoment = 12,
                      kParticle = 18, kStarts = 24;
void add(double* a, const SymTensor& t, double s) {
  for (std::size_t k = 0; k < 6; ++k) a[k] += s * t[k];
}
SymTensor tensor(const double* a, double s) {
  SymTensor t;
  for (std::size_t k = 0; k < 6; ++k) t[k] = s * a[k];
  return t;
}
}  // namespace

GridStatistics::GridStatistics(GridStatisticsOptions options)
    : o_(std::move(options)), grid_(o_.grid), acc_(grid_.size() * kFields, 0.0) {
  if (o_.every == 0) throw Error("grid statistics: 'every' must be at least 1");
}

void GridStatistics::declare_contact_state(ContactPipeline& pipeline) {
  pipeline.require_contact_stress();
}

void GridStatistics::setup(Simulation& sim) {
  if (o_.rotate_with >= static_cast<int>(sim.walls.size()))
    throw Error("grid statistics: the wall to rotate with does not exist");
  if (!sim.contacts().stress())
    throw Error("grid statistics: the module was added after the contacts were assembled");
}

bool GridStatistics::in_window(const Simulation& sim) const {
  return sim.time >= o_.start && sim.time <= o_.end;
}

void GridStatistics::pre_force(Simulation& sim) {
  sampling_ = in_window(sim) && steps_ % o_.every == 0;
  if (sampling_) sim.contacts().stress()->arm();
}

void GridStatistics::post_force(Simulation& sim) {
  if (!in_window(sim)) return;
  ++steps_;
  window_time_ += sim.dt;
  const ParticleStore& p = sim.particles;
  const ContactStress& cs = *sim.contacts().stress();
  if (sampling_ && cs.moment.size() != p.size())
    throw Error(name() + ": the particles changed between the force loops and post_force");
  auto count_start = [&](std::size_t slot) {
    const std::size_t c = grid_.cell_of(p.x[sim.slot_owner(slot)]);
    if (c != StatGrid::outside) cell(c)[kStarts] += 1;
  };
  for (const ContactStart& s : cs.starts) {
    count_start(s.i);
    if (s.j >= 0) count_start(static_cast<std::size_t>(s.j));
  }
  if (!sampling_) return;
  ++samples_;
  const double four_thirds_pi = 4.0 / 3.0 * std::numbers::pi;
  for (std::size_t i = 0; i < p.owned(); ++i) {
    const std::size_t c = grid_.cell_of(p.x[i]);
    if (c == StatGrid::outside) continue;
    double* a = cell(c);
    const auto e = grid_.basis_at(p.x[i]);
    const double m = p.mass[i], vol = four_thirds_pi * p.radius[i] * p.radius[i] * p.radius[i];
    const Vec3 v = in_basis(p.v[i], e);
    const SymTensor moment = in_basis(cs.moment[i], e);
    a[kCount] += 1;
    a[kMass] += m;
    a[kVolume] += vol;
    a[kMv] += m * v.x;
    a[kMv + 1] += m * v.y;
    a[kMv + 2] += m * v.z;
    SymTensor vv{};
    add_sym_outer(vv, v, v, 1.0);
    add(a + kMvv, vv, m);
    add(a + kMoment, moment, 1.0);
    add(a + kParticle, moment, m / vol);
  }
}

void GridStatistics::end_of_step(Simulation& sim) {
  if (o_.rotate_with < 0) return;
  const auto& k = sim.walls[static_cast<std::size_t>(o_.rotate_with)]->kinematics;
  grid_.turn(dot(k.angular_velocity, grid_.spec().axis) * sim.dt);
}

GridStatistics::CellAverage GridStatistics::average(std::size_t c) const {
  CellAverage r;
  const double* a = cell(c);
  if (samples_ == 0) return r;
  const double n = static_cast<double>(samples_), vcell = grid_.volume(c);
  r.particles = a[kCount] / n;
  r.solid_fraction = a[kVolume] / (n * vcell);
  if (a[kMass] > 0) {
    r.velocity = Vec3{a[kMv], a[kMv + 1], a[kMv + 2]} / a[kMass];
    // Σ m v'⊗v' = Σ m v⊗v − M u⊗u with u the mass-weighted mean velocity
    SymTensor fluct = tensor(a + kMvv, 1.0);
    add_sym_outer(fluct, r.velocity, r.velocity, -a[kMass]);
    r.contact_stress = tensor(a + kMoment, 1.0 / (n * vcell));
    r.stress = r.contact_stress;
    for (std::size_t k = 0; k < 6; ++k) r.stress[k] -= fluct[k] / (n * vcell);
    r.particle_stress = tensor(a + kParticle, 1.0 / a[kMass]);
  }
  if (r.particles > 0 && window_time_ > 0)
    r.contact_frequency = a[kStarts] / (r.particles * window_time_);
  return r;
}

std::vector<Table> GridStatistics::tables(const Simulation&) const {
  const bool cyl = grid_.spec().cylindrical;
  const std::array<const char*, 3> ax = cyl ? std::array<const char*, 3>{"r", "theta", "axial"}
                                            : std::array<const char*, 3>{"x", "y", "z"};
  const std::array<std::pair<int, int>, 6> comp{{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}};
  std::vector<Column> cols{{"cell", "-"}, {"i", "-"}, {"j", "-"}, {"k", "-"}};
  for (int d = 0; d < 3; ++d)
    cols.push_back({fmt::format("centre_{}", ax[d]), cyl && d == 1 ? "rad" : "m"});
  cols.push_back({"volume", "m3"});
  cols.push_back({"particles", "-"});
  cols.push_back({"solid_fraction", "-"});
  for (int d = 0; d < 3; ++d) cols.push_back({fmt::format("velocity_{}", ax[d]), "m/s"});
  for (const auto& [a, b] : comp) cols.push_back({fmt::format("stress_{}_{}", ax[a], ax[b]), "Pa"});
  for (const char* c : {"stress_1", "stress_2", "stress_3", "mean_stress", "tau_max",
                        "kinetic_pressure", "particle_mean_stress", "particle_tau_max"})
    cols.push_back({c, "Pa"});
  cols.push_back({"contact_frequency", "1/s"});
  cols.push_back({"primary_contact_frequency", "1/s"});
  Table t(o_.name, cols);
  for (std::size_t c = 0; c < grid_.size(); ++c) {
    const CellAverage r = average(c);
    const auto id = grid_.index(c);
    const auto x = grid_.centre(c);
    const StressMeasures s = stress_measures(r.stress), sp = stress_measures(r.particle_stress);
    double kin = 0;
    for (int k = 0; k < 3; ++k) kin -= (r.stress[k] - r.contact_stress[k]) / 3;
    std::vector<Cell> row{static_cast<double>(c),
                          static_cast<double>(id[0]),
                          static_cast<double>(id[1]),
                          static_cast<double>(id[2]),
                          x[0],
                          x[1],
                          x[2],
                          grid_.volume(c),
                          r.particles,
                          r.solid_fraction,
                          r.velocity.x,
                          r.velocity.y,
                          r.velocity.z};
    for (double v : r.stress) row.emplace_back(v);
    for (double v :
         {s.principal[0], s.principal[1], s.principal[2], s.mean, s.tau_max, kin, sp.mean,
          sp.tau_max, r.contact_frequency, o_.primary_frequency_factor * r.contact_frequency})
      row.emplace_back(v);
    t.add_row(row);
  }
  // ṅ(σ): contacts begun in cells whose particle pressure falls in each bin, per particle of the
  // grid, per second, per Pa of the bin (its integral is the mean contact frequency per particle)
  std::vector<double> pressure(grid_.size()), starts(grid_.size());
  double top = o_.spectrum_max, particles = 0;
  for (std::size_t c = 0; c < grid_.size(); ++c) {
    const CellAverage r = average(c);
    const auto& sp = r.particle_stress;
    pressure[c] = std::max(0.0, -(sp[0] + sp[1] + sp[2]) / 3);
    starts[c] = cell(c)[kStarts];
    particles += r.particles;
    if (o_.spectrum_max <= 0) top = std::max(top, pressure[c]);
  }
  const std::size_t nb = o_.spectrum_bins;
  Table spec(o_.name + "_spectrum",
             {{"stress", "Pa"}, {"frequency", "1/(s Pa)"}, {"primary_frequency", "1/(s Pa)"}});
  if (top > 0 && particles > 0 && window_time_ > 0) {
    const double width = top / static_cast<double>(nb);
    std::vector<double> bins(nb, 0.0);
    for (std::size_t c = 0; c < grid_.size(); ++c)
      bins[std::min(nb - 1, static_cast<std::size_t>(pressure[c] / width))] += starts[c];
    for (std::size_t b = 0; b < nb; ++b) {
      const double n = bins[b] / (particles * window_time_ * width);
      spec.add_row({(static_cast<double>(b) + 0.5) * width, n, o_.primary_frequency_factor * n});
    }
  }
  return {t, spec};
}

std::vector<Dataset> GridStatistics::datasets(const Simulation&) const {
  Dataset d;
  d.name = o_.name;
  d.cells = grid_.spec().cells;
  d.points = grid_.corners();
  const std::size_t n = grid_.size();
  DatasetArray phi{"solid_fraction", 1, {}}, count{"particles", 1, {}}, vel{"velocity", 3, {}},
      stress{"stress", 9, {}}, principal{"principal_stress", 3, {}}, mean{"mean_stress", 1, {}},
      tau{"tau_max", 1, {}}, pmean{"particle_mean_stress", 1, {}}, freq{"contact_frequency", 1, {}};
  for (std::size_t c = 0; c < n; ++c) {
    const CellAverage r = average(c);
    const StressMeasures s = stress_measures(r.stress);
    const auto& t = r.stress;
    phi.values.push_back(r.solid_fraction);
    count.values.push_back(r.particles);
    vel.values.insert(vel.values.end(), {r.velocity.x, r.velocity.y, r.velocity.z});
    stress.values.insert(stress.values.end(),
                         {t[0], t[3], t[4], t[3], t[1], t[5], t[4], t[5], t[2]});
    principal.values.insert(principal.values.end(), s.principal.begin(), s.principal.end());
    mean.values.push_back(s.mean);
    tau.values.push_back(s.tau_max);
    const auto& sp = r.particle_stress;
    pmean.values.push_back((sp[0] + sp[1] + sp[2]) / 3);
    freq.values.push_back(r.contact_frequency);
  }
  d.cell_data = {phi, count, vel, stress, principal, mean, tau, pmean, freq};
  return {d};
}

void GridStatistics::save(Archive& a) const {
  const std::string k = o_.name + "/";
  a.put(k + "sums", acc_);
  a.put(k + "state", std::vector<double>{static_cast<double>(samples_), static_cast<double>(steps_),
                                         window_time_, grid_.angle()});
}

void GridStatistics::load(const Archive& a) {
  const std::string k = o_.name + "/";
  auto sums = a.get<double>(k + "sums");
  const auto state = a.get<double>(k + "state");
  if (sums.size() != acc_.size() || state.size() != 4)
    throw Error("checkpoint entry '" + k + "sums' does not match the grid of this case");
  acc_ = std::move(sums);
  samples_ = static_cast<std::uint64_t>(state[0]);
  steps_ = static_cast<std::uint64_t>(state[1]);
  window_time_ = state[2];
  grid_.set_angle(state[3]);
}

}  // namespace comminute::analysis
