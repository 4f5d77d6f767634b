#include "comminute/engine/wall_candidates.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <fmt/format.h>

#include "comminute/core/error.hpp"
#include "comminute/core/parallel.hpp"
#include "comminute/engine/parallel_threshold.hpp"
#include "comminute/neighbor/neighbor_list.hpp"

namespace comminute {

double WallCandidates::largest_travel() const {
  double travel = 0;
  for (double t : travel_) travel = std::max(travel, t);
  return travel;
}

bool WallCandidates::add(const ParticleStore& p, const Walls& walls, std::uint32_t i,
                         std::uint32_t w, const Vec3& x, double r, double skin,
                         std::vector<std::uint32_t>& elements, std::vector<WallContact>& found,
                         std::vector<WallContactRecord>& into) const {
  found.clear();
  elements.clear();
  // a wall with elements lists those within the skin (kept for the force loop's look-ups) and
  // finds the candidate features among them
  const bool listed = walls[w]->near_elements(x, r, skin, elements);
  const bool near = (listed ? walls[w]->contacts_among(x, r, skin, elements, found)
                            : walls[w]->contacts(x, r, skin, found)) > 0;
  if (!near && !full_scan_[w]) return listed;
  // one candidate per (particle, wall, feature); a full-scan wall keeps one per particle
  if (found.empty()) found.push_back({{}, {}, -1, 0});
  for (const auto& c : found) into.push_back({i, w, c.feature, NeighborList::none, p.id[i]});
  return listed;
}

void WallCandidates::build(const ParticleStore& p, const Walls& walls, double skin,
                           ContactStateStore& state) {
  // the touching wall contacts, by (id, wall, feature), with their index in the old list
  std::vector<WallContactRecord> old;
  for (std::size_t q = 0; q < records_.size(); ++q)
    if (state.active[q]) {
      old.push_back(records_[q]);
      old.back().candidate = static_cast<std::uint32_t>(q);
    }
  auto key_less = [](const WallContactRecord& a, const WallContactRecord& b) {
    return std::tie(a.id, a.wall, a.feature) < std::tie(b.id, b.wall, b.feature);
  };
  std::sort(old.begin(), old.end(), key_less);
  std::vector<WallContactRecord> fresh;  // `candidate`: the old index whose state it continues
  full_scan_.assign(walls.size(), 0);
  travel_.assign(walls.size(), 0.0);
  elements_.clear(walls.size());
  // each thread searches a range of the particles (ghosts: their owners meet the walls) into a
  // part of its own; the parts are joined in range order, as a serial search would list them
  struct Part {
    std::vector<WallContactRecord> found;
    std::vector<std::uint32_t> elements;  // the particles' element lists, one after the other
    std::vector<std::uint32_t> counts;    // per particle: how many
    bool first_listed = false;            // the first particle's elements were listed
  };
  const std::size_t n = p.owned();
  const int nt = n >= kParallelMin ? max_threads() : 1;
  std::vector<Part> parts(static_cast<std::size_t>(nt));
  for (std::uint32_t w = 0; w < walls.size(); ++w) {
    full_scan_[w] = walls[w]->full_scan();
#pragma omp parallel num_threads(nt)
    {
      const auto t = static_cast<std::size_t>(thread_id()), ut = static_cast<std::size_t>(nt);
      Part& part = parts[t];
      part.found.clear();
      part.elements.clear();
      part.counts.clear();
      std::vector<WallContact> found;
      std::vector<std::uint32_t> elements;
      for (std::size_t s = n * t / ut; s < n * (t + 1) / ut; ++s) {
        const auto i = static_cast<std::uint32_t>(s);
        const std::size_t from = part.found.size();
        const bool listed =
            add(p, walls, i, w, p.x[i], p.radius[i], skin, elements, found, part.found);
        if (i == 0) part.first_listed = listed;
        part.elements.insert(part.elements.end(), elements.begin(), elements.end());
        part.counts.push_back(static_cast<std::uint32_t>(elements.size()));
        for (std::size_t k = from; k < part.found.size(); ++k) {
          WallContactRecord& r = part.found[k];
          auto it = std::lower_bound(old.begin(), old.end(), r, key_less);
          if (it != old.end() && !key_less(r, *it)) r.candidate = it->candidate;
        }
      }
    }
    if (n > 0 && parts[0].first_listed) elements_.start(w);
    for (const Part& part : parts) {
      fresh.insert(fresh.end(), part.found.begin(), part.found.end());
      if (!elements_.on(w)) continue;
      std::size_t at = 0;
      for (const std::uint32_t c : part.counts) {
        elements_.append(w, std::span<const std::uint32_t>(part.elements.data() + at, c));
        at += c;
      }
    }
  }
  // by particle (then wall, feature): lets the force loop split the list between threads
  std::stable_sort(fresh.begin(), fresh.end(),
                   [](const WallContactRecord& a, const WallContactRecord& b) {
                     return a.particle < b.particle;
                   });
  std::vector<std::uint32_t> state_from(fresh.size());
  for (std::size_t q = 0; q < fresh.size(); ++q) state_from[q] = fresh[q].candidate;
  state.gather(state_from);
  records_.swap(fresh);
}

void WallCandidates::add_appended(const ParticleStore& p, const Walls& walls, double skin,
                                  std::size_t n_kept, std::span<const Vec3> x_reach,
                                  std::span<const double> r_reach, WallElementLists& lists,
                                  std::vector<WallContactRecord>& into) const {
  std::vector<WallContact> found;
  std::vector<std::uint32_t> elements;
  for (std::size_t s = n_kept; s < p.size(); ++s)
    for (std::uint32_t w = 0; w < walls.size(); ++w) {
      add(p, walls, static_cast<std::uint32_t>(s), w, x_reach[s], r_reach[s], skin, elements, found,
          into);
      if (lists.on(w)) lists.append(w, elements);
    }
}

void WallCandidates::remap(const ParticleStore& p, const Walls& walls, double skin,
                           std::span<const std::uint32_t> to_new, std::size_t n_kept,
                           std::span<const Vec3> x_reach, std::span<const double> r_reach,
                           ContactStateStore& state) {
  constexpr std::uint32_t removed = NeighborList::none;
  std::vector<WallContactRecord> kept;
  std::vector<std::uint32_t> state_from;
  for (std::size_t q = 0; q < records_.size(); ++q) {
    const WallContactRecord& c = records_[q];
    const std::uint32_t s = c.particle < to_new.size() ? to_new[c.particle] : removed;
    if (s == removed) continue;
    WallContactRecord r = c;
    r.particle = s;
    kept.push_back(r);
    state_from.push_back(static_cast<std::uint32_t>(q));
  }
  WallElementLists lists = elements_.remapped(to_new, n_kept, removed);
  add_appended(p, walls, skin, n_kept, x_reach, r_reach, lists, kept);
  elements_ = std::move(lists);
  state_from.resize(kept.size(), NeighborList::none);  // the appended ones start afresh
  records_.swap(kept);
  state.gather(state_from);
}

void WallCandidates::renew(const ParticleStore& p, const Walls& walls, double skin,
                           const std::vector<std::uint8_t>& renewed, std::size_t n_old,
                           std::span<const Vec3> x_reach, std::span<const double> r_reach,
                           ContactStateStore& state) {
  std::vector<std::uint32_t> fresh;
  for (std::size_t q = 0; q < records_.size(); ++q) {
    WallContactRecord& c = records_[q];
    if (c.particle < n_old && renewed[c.particle]) {
      c.id = p.id[c.particle];
      fresh.push_back(static_cast<std::uint32_t>(q));
    }
  }
  add_appended(p, walls, skin, n_old, x_reach, r_reach, elements_, records_);
  state.renew(fresh, records_.size());
}

void WallCandidates::save(Archive& a) const {
  a.put("walls/candidates", records_);
  a.put("walls/travel", travel_);
  a.put("walls/full_scan", full_scan_);
}

void WallCandidates::load(const Archive& a, std::size_t n_build) {
  auto candidates = a.get<WallContactRecord>("walls/candidates");
  auto travel = a.get<double>("walls/travel");
  auto full_scan = a.get<std::uint8_t>("walls/full_scan");
  const std::size_t n_walls = travel.size();
  if (full_scan.size() != n_walls)
    throw Error(fmt::format("checkpoint entry 'walls/full_scan' holds {} walls, 'walls/travel' {}",
                            full_scan.size(), n_walls));
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const auto& c = candidates[k];
    // (`candidate` is only meaningful during a build: it is not read from a checkpoint)
    if (c.particle >= n_build || c.wall >= n_walls)
      throw Error(
          fmt::format("checkpoint entry 'walls/candidates' candidate {} (particle {}, "
                      "wall {}) is out of range",
                      k, c.particle, c.wall));
  }
  for (double d : travel)
    if (!std::isfinite(d)) throw Error("checkpoint entry 'walls/travel' is not finite");
  records_ = std::move(candidates);
  elements_.clear(n_walls);
  travel_ = std::move(travel);
  full_scan_ = std::move(full_scan);
}

}  // namespace comminute
