// Issue 8 point 1: a simulated drop-weight test gives back the t10(E) and t_n family the material
// was given. Many identical 10 mm particles side by side hit a steel plane at one speed v (no
// gravity: the specific impact energy is exactly E = v^2/2, of which the particle's share e of
// the contact work, models.md eq. F5, is its stressing energy e E). Fragments are free to break
// again. The product of the particles that broke is compared with the material's relation
// t10 = A [1 - exp(-b' e E / E50b(e E))] (models.md eq. P1, P1b) and t_n = 100 I_{t10/100}(alpha_n,
// beta_n) (eq. P2) for n = 2, 4.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <unordered_map>

#include "comminute/breakage/breakage_module.hpp"
#include "comminute/breakage/criteria/tavares.hpp"
#include "comminute/breakage/progeny/t10_progeny.hpp"
#include "comminute/contact/contact_law.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/engine/simulation.hpp"
#include "comminute/fracture/breaking_median.hpp"
#include "comminute/fracture/energy_share.hpp"
#include "comminute/geometry/plane_wall.hpp"

using namespace comminute;

namespace {

struct DropMaterial {
  const char* name;
  fracture::SizeEffect size_effect;  // absorbed basis
  double sigma, emax_ratio;
  fracture::T10Parameters t10;
};

// Two illustrative ores: different fracture energies, spreads, truncations and t10 relations.
DropMaterial ore_a() {
  fracture::T10Parameters t = breakage::T10Progeny::illustrative();
  t.a = 50.0;
  t.b_prime = 1.0;
  return {"ore_a", {100.0, 0.010, 1.0, 1.0}, 0.8, 5.0, t};
}
DropMaterial ore_b() {
  fracture::T10Parameters t = breakage::T10Progeny::illustrative();
  t.a = 55.0;
  t.b_prime = 0.6;
  return {"ore_b", {250.0, 0.005, 0.8, 1.0}, 0.6, std::numeric_limits<double>::infinity(), t};
}

constexpr double d_parent = 0.010;  // m
constexpr double rho = 2700.0;      // kg/m3
constexpr double young_ore = 5e9, nu_ore = 0.25, young_steel = 1.6e10, nu_steel = 0.3;

double share() {  // e of the ore against the steel plane, models.md eq. F5
  return fracture::energy_share(fracture::plane_strain_modulus(young_ore, nu_ore),
                                fracture::plane_strain_modulus(young_steel, nu_steel));
}

struct Product {
  std::size_t broken = 0;      // particles of the initial set that broke
  std::array<double, 3> t{};   // %, t2, t4, t10 of their product
  std::array<double, 3> se{};  // %, standard errors (spread between parents)
  double mean_stressing = 0;   // J/kg, mean stressing energy of the first-generation breakages
  double mean_fracture = 0;    // J/kg, mean energy absorbed at fracture
  std::size_t later_generations = 0;  // breakages of fragments
};

// side x side particles (a grid spaced 2 d) hit the plane at speed v; runs 250 us (contact of the
// parent ~50 us; a 400 us run gave the same products).
Product drop(const DropMaterial& dm, double v, int side, breakage::SizingEnergy sizing) {
  Simulation sim;
  sim.materials.add({"ore", rho, young_ore, nu_ore});
  sim.materials.add({"steel", 7800.0, young_steel, nu_steel});
  PairInput pi;
  pi.restitution = 0.5;  // the case-file default
  pi.friction = 0.5;
  sim.materials.set_pair(0, 0, pi);
  sim.materials.set_pair(0, 1, pi);
  const CaseFile contact = CaseFile::parse("");
  sim.law = ContactLawRegistry::create("hertz_mindlin", contact.root());
  sim.gravity = {0, 0, 0};
  auto plane = std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1});
  plane->material = 1;
  sim.walls.push_back(std::move(plane));
  for (int a = 0; a < side; ++a)
    for (int b = 0; b < side; ++b) {
      ParticleInit p;
      p.x = {2 * d_parent * a, 2 * d_parent * b, 0.5 * d_parent + 1e-5};
      p.v = {0, 0, -v};
      p.radius = 0.5 * d_parent;
      p.density = rho;
      sim.particles.add(p);
    }
  breakage::TavaresParameters tp;
  tp.size_effect = dm.size_effect;
  tp.sigma = dm.sigma;
  tp.emax_ratio = dm.emax_ratio;
  breakage::MaterialBreakage m;
  m.criterion = std::make_unique<breakage::Tavares>(tp);
  m.progeny = std::make_unique<breakage::T10Progeny>(dm.t10);
  m.min_breakable_size = 0.002;
  m.min_fragment_size = 0.001;  // no fragment below 1 mm (the time step resolves 1 mm)
  m.min_fragment_ratio = 0.1;   // fines below d/10: t10 is the fines' share plus fragments at d/10
  m.fines = breakage::FinesRule::mass;
  m.sizing_energy = sizing;
  std::vector<std::optional<breakage::MaterialBreakage>> mats;
  mats.emplace_back(std::move(m));
  auto mod =
      std::make_unique<breakage::BreakageModule>(std::move(mats), breakage::BreakageOptions{});
  const breakage::BreakageModule* module = mod.get();
  sim.modules.push_back(std::move(mod));
  sim.dt = 4e-7;  // 0.2 x the Rayleigh time of the smallest fragment (1 mm): 2.0e-6 s
  sim.setup();
  sim.run(static_cast<std::uint64_t>(250e-6 / sim.dt));

  // Ancestry: each fragment's parent; the product of an initial particle is everything below it.
  std::unordered_map<std::uint64_t, std::uint64_t> parent_of;
  for (const auto& f : module->fragment_log()) parent_of[f.fragment_id] = f.parent_id;
  auto root = [&](std::uint64_t id) {
    for (auto it = parent_of.find(id); it != parent_of.end(); it = parent_of.find(id))
      id = it->second;
    return id;
  };
  struct Tally {
    double mass = 0;
    std::array<double, 3> passing{};
  };
  std::map<std::uint64_t, Tally> by_root;
  Product out;
  const std::array<double, 3> sizes = {d_parent / 2, d_parent / 4, d_parent / 10};
  for (const auto& r : module->log()) {
    if (!r.broken) continue;
    Tally& t = by_root[root(r.parent_id)];
    if (r.generation == 0) {
      t.mass = r.mass;
      out.mean_stressing += r.stressing_energy;
      out.mean_fracture += r.specific_energy;
    } else {
      ++out.later_generations;
    }
    for (double& p : t.passing) p += r.fines_mass;  // fines are below d_parent/10
  }
  const auto& p = sim.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto it = by_root.find(root(p.id[i]));
    if (it == by_root.end() || p.id[i] == it->first) continue;  // an unbroken initial particle
    const double x = breakage::sphere_diameter(p.mass[i], rho);
    for (std::size_t k = 0; k < 3; ++k)
      if (x <= sizes[k] * (1 + 1e-12)) it->second.passing[k] += p.mass[i];
  }
  out.broken = by_root.size();
  if (out.broken == 0) return out;
  const double n = static_cast<double>(out.broken);
  out.mean_stressing /= n;
  out.mean_fracture /= n;
  for (std::size_t k = 0; k < 3; ++k) {
    double sum = 0, sum2 = 0, mass = 0;
    for (const auto& [id, t] : by_root) {
      const double tk = 100 * t.passing[k] / t.mass;
      sum += tk;
      sum2 += tk * tk;
      mass += t.mass;
    }
    double passing = 0;
    for (const auto& [id, t] : by_root) passing += t.passing[k];
    out.t[k] = 100 * passing / mass;
    const double mean = sum / n;
    out.se[k] = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / std::max(1.0, n - 1));
  }
  return out;
}

}  // namespace

