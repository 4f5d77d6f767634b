#include "comminute/analysis/bed_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "comminute/core/error.hpp"
#include "comminute/engine/contact_pipeline.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::analysis {

namespace {
constexpr std::array<const char*, 6> kComponents{"xx", "yy", "zz", "xy", "xz", "yz"};
}

BedStatistics::BedStatistics(BedStatisticsOptions options)
    : o_(std::move(options)), region_(o_.region) {
  if (o_.every == 0) throw Error("bed statistics: 'every' must be at least 1");
  if (o_.layers == 0) throw Error("bed statistics: at least one layer");
}

void BedStatistics::declare_contact_state(ContactPipeline& pipeline) {
  ContactStress& cs = pipeline.require_contact_stress();
  cs.set_threshold(o_.threshold);
  if (o_.force_chains) cs.want_contact_list();
}

void BedStatistics::setup(Simulation& sim) {
  if (o_.load_wall >= static_cast<int>(sim.walls.size()))
    throw Error("bed statistics: the load wall does not exist");
  if (!sim.contacts().stress())
    throw Error("bed statistics: the module was added after the contacts were assembled");
  register_fields(sim.particles);
}

void BedStatistics::restored(Simulation& sim) {
  register_fields(sim.particles);
}

void BedStatistics::register_fields(ParticleStore& p) {
  fields_.clear();
  for (const char* c : kComponents)
    fields_.push_back(p.add_field(fmt::format("bed.stress_{}", c), 0.0));
  fields_.push_back(p.add_field("bed.load_bearing", 0.0));
}

Cadence BedStatistics::output_cadence() const {
  Cadence c;
  c.steps = o_.every;
  return c;
}

void BedStatistics::pre_force(Simulation& sim) {
  sampling_ = (sim.step_count + 1) % o_.every == 0;
  if (sampling_) sim.contacts().stress()->arm();
}

std::pair<double, double> BedStatistics::coordination(const std::vector<std::uint32_t>& counts) {
  double ends = 0, n0 = 0, n1 = 0;
  for (std::uint32_t k : counts) {
    ends += k;
    n0 += k == 0;
    n1 += k == 1;
  }
  const double n = static_cast<double>(counts.size());
  const double z = n > 0 ? ends / n : 0.0;  // 2C/N: each contact has two ends
  const double rest = n - n0 - n1;
  return {z, rest > 0 ? (ends - n1) / rest : 0.0};  // Thornton 2000, Géotechnique 50, eq. 4
}

double BedStatistics::cross_section() const {
  const StatGridSpec& s = region_.spec();
  if (s.cylindrical) return std::numbers::pi * (s.r_max * s.r_max - s.r_min * s.r_min);
  return (s.hi.x - s.lo.x) * (s.hi.y - s.lo.y);
}

void BedStatistics::post_force(Simulation& sim) {
  if (!sampling_) return;
  const ParticleStore& p = sim.particles;
  const ContactStress& cs = *sim.contacts().stress();
  if (sampling_ && cs.moment.size() != p.size())
    throw Error(name() + ": the particles changed between the force loops and post_force");
  const StatGridSpec& s = region_.spec();
  struct Member {
    double height;  // m, of the centre above the region's bottom
    SymTensor moment;
  };
  std::vector<Member> members;
  std::vector<std::uint32_t> counts;
  SymTensor total{};
  double solid = 0, top = 0;
  const double bottom = s.cylindrical ? s.z_min : s.lo.z;
  for (std::size_t i = 0; i < p.owned(); ++i) {
    const double vol = 4.0 / 3.0 * std::numbers::pi * std::pow(p.radius[i], 3);
    SymTensor sigma = cs.moment[i];
    for (double& v : sigma) v /= vol;
    for (std::size_t k = 0; k < 6; ++k) sim.particles.field(fields_[k])[i] = sigma[k];
    sim.particles.field(fields_[6])[i] = cs.load_bearing[i];
    if (region_.cell_of(p.x[i]) == StatGrid::outside) continue;
    const Member m{(s.cylindrical ? dot(p.x[i] - s.origin, s.axis) : p.x[i].z) - bottom,
                   in_basis(cs.moment[i], region_.basis_at(p.x[i]))};
    for (std::size_t k = 0; k < 6; ++k) total[k] += m.moment[k];
    counts.push_back(cs.load_bearing[i]);
    solid += vol;
    top = std::max(top, m.height + p.radius[i]);
    members.push_back(m);
  }
  const double area = cross_section();
  const double h = top;  // the bed's height above the region's bottom
  const double vbed = area * h;
  const auto [z, zm] = coordination(counts);
  double ends = 0;
  for (auto k : counts) ends += k;
  Row r{};
  r.time = sim.time;
  r.particles = static_cast<double>(counts.size());
  r.contacts = ends / 2;
  r.coordination = z;
  r.mechanical_coordination = zm;
  r.bed_height = h;
  r.void_ratio = solid > 0 ? vbed / solid - 1 : 0.0;
  r.axial_stress = vbed > 0 ? -total[2] / vbed + 0.0 : 0.0;  // compression positive (no -0)
  r.mean_stress = vbed > 0 ? (total[0] + total[1] + total[2]) / (3 * vbed) : 0.0;
  if (o_.load_wall >= 0) {
    const Vec3 axis = s.cylindrical ? s.axis : Vec3{0, 0, 1};
    r.wall_axial_stress =
        std::abs(dot(sim.walls[static_cast<std::size_t>(o_.load_wall)]->force, axis)) / area;
  }
  rows_.push_back(r);
  // layers: equal slices of the bed's current height
  const std::size_t nl = o_.layers;
  std::vector<SymTensor> layer(nl, SymTensor{});
  std::vector<double> layer_count(nl, 0.0);
  for (const Member& m : members) {
    const double f = h > 0 ? m.height / h * static_cast<double>(nl) : 0.0;
    const std::size_t c = std::min(nl - 1, static_cast<std::size_t>(std::max(0.0, f)));
    for (std::size_t k = 0; k < 6; ++k) layer[c][k] += m.moment[k];
    layer_count[c] += 1;
  }
  for (std::size_t c = 0; c < nl; ++c) {
    SymTensor st = layer[c];
    for (double& v : st) v = vbed > 0 ? v / (vbed / static_cast<double>(nl)) : 0.0;
    layers_.push_back({sim.time, static_cast<double>(c), layer_count[c], st});
  }
  if (o_.force_chains) {
    chains_.clear();
    chain_ids_.clear();
    auto id = [&](std::int32_t slot) {
      return slot < 0 ? static_cast<double>(slot)
                      : static_cast<double>(p.id[sim.slot_owner(static_cast<std::size_t>(slot))]);
    };
    for (const ContactRecord& c : cs.contacts)
      if (c.normal_force > o_.threshold) {
        chains_.push_back(c);
        chain_ids_.push_back({id(static_cast<std::int32_t>(c.i)), id(c.j)});
      }
    chain_step_ = sim.step_count + 1;
  }
}

