#include "comminute/engine/insertion.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "comminute/core/error.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute {

InsertionModule::InsertionModule(InsertionSpec spec, std::uint64_t seed)
    : spec_(std::move(spec)), rng_(seed, rng_stream::insertion + 16 * spec_.stream) {}

namespace {

// A hash grid of the particles near the region, grown as particles are placed.
class PlacementGrid {
 public:
  PlacementGrid(double cell) : cell_(cell) {}
  void add(std::uint32_t i, const Vec3& x) { cells_[key(x)].push_back(i); }
  template <class F>
  bool any_near(const Vec3& x, F&& overlaps) const {
    const auto c = coords(x);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          auto it = cells_.find(pack(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it == cells_.end()) continue;
          for (auto j : it->second)
            if (overlaps(j)) return true;
        }
    return false;
  }

 private:
  std::array<long, 3> coords(const Vec3& x) const {
    // clamped before the conversion: a far-away or non-finite point must not overflow the long
    auto c = [this](double v) {
      const double q = std::floor(v / cell_);
      return std::isfinite(q) ? static_cast<long>(std::clamp(q, -1e15, 1e15)) : 0L;
    };
    return {c(x.x), c(x.y), c(x.z)};
  }
  static std::uint64_t pack(long a, long b, long c) {
    auto u = [](long v) { return static_cast<std::uint64_t>(v + (1l << 20)) & 0x1FFFFF; };
    return (u(a) << 42) | (u(b) << 21) | u(c);
  }
  std::uint64_t key(const Vec3& x) const {
    auto c = coords(x);
    return pack(c[0], c[1], c[2]);
  }
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

}  // namespace

std::uint64_t InsertionModule::place(Simulation& sim, std::uint64_t n, int attempts_per_particle) {
  auto& p = sim.particles;
  Vec3 lo, hi;
  spec_.region.bounds(lo, hi);
  double rmax = 0.5 * spec_.size->max_diameter();
  // existing particles that can touch the region
  std::vector<std::uint32_t> near;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    bool in = true;
    for (int a = 0; a < 3; ++a)
      in = in && p.x[i][a] + p.radius[i] > lo[a] - 2 * rmax &&
           p.x[i][a] - p.radius[i] < hi[a] + 2 * rmax;
    if (in) {
      near.push_back(i);
      rmax = std::max(rmax, p.radius[i]);
    }
  }
  PlacementGrid grid(2 * rmax);
  for (auto i : near) grid.add(i, p.x[i]);
  std::vector<WallContact> touch;
  std::uint64_t placed = 0;
  for (std::uint64_t k = 0; k < n; ++k) {
    const double r = 0.5 * spec_.size->sample(rng_);
    bool ok = false;
    Vec3 x;
    for (int attempt = 0; attempt < attempts_per_particle && !ok; ++attempt) {
      x = spec_.region.sample(rng_, r);
      const bool hit_particle = grid.any_near(x, [&](std::uint32_t j) {
        const double s = r + p.radius[j];
        return norm2(x - p.x[j]) < s * s;
      });
      if (hit_particle) continue;
      bool hit_wall = false;
      for (const auto& w : sim.walls) {
        touch.clear();
        w->contacts(x, r, 0.0, touch);
        for (const auto& c : touch) hit_wall = hit_wall || c.overlap > 0;
      }
      ok = !hit_wall;
    }
    if (!ok) break;
    ParticleInit init;
    init.x = x;
    init.radius = r;
    init.density = spec_.density;
    init.material = spec_.material;
    init.v = spec_.velocity;
    if (spec_.velocity_spread > 0)
      for (int a = 0; a < 3; ++a) init.v[a] += spec_.velocity_spread * rng_.uniform(-1.0, 1.0);
    p.add(init);
    grid.add(static_cast<std::uint32_t>(p.size() - 1), x);
    ++placed;
  }
  if (placed > 0) sim.particles_changed();
  return placed;
}

void InsertionModule::setup(Simulation& sim) {
  if (spec_.pour) {
    next_time_ = spec_.start;
    return;
  }
  std::uint64_t n = spec_.count;
  if (n == 0)
    n = static_cast<std::uint64_t>(
        std::llround(spec_.volume_fraction * spec_.region.volume() / spec_.size->mean_volume()));
  inserted_ = place(sim, n, 2000);
  if (inserted_ < n)
    throw SimulationError(fmt::format(
        "{}: placed only {} of {} particles without overlap in the fill region (random sequential "
        "addition jams near a solid fraction of 0.3); lower the count/volume_fraction or enlarge "
        "the region",
        spec_.label, inserted_, n));
}

std::uint64_t pour_due(double rate, double start, double end, double time, std::uint64_t count) {
  const double t = std::min(time, end) - start;
  const double due_real = std::floor(rate * t + 1e-9);  // checked before the conversion
  auto due = std::isfinite(due_real) && due_real > 0
                 ? static_cast<std::uint64_t>(std::min(due_real, 1e18))
                 : std::uint64_t{0};
  return count > 0 ? std::min(due, count) : due;
}

void InsertionModule::pre_force(Simulation& sim) {
  if (!spec_.pour || sim.time < next_time_ || sim.time > spec_.end + spec_.interval) return;
  next_time_ += spec_.interval;
  const std::uint64_t due = pour_due(spec_.rate, spec_.start, spec_.end, sim.time, spec_.count);
  if (due <= inserted_) return;
  const std::uint64_t placed = place(sim, due - inserted_, 50);
  inserted_ += placed;
  if (inserted_ < due && !warned_full_) {
    fmt::print(stderr,
               "warning: {}: the pour region is full at t = {:.4g} s ({} of {} inserted); the "
               "rest follows as space frees up\n",
               spec_.label, sim.time, inserted_, due);
    warned_full_ = true;
  }
}

void InsertionModule::save(Archive& a) const {
  a.put(name() + "/rng", std::vector<std::uint64_t>(rng_.state().begin(), rng_.state().end()));
  a.put_value(name() + "/inserted", inserted_);
  a.put_value(name() + "/next_time", next_time_);
}

void InsertionModule::load(const Archive& a) {
  auto s = a.get<std::uint64_t>(name() + "/rng");
  Rng::State st{};
  if (s.size() != st.size())
    throw Error(fmt::format("checkpoint entry '{}/rng' holds {} words, a generator state {}",
                            name(), s.size(), st.size()));
  std::copy(s.begin(), s.end(), st.begin());
  rng_.set_state(st);
  inserted_ = a.get_value<std::uint64_t>(name() + "/inserted");
  next_time_ = a.get_value<double>(name() + "/next_time");
  if (!std::isfinite(next_time_))
    throw Error(fmt::format("checkpoint entry '{}/next_time' is not finite", name()));
}

}  // namespace comminute