// The product's t2, t4 and t10 agree with the material's relation within 10 % at stressing
// energies 0.5, 1.2 and 3 E50 for two materials (restitution 0.5, the case-file default). Why
// 10 % holds and is not a tuned band: the fragment sizes of one event reproduce t_n(t10) by
// construction (stratified sampling, eq. P4), the stressing energy is the particle's share of the
// impact energy from the first step of contact (printed: e E to 4 digits), so the product departs
// from the relation only through the re-breakage of fragments (+0 to +2 % here, printed). The
// standard error of each t_n (spread between parents / sqrt(n), printed) is below 2 % of t_n, so
// 10 % is at least five standard errors (at 0.5 E50 only 3-6 of 144 particles break, the dashpot
// taking part of the impact energy before the particle absorbs it, but nothing re-breaks there:
// the product is exact). Measured (2026-11-30): within +2.0 % everywhere.
// The rule before issue 8 (sizing_energy = "at_fracture": t10 at the energy absorbed at the
// instant of fracture) fails it: t10 -5.6, -11.8, -13.1 % (ore_a) and -5.0, -14.7, -25.3 % (ore_b)
// at 0.5, 1.2, 3 E50; t4 down to -21.5 %, t2 to -17.4 % (run with COMMINUTE_DROP_WEIGHT_OLD_RULE=1
// to print it beside the new rule).
TEST(DropWeight, ProductReproducesTheMaterialsT10AndTnFamily) {
  const double e = share();
  for (const DropMaterial& dm : {ore_a(), ore_b()}) {
    const fracture::FractureEnergyModel fem{dm.size_effect, dm.sigma, dm.emax_ratio};
    const fracture::FractureEnergyDistribution dist = fem.distribution(d_parent);
    const fracture::T10Model model(dm.t10);
    for (double ratio : {0.5, 1.2, 3.0}) {
      const double e_abs = ratio * dist.e50();    // J/kg, the particle's stressing energy
      const double v = std::sqrt(2 * e_abs / e);  // impact speed, E = v^2/2
      const double e50b = fracture::breaking_median(dist, e_abs);
      const double t10 = model.t10(e_abs, e50b);
      const auto tn = model.tn(t10);
      const std::array<double, 3> ref = {tn[0], tn[1], t10};
      // fewer particles break at low energy (the dashpot takes part of the impact energy before
      // the particle has absorbed it): more particles there
      const int side = ratio < 1 ? 12 : ratio < 2 ? 8 : 6;
      const Product now = drop(dm, v, side, breakage::SizingEnergy::stressing);
      const Product old = std::getenv("COMMINUTE_DROP_WEIGHT_OLD_RULE")
                              ? drop(dm, v, side, breakage::SizingEnergy::at_fracture)
                              : Product{};
      ASSERT_GE(now.broken, 3u) << dm.name << " " << ratio;
      std::printf(
          "%s E/E50 = %.1f (v = %.2f m/s, e E = %.1f J/kg): %zu broken, %zu later breakages, mean "
          "stressing %.1f, at fracture %.1f J/kg\n",
          dm.name, ratio, v, e_abs, now.broken, now.later_generations, now.mean_stressing,
          now.mean_fracture);
      const char* names[3] = {"t2", "t4", "t10"};
      for (std::size_t k = 0; k < 3; ++k) {
        std::printf(
            "   %-3s model %6.2f %%  stressing %6.2f %% (se %.2f, %+.1f %%)  at_fracture "
            "%6.2f %% (%+.1f %%)\n",
            names[k], ref[k], now.t[k], now.se[k], 100 * (now.t[k] / ref[k] - 1), old.t[k],
            100 * (old.t[k] / ref[k] - 1));
        EXPECT_NEAR(now.t[k] / ref[k], 1.0, 0.10)
            << dm.name << " E/E50 " << ratio << " " << names[k];
        EXPECT_LT(now.se[k], 0.02 * ref[k]) << "too few particles for the 10 % band";
      }
    }
  }
}
