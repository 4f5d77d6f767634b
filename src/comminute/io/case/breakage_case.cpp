#include "comminute/io/case/breakage_case.hpp"

#include <fmt/format.h>

#include <cmath>

#include "comminute/analysis/size_distribution_observer.hpp"
#include "comminute/core/error.hpp"

namespace comminute::io {

namespace {

breakage::MaterialBreakage read_material(const CaseTable& b, const Material& mat) {
  breakage::MaterialBreakage m;
  const auto names = breakage::CriterionRegistry::names();
  const std::string criterion = b.choice("criterion", names);
  m.criterion = breakage::CriterionRegistry::create(criterion, b, mat);
  m.min_breakable_size = b.number("min_breakable_size", Limits::non_negative(), 0.0);
  m.min_fragment_size = b.number("min_fragment_size", Limits::non_negative(), 0.0);
  m.min_fragment_ratio = b.number("min_fragment_ratio", Limits{0.0, 1.0, false, true}, 0.05);
  m.fines = b.choice("fines", {"particles", "mass"}, "particles") == "mass"
                ? breakage::FinesRule::mass
                : breakage::FinesRule::particles;
  m.release_fraction = b.number("release_fraction", Limits::unit_interval(), 0.0);
  m.fragment_spin = b.choice("fragment_spin", {"parent", "angular_momentum"}, "parent") == "parent"
                        ? breakage::FragmentSpin::parent
                        : breakage::FragmentSpin::angular_momentum;
  m.force_measure = b.choice("force_measure", {"largest_contact", "contact_sum"},
                             "largest_contact") == "largest_contact"
                        ? breakage::ForceMeasure::largest_contact
                        : breakage::ForceMeasure::contact_sum;
  if (m.min_fragment_size <= 0 && m.min_breakable_size <= 0)
    b.fail("min_fragment_size",
           "set min_fragment_size or min_breakable_size (m) > 0: otherwise fragments shrink "
           "without limit and so does the time step");
  const CaseTable pr = b.table("progeny");
  m.progeny = breakage::ProgenyRegistry::create(
      pr.choice("model", breakage::ProgenyRegistry::names(), "t10"), pr);
  m.sizing_energy =
      pr.choice("sizing_energy", {"stressing", "at_fracture"}, "stressing") == "stressing"
          ? breakage::SizingEnergy::stressing
          : breakage::SizingEnergy::at_fracture;
  if (m.criterion->median_fracture_energy(1.0) <= 0)
    m.reference_energy = pr.number("reference_energy", Limits::positive());
  else
    m.reference_energy = pr.number("reference_energy", Limits::positive(), -1.0);
  return m;
}

}  // namespace

breakage::BreakageModule* add_breakage(const CaseTable& root, DemCase& dem) {
  Simulation& sim = *dem.sim;
  std::vector<std::optional<breakage::MaterialBreakage>> mats(sim.materials.size());
  bool any = false;
  const CaseTable materials = root.table("materials");
  for (std::size_t k = 0; k < sim.materials.size(); ++k) {
    const Material& mat = sim.materials.material(static_cast<std::uint16_t>(k));
    const auto t = materials.table(mat.name).optional_table("breakage");
    if (!t) continue;
    mats[k] = read_material(*t, mat);
    any = true;
  }
  const auto g = root.optional_table("breakage");
  if (!any) {
    if (g) g->fail("", "[breakage] is set but no material has a [materials.<name>.breakage] table");
    return nullptr;
  }
  breakage::BreakageOptions opt;
  analysis::SieveOptions sieves;
  double psd_interval = 0;
  if (g) {
    opt.placement_model = breakage::PlacementRegistry::create(
        g->choice("placement", breakage::PlacementRegistry::names(), "inside_parent"), *g);
    opt.growth_step = g->number("growth_step", Limits{0.0, 1.0, true, false}, 0.005);
    opt.growth_overlap_ratio =
        g->number("growth_overlap_ratio", Limits{0.0, 0.5, false, false}, 0.001);
    opt.growth_pushes = g->choice("growth", {"capped", "pushing"}, "capped") == "pushing";
    opt.event_end_steps = static_cast<int>(g->integer("event_end_steps", 1, 1000000, 20));
    opt.log_all_events = g->boolean("log_all_events", false);
    if (g->has("max_generations"))
      opt.max_generations = static_cast<std::uint32_t>(g->integer("max_generations", 1, 1000000));
    opt.replacement_interval = static_cast<int>(g->integer("replacement_interval", 1, 1000, 1));
    opt.output_interval = g->number("output_interval", Limits::non_negative(), 0.0);
    opt.time_step_floor = g->number("time_step_floor", Limits::unit_interval(), 0.1);
    opt.floor_rule = g->choice("floor_rule", {"fines", "density_scaling"}, "fines") == "fines"
                         ? breakage::FloorRule::fines
                         : breakage::FloorRule::density_scaling;
    psd_interval = g->number("size_distribution_interval", Limits::non_negative(), 0.0);
    if (g->has("sieves")) sieves.sieves = g->numbers("sieves", Limits::positive());
    sieves.bottom = g->number("sieve_bottom", Limits::non_negative(), 0.0);
  }
  auto module = std::make_unique<breakage::BreakageModule>(std::move(mats), opt);
  module->register_fields(sim.particles);
  breakage::BreakageModule* out = module.get();
  sim.modules.push_back(std::move(module));
  sim.modules.push_back(
      std::make_unique<analysis::SizeDistributionObserver>(out, sieves, psd_interval));
  return out;
}

}  // namespace comminute::io
