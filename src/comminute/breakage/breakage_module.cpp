#include "comminute/breakage/breakage_module.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "comminute/breakage/parallel_filter.hpp"
#include "comminute/engine/simulation.hpp"
#include "comminute/engine/time_step_policy.hpp"

namespace comminute::breakage {

namespace {
BreakageOptions with_placement(BreakageOptions opt) {
  if (!opt.placement_model)
    opt.placement_model = std::make_shared<InsideParentPlacement>(opt.placement);
  return opt;
}
}  // namespace

BreakageModule::BreakageModule(std::vector<std::optional<MaterialBreakage>> per_material,
                               BreakageOptions opt)
    : materials_(std::move(per_material)),
      opt_(with_placement(std::move(opt))),
      events_(opt_.event_end_steps, opt_.log_all_events, opt_.max_generations),
      growth_(opt_.growth_overlap_ratio, opt_.growth_step, opt_.growth_pushes),
      replacement_(opt_.placement_model, opt_.replacement_interval) {}

BreakageModule::~BreakageModule() = default;

void BreakageModule::register_fields(ParticleStore& p) {
  for (auto& m : materials_)
    if (m) m->criterion->attach(p);
  fields_.initialized = p.add_field("breakage.initialized", 0.0);  // 1 once strength is drawn
  fields_.generation = p.add_field("breakage.generation", 0.0);
  fields_.parent_id = p.add_field("breakage.parent_id", 0.0);   // ids start at 1
  fields_.target = p.add_field("breakage.target_radius", 0.0);  // m, final radius while growing
  if (opt_.time_step_floor > 0 && opt_.floor_rule == FloorRule::density_scaling)
    fields_.mass_scale = p.add_field(ParticleStore::mass_scale_field, 1.0);
  events_.register_fields(p);
}

void BreakageModule::setup(Simulation& sim) {
  strength_rng_ = Rng(sim.seed, rng_stream::breakage);
  configure(sim);
  auto& p = sim.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.field(fields_.initialized)[i] == 0) initialize_particle(sim, i, strength_rng_);
}

void BreakageModule::configure(Simulation& sim) {
  auto& p = sim.particles;
  register_fields(p);
  const std::size_t n_materials = sim.materials.size();
  materials_.resize(std::max(materials_.size(), n_materials));
  events_.configure(sim);
  ledger_.set_materials(n_materials);
  growth_.recount(p);
}

void BreakageModule::initialize_particle(Simulation& sim, std::size_t i, Rng& rng) const {
  auto& p = sim.particles;
  p.field(fields_.initialized)[i] = 1;
  const auto& m = materials_[p.material[i]];
  if (!m) return;
  const double target = p.field(fields_.target)[i];
  m->criterion->initialize(p, i, 2 * (target > 0 ? target : p.radius[i]), rng);
}

void BreakageModule::post_force(Simulation& sim) {
  if (growth_.pending() > 0) growth_.grow(sim, fields_.target, ledger_);
  events_.gather_loads(sim);
  auto& p = sim.particles;
  // particles inserted by other modules draw strength (in slot order: one RNG stream)
  const auto& initialized = p.field(fields_.initialized);
  for (const std::uint32_t i :
       parallel_filter(p.owned(), [&](std::size_t s) { return initialized[s] == 0; }))
    initialize_particle(sim, i, strength_rng_);
  events_.assess(sim, materials_, fields_, log_,
                 [&](std::size_t i, const EventRecord& r) { replacement_.enqueue(p.id[i], r); });
}

double BreakageModule::rayleigh_floor(const Simulation& sim) const {
  // No scaling when the step is fixed by the case ([simulation] time_step): it does not follow
  // the particles, so nothing to protect.
  if (!(opt_.time_step_floor > 0) || !sim.step_control) return 0;
  const TimeStepControl& c = *sim.step_control;
  return opt_.time_step_floor * c.ceiling() / c.fraction();
}

Replacement::Context BreakageModule::replacement_context(Simulation& sim) {
  return {materials_,
          fields_,
          ledger_,
          log_,
          growth_,
          rayleigh_floor(sim),
          opt_.floor_rule,
          [this, &sim](std::size_t s, Rng& rng) {
            events_.clear(sim.particles, s);
            initialize_particle(sim, s, rng);
          },
          mass_rule_};
}

void BreakageModule::end_of_step(Simulation& sim) {
  replacement_.end_of_step(sim, replacement_context(sim));
}

void BreakageModule::save(Archive& a) const {
  const auto s = strength_rng_.state();
  a.put("breakage/strength_rng", std::vector<std::uint64_t>(s.begin(), s.end()));
  log_.save(a);
  ledger_.save(a);
  series_.save(a);
}

void BreakageModule::load(const Archive& a) {
  auto to_state = [&a](const std::string& entry) {
    const auto v = a.get<std::uint64_t>(entry);
    Rng::State s{};
    if (v.size() != s.size())
      throw Error(fmt::format("checkpoint entry '{}' holds {} words, a generator state {}", entry,
                              v.size(), s.size()));
    std::copy_n(v.begin(), s.size(), s.begin());
    return s;
  };
  strength_rng_.set_state(to_state("breakage/strength_rng"));
  log_.load(a);
  ledger_.load(a);
  series_.load(a);
}

void BreakageModule::announce_sizes(std::vector<ParticleSize>& sizes, const Simulation& sim) const {
  for (std::size_t k = 0; k < materials_.size(); ++k) {
    if (!materials_[k]) continue;
    const double d =
        std::max(materials_[k]->min_fragment_size,
                 materials_[k]->min_fragment_ratio * materials_[k]->min_breakable_size);
    const auto m = static_cast<std::uint16_t>(k);
    sizes.push_back({0.5 * d, m,
                     fmt::format("the smallest fragment ({:.4g} m) material '{}' can produce", d,
                                 sim.materials.material(m).name),
                     true});
  }
}

void BreakageModule::restored(Simulation& sim) {
  configure(sim);  // modules are not set up again after a checkpoint
}

}  // namespace comminute::breakage
