#include "comminute/io/case/texture_case.hpp"

#include <fmt/format.h>

#include "comminute/analysis/liberation_observer.hpp"
#include "comminute/breakage/breakage_module.hpp"
#include "comminute/breakage/texture/texture_generator.hpp"
#include "comminute/breakage/texture/tiff_stack.hpp"
#include "comminute/core/error.hpp"

namespace comminute::io {

namespace {

std::vector<breakage::texture::Phase> read_phases(const CaseTable& t) {
  std::vector<breakage::texture::Phase> phases;
  for (const CaseTable& p : t.tables("phases"))
    phases.push_back({p.string("name"), p.number("density", Limits::positive()),
                      p.number("relative_strength", Limits::positive(), 1.0)});
  if (phases.empty() || phases.size() > 255)
    t.fail("phases", "give 1 to 255 [[texture.phases]] tables (name, density, relative_strength)");
  return phases;
}

breakage::texture::TextureVolume read_volume(const CaseTable& t,
                                             std::vector<breakage::texture::Phase> phases,
                                             std::uint64_t seed) {
  using namespace breakage::texture;
  const auto gen = t.optional_table("generator");
  if (t.has("image") == gen.has_value())
    t.fail("image", "give exactly one of image (a raw voxel file) and [texture.generator]");
  if (!gen) {
    const auto path = t.input_file("image");
    const std::string ext = path.extension().string();
    const bool tiff = ext == ".tif" || ext == ".tiff" || ext == ".TIF" || ext == ".TIFF";
    if (tiff != t.has("voxel_size"))
      t.fail(tiff ? "image" : "voxel_size",
             tiff ? "a TIFF stack needs voxel_size (m): TIFF carries no physical size"
                  : "voxel_size is for TIFF stacks; a raw image has it in its header");
    try {
      if (tiff)
        return read_tiff_texture(path.string(), t.number("voxel_size", Limits::positive()),
                                 std::move(phases));
      return read_raw_texture(path.string(), std::move(phases));
    } catch (const InputError&) {
      throw;
    } catch (const Error& e) {
      t.fail("image", e.what());
    }
  }
  GeneratorSpec s;
  s.model = gen->choice("model", {"boolean_spheres", "lattice"}, "boolean_spheres") == "lattice"
                ? TextureModel::lattice
                : TextureModel::boolean_spheres;
  const auto size = gen->numbers("size", Limits{1.0, 4096.0});
  if (size.size() != 3) gen->fail("size", "needs three voxel counts [nx, ny, nz]");
  for (double v : size)
    if (v != std::floor(v)) gen->fail("size", "voxel counts must be integers");
  s.nx = static_cast<std::size_t>(size[0]);
  s.ny = static_cast<std::size_t>(size[1]);
  s.nz = static_cast<std::size_t>(size[2]);
  if (size[0] * size[1] * size[2] > 1024.0 * 1024.0 * 1024.0)
    gen->fail("size", "at most 1024^3 voxels (1 GiB) in all");
  s.voxel_size = gen->number("voxel_size", Limits::positive());
  for (const CaseTable& g : gen->tables("grains")) {
    GrainSpec grain;
    grain.phase = static_cast<std::uint8_t>(
        g.integer("phase", 1, static_cast<std::int64_t>(phases.size()) - 1));
    grain.volume_fraction = g.number("volume_fraction", Limits::open_unit_interval());
    grain.grain_radius = g.number("grain_radius", Limits::at_least(0.5 * s.voxel_size));
    grain.grain_radius_sigma = g.number("grain_radius_sigma", Limits::non_negative(), 0.0);
    s.grains.push_back(grain);
  }
  if (s.grains.empty()) gen->fail("grains", "give at least one [[texture.generator.grains]]");
  try {
    return generate_texture(s, std::move(phases), seed);
  } catch (const Error& e) {
    gen->fail("grains", e.what());
  }
}

}  // namespace

breakage::texture::TextureModule* add_texture(const CaseTable& root, DemCase& dem) {
  Simulation& sim = *dem.sim;
  const auto t = root.optional_table("texture");
  const auto lib = root.optional_table("liberation");
  if (!t) {
    if (lib) lib->fail("", "[liberation] needs a [texture] table");
    return nullptr;
  }
  auto phases = read_phases(*t);
  const std::size_t n_phases = phases.size();
  std::vector<double> f_rel;
  for (const auto& p : phases) f_rel.push_back(p.relative_strength);
  auto volume = std::make_shared<const breakage::texture::TextureVolume>(
      read_volume(*t, std::move(phases), sim.seed));
  breakage::texture::TextureOptions opt;
  const auto n = static_cast<std::size_t>(t->integer("resolution", 1, 256, 16));
  opt.density_from_phases = t->boolean("density_from_phases", true);
  opt.output_interval = t->number("output_interval", Limits::non_negative(), 0.0);
  opt.resolution.assign(sim.materials.size(), 0);
  std::vector<std::string> names;
  if (t->has("materials")) {
    names = t->strings("materials");
  } else {
    for (std::size_t k = 0; k < sim.materials.size(); ++k)
      names.push_back(sim.materials.material(static_cast<std::uint16_t>(k)).name);
  }
  const CaseTable materials = root.table("materials");
  breakage::BreakageModule* breakage = nullptr;
  for (auto& m : sim.modules)
    if (auto* b = dynamic_cast<breakage::BreakageModule*>(m.get())) breakage = b;
  for (const auto& name : names) {
    const int k = sim.materials.find(name);
    if (k < 0) t->fail("materials", fmt::format("no material '{}'", name));
    const auto own = materials.table(name).optional_table("texture");
    opt.resolution[static_cast<std::size_t>(k)] =
        own ? static_cast<std::size_t>(
                  own->integer("resolution", 1, 256, static_cast<std::int64_t>(n)))
            : n;
    // The composition criterion weighs the phases of this texture: same count, same strengths.
    const auto* mb = breakage ? breakage->material(static_cast<std::size_t>(k)) : nullptr;
    const auto* c = mb ? mb->criterion->relative_strength() : nullptr;
    if (c && *c != f_rel)
      t->fail("phases", fmt::format("material '{}': the criterion's relative_strength must list "
                                    "the {} phases' relative_strength in order",
                                    name, n_phases));
  }
  auto module = std::make_unique<breakage::texture::TextureModule>(volume, opt, sim.seed);
  module->register_fields(sim.particles);
  auto* out = module.get();
  if (breakage && opt.density_from_phases) breakage->set_fragment_mass_rule(out);
  sim.modules.push_back(std::move(module));
  if (lib) {
    analysis::LiberationOptions lo;
    lo.target_phase = static_cast<std::size_t>(lib->integer(
        "target_phase", 0, static_cast<std::int64_t>(n_phases) - 1, n_phases > 1 ? 1 : 0));
    if (lib->has("sieves")) lo.size_edges = lib->numbers("sieves", Limits::positive());
    lo.from_outlets = lib->choice("source", {"domain", "outlets"}, "domain") == "outlets";
    lo.window = lib->number("window", Limits::non_negative(), 0.0);
    lo.interval = lib->number("interval", Limits::non_negative(), 0.0);
    const OutletModule* outlets = nullptr;
    for (auto& m : sim.modules)
      if (auto* o = dynamic_cast<const OutletModule*>(m.get())) outlets = o;
    if (lo.from_outlets && !outlets)
      lib->fail("source", "'outlets' needs at least one outlet in the case");
    sim.modules.push_back(std::make_unique<analysis::LiberationObserver>(out, outlets, lo));
  }
  return out;
}

}  // namespace comminute::io