std::vector<Table> BedStatistics::tables(const Simulation&) const {
  Table t(o_.name, {{"time", "s"},
                    {"particles", "-"},
                    {"load_bearing_contacts", "-"},
                    {"coordination", "-"},
                    {"mechanical_coordination", "-"},
                    {"void_ratio", "-"},
                    {"bed_height", "m"},
                    {"axial_stress", "Pa"},
                    {"wall_axial_stress", "Pa"},
                    {"mean_stress", "Pa"}});
  for (const Row& r : rows_)
    t.add_row({r.time, r.particles, r.contacts, r.coordination, r.mechanical_coordination,
               r.void_ratio, r.bed_height, r.axial_stress, r.wall_axial_stress, r.mean_stress});
  const bool cyl = region_.spec().cylindrical;
  std::vector<Column> cols{{"time", "s"}, {"layer", "-"}, {"particles", "-"}};
  const std::array<const char*, 6> names =
      cyl ? std::array<const char*, 6>{"r_r",     "theta_theta", "axial_axial",
                                       "r_theta", "r_axial",     "theta_axial"}
          : kComponents;
  for (const char* c : names) cols.push_back({fmt::format("stress_{}", c), "Pa"});
  Table l(o_.name + "_layers", cols);
  for (const LayerRow& r : layers_) {
    std::vector<Cell> row{r.time, r.layer, r.particles};
    for (double v : r.stress) row.emplace_back(v);
    l.add_row(row);
  }
  return {t, l};
}

std::vector<Dataset> BedStatistics::datasets(const Simulation&) const {
  if (!o_.force_chains || chain_step_ == 0) return {};
  Dataset d;
  d.name = fmt::format("{0}_chains/{0}_chains_{1:09d}", o_.name, chain_step_);
  DatasetArray fn{"normal_force", 1, {}}, f{"force", 3, {}}, pi{"particle", 1, {}},
      pj{"partner", 1, {}};
  for (std::size_t k = 0; k < chains_.size(); ++k) {
    const ContactRecord& c = chains_[k];
    const auto at = static_cast<std::uint32_t>(d.points.size());
    d.points.push_back(c.xi);
    d.points.push_back(c.xj);
    d.lines.push_back({at, at + 1});
    fn.values.push_back(c.normal_force);
    f.values.insert(f.values.end(), {c.force.x, c.force.y, c.force.z});
    pi.values.push_back(chain_ids_[k][0]);
    pj.values.push_back(chain_ids_[k][1]);
  }
  d.cell_data = {fn, f, pi, pj};
  return {d};
}

void BedStatistics::save(Archive& a) const {
  a.put(o_.name + "/rows", rows_);
  a.put(o_.name + "/layers", layers_);
}

void BedStatistics::load(const Archive& a) {
  rows_ = a.get<Row>(o_.name + "/rows");
  layers_ = a.get<LayerRow>(o_.name + "/layers");
}

}  // namespace comminute::analysis
