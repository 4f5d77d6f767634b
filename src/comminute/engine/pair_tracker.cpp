#include "comminute/engine/pair_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>

#include <fmt/format.h>

#include "comminute/core/error.hpp"
#include "comminute/core/memory.hpp"

namespace comminute {

namespace {
// Room for n values in v, whose old values are not needed: a v too small is freed and re-made
// 1/8 larger (the next in-place updates add fragments) with nothing copied; the pages of the
// first n made resident before they are written (fresh pages: core/memory.hpp).
template <class T>
void make_room(std::vector<T>& v, std::size_t n) {
  if (v.capacity() < n) {
    std::vector<T>().swap(v);
    v.reserve(n + n / 8);
  }
  make_resident(v, n);
}
}  // namespace

bool PairTracker::update(ParticleStore& p, const Walls& walls, SimulationOptions& options,
                         ContactStateStore& pair_state, ContactStateStore& wall_state,
                         const std::vector<std::uint64_t>* labels) {
  if (!due(p, options)) return false;
  rebuild(p, walls, options, pair_state, wall_state, labels);
  return true;
}

bool PairTracker::due(const ParticleStore& p, const SimulationOptions& options) {
  if (!stale_) {
    const double travel = walls_.largest_travel();
    // |x - x_build| for every particle; plus the change of radius for the tracked ones
    // (a max: exact, so the same on any number of threads)
    double reach = std::sqrt(max_disp2_);
    const auto n_tracked = static_cast<std::ptrdiff_t>(reach_tracked_.size());
#pragma omp parallel for schedule(static) reduction(max : reach) if (n_tracked >= 16384)
    for (std::ptrdiff_t q = 0; q < n_tracked; ++q)
      reach = std::max(reach, reach_change(p, reach_tracked_[static_cast<std::size_t>(q)]));
    const double limit = 0.5 * options.skin;
    if (reach > limit || travel > limit) stale_ = true;
  }
  return stale_;
}

void PairTracker::moved(const ParticleStore& p, double from_build2, double step2, double skin) {
  const double step = std::sqrt(step2);
  prune_travel_ += step;
  if (exact_drift_) {
    max_disp2_ = from_build2;
    return;
  }
  // every particle moved at most travel_bound_ from its build position: below skin/2 (with room
  // for round-off) due() decides from the bound as from the exact value
  ++steps_since_measure_;
  travel_bound_ += step;
  if (travel_bound_ <= (1 - 1e-9) * 0.5 * skin && x_at_build_.size() >= p.owned()) {
    max_disp2_ = travel_bound_ * travel_bound_;
    return;
  }
  max_disp2_ = largest_displacement2(p);
  travel_bound_ = std::sqrt(max_disp2_);
  if (steps_since_measure_ < kMeasureAgain) exact_drift_ = true;
  steps_since_measure_ = 0;
}

double PairTracker::largest_displacement2(const ParticleStore& p) const {
  const auto n = static_cast<std::ptrdiff_t>(p.owned());
  if (x_at_build_.size() < p.owned()) return std::numeric_limits<double>::infinity();
  double worst = 0;  // (a max: exact, so the same on any number of threads)
#pragma omp parallel for schedule(static) reduction(max : worst) if (n >= 16384)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    worst = std::max(worst, norm2(p.x[k] - x_at_build_[k]));
  }
  return worst;
}

const PrunedPairs* PairTracker::near_pairs(const ParticleStore& p, const SimulationOptions& options,
                                           const std::vector<std::uint8_t>& active) {
  // (a tenth of the skin by default: on the dense bench bed 2-4 % faster than a quarter on one and
  // two threads, the settle and drum beds alike either way; bench/RESULTS.md, thirty-sixth stop)
  const double buffer = options.prune_buffer < 0 ? 0.1 * options.skin : options.prune_buffer;
  if (!(buffer > 0 && buffer < options.skin) || stale_ || r_at_build_.size() != p.size() ||
      prune_paused_)
    return nullptr;
  // A pair left out was at least `buffer` from touching at the prune, and neither of its particles
  // was growing (PrunedPairs keeps those pairs; a particle that is not growing keeps its radius).
  // Since then each particle moved at most prune_travel_, so the pair cannot touch while
  // 2 prune_travel_ <= buffer; the factor below leaves room for round-off.
  if (!near_valid_ || 2 * prune_travel_ > (1 - 1e-9) * buffer) {
    // A prune costs about what visiting the whole list costs in 4 steps (one distance per listed
    // pair, against the listed pairs it spares per step: up to the 45 % of the dense bench bed's
    // listed pairs that do not touch):
    // when particles move fast enough to need one sooner, the whole list is visited until the
    // next rebuild.
    if (near_valid_ && steps_since_prune_ < 4) {
      pause_pruning();
      return nullptr;
    }
    near_.prune(p, nlist_, buffer, active.data());
    near_valid_ = true;
    prune_travel_ = 0;
    steps_since_prune_ = 0;
    ++prunes_;
  }
  ++steps_since_prune_;
  return &near_;
}

void PairTracker::pause_pruning() {
  near_valid_ = false;
  prune_paused_ = true;
}

void PairTracker::prepare(ParticleStore& p, SimulationOptions& options) {
  if (options.skin <= 0 && !p.empty()) {
    double mean = 0;
    for (double r : p.radius) mean += 2 * r;
    options.skin = 0.2 * mean / static_cast<double>(p.size());
  }
  // an eighth: on the breakage bench (bench_breakage 50000, 300 steps) the fragments' work is then
  // shared between the threads (bench/RESULTS.md, eleventh stop)
  const bool crowded_tail = 8 * appended_since_sort_ > p.size();
  const bool sort_now =
      options.sort_every > 0 && (rebuilds_ % options.sort_every == 0 || crowded_tail);
  if (sort_now && !p.empty()) {
    const double rmax = *std::max_element(p.radius.begin(), p.radius.end());
    auto order = NeighborList::cell_order(p, 2 * rmax + options.skin);
    p.permute(order);
    appended_since_sort_ = 0;
  }
}

void PairTracker::rebuild(ParticleStore& p, const Walls& walls, SimulationOptions& options,
                          ContactStateStore& pair_state, ContactStateStore& wall_state,
                          const std::vector<std::uint64_t>* labels) {
  if (!labels) prepare(p, options);
  flagged_valid_ = false;
  nlist_.build(p, options.skin, pair_state.active, labels);
  const auto& carried = nlist_.carried();
  // the last build's positions are spent: released before the carry, the peak memory of a rebuild
  std::vector<Vec3>().swap(x_at_build_);
  std::vector<Vec3>().swap(x_spare_);
  std::vector<double>().swap(r_spare_);
  pair_state.carry(carried.from, carried.to, carried.reversed, nlist_.size());
  // with 1/8 spare: the in-place updates until the next build append fragments, and growing into
  // fresh pages costs a page fault per 4 KiB, more than the copy (bench_breakage)
  make_room(x_at_build_, p.size());
  make_room(r_at_build_, p.size());
  x_at_build_.assign(p.x.begin(), p.x.end());
  r_at_build_.assign(p.radius.begin(), p.radius.end());
  reach_tracked_.clear();
  for (std::size_t i = 0; i < p.owned(); ++i)
    if (p.flags[i] & pflag::growing) reach_tracked_.push_back(static_cast<std::uint32_t>(i));
  walls_.build(p, walls, options.skin, wall_state);
  stale_ = false;
  travel_bound_ = 0;
  exact_drift_ = false;
  steps_since_measure_ = 0;
  near_valid_ = false;
  prune_paused_ = false;
  ++rebuilds_;
}

std::optional<std::unordered_map<std::uint64_t, double>> PairTracker::final_radii(
    const ParticleStore& p, const std::vector<NewFragment>& fragments, std::size_t n_kept) {
  std::unordered_map<std::uint64_t, double> final_radius;  // by fragment id
  for (const auto& f : fragments) final_radius[f.id] = f.final_radius;
  for (std::size_t s = n_kept; s < p.size(); ++s)
    if (final_radius.count(p.id[s]) == 0) return std::nullopt;  // something else was inserted
  return final_radius;
}

void PairTracker::reach_of_appended(const ParticleStore& p, std::size_t n_kept,
                                    const std::unordered_map<std::uint64_t, double>& final_radius,
                                    std::vector<std::uint32_t>& tracked) {
  // a fragment's reach sphere at "build" is where it is now at its final size: growth up to that
  // size then never invalidates the list; the pruned list keeps all its pairs until the next prune
  make_resident(x_at_build_, p.size());  // (core/memory.hpp)
  make_resident(r_at_build_, p.size());
  x_at_build_.resize(p.size());
  r_at_build_.resize(p.size());
  for (std::size_t s = n_kept; s < p.size(); ++s) {
    x_at_build_[s] = p.x[s];
    r_at_build_[s] = std::max(p.radius[s], final_radius.at(p.id[s]));
    tracked.push_back(static_cast<std::uint32_t>(s));
  }
}

const std::vector<std::uint32_t>& PairTracker::pairs_flagged(
    const std::vector<std::uint8_t>& flags) {
  if (!flagged_valid_ || flagged_by_ != flags) {
    flagged_ = nlist_.pairs_flagged(flags);
    flagged_by_ = flags;
    flagged_valid_ = true;
  }
  return flagged_;
}

bool PairTracker::replace(const ParticleStore& p, const Walls& walls, double skin,
                          const std::vector<NewFragment>& fragments,
                          const std::vector<std::uint32_t>& renewed, ContactStateStore& pair_state,
                          ContactStateStore& wall_state) {
  if (stale_ || skin <= 0 || !nlist_.can_update_in_place()) return false;
  if (!renewed.empty()) return renew(p, walls, skin, fragments, renewed, pair_state, wall_state);
  flagged_valid_ = false;
  const std::vector<std::uint32_t> to_new = nlist_.slots_after_removal(p);
  const std::size_t n_kept = static_cast<std::size_t>(std::count_if(
      to_new.begin(), to_new.end(), [](std::uint32_t s) { return s != NeighborList::none; }));
  if (to_new.empty() || p.size() - n_kept != fragments.size()) return false;
  const auto final_radius = final_radii(p, fragments, n_kept);
  if (!final_radius) return false;
  // the kept reach spheres move to their new slots (distinct targets: on all threads) in spare
  // arrays kept between updates, swapped in below
  std::vector<Vec3>& x_build = x_spare_;
  std::vector<double>& r_build = r_spare_;
  make_room(x_build, p.size());
  make_room(r_build, p.size());
  x_build.resize(n_kept);
  r_build.resize(n_kept);
  const auto n_old = static_cast<std::ptrdiff_t>(to_new.size());
#pragma omp parallel for schedule(static) if (n_old >= 16384)
  for (std::ptrdiff_t o = 0; o < n_old; ++o) {
    const auto old = static_cast<std::size_t>(o);
    if (to_new[old] != NeighborList::none) {
      x_build[to_new[old]] = x_at_build_[old];
      r_build[to_new[old]] = r_at_build_[old];
    }
  }
  std::vector<std::uint32_t> tracked;
  for (std::uint32_t s : reach_tracked_)
    if (to_new[s] != NeighborList::none) tracked.push_back(to_new[s]);
  x_at_build_.swap(x_build);
  r_at_build_.swap(r_build);
  reach_of_appended(p, n_kept, *final_radius, tracked);
  reach_tracked_.swap(tracked);
  nlist_.update_in_place(p, to_new, x_at_build_, r_at_build_);
  // replacements come in bursts, one per step, and a fragment flies fast, so carrying the pruned
  // list through each update (a pass over the list) and pruning again cost more than the pruned
  // loop saves (bench_breakage, bench/RESULTS.md)
  pause_pruning();
  pair_state.gather(nlist_.kept_from());
  // wall candidates: kept ones remapped, each fragment's found at its reach sphere
  walls_.remap(p, walls, skin, to_new, n_kept, x_at_build_, r_at_build_, wall_state);
  return true;
}

bool PairTracker::renew(const ParticleStore& p, const Walls& walls, double skin,
                        const std::vector<NewFragment>& fragments,
                        const std::vector<std::uint32_t>& renewed, ContactStateStore& pair_state,
                        ContactStateStore& wall_state) {
  // the store must hold the particles of the lists, but for new ones in the renewed slots, and
  // then the appended fragments
  const std::vector<std::uint64_t>& ids = nlist_.ids_at_build();
  const std::size_t n_old = ids.size();
  if (p.size() < n_old || x_at_build_.size() != n_old ||
      p.size() - n_old + renewed.size() != fragments.size())
    return false;
  const auto final_radius = final_radii(p, fragments, n_old);
  if (!final_radius) return false;
  std::vector<std::uint8_t> is_renewed(n_old, 0);
  for (const std::uint32_t s : renewed) {
    if (s >= n_old || final_radius->count(p.id[s]) == 0) return false;
    is_renewed[s] = 1;
  }
  bool same = true;
  const auto sn = static_cast<std::ptrdiff_t>(n_old);
#pragma omp parallel for schedule(static) reduction(&& : same) if (sn >= 16384)
  for (std::ptrdiff_t s = 0; s < sn; ++s)
    same = same && (is_renewed[static_cast<std::size_t>(s)] != 0 ||
                    p.id[static_cast<std::size_t>(s)] == ids[static_cast<std::size_t>(s)]);
  if (!same) return false;
  // A renewed slot's new particle lies inside the sphere the old one had at its last position,
  // which lay within skin/2 of its reach sphere at build (x_b, r_b): the sphere about the new
  // particle's centre x inside (x_b, r_b), radius r_b - |x - x_b| (negative when the particle is
  // smaller than skin/2 and off-centre), is its reach sphere. Every sphere its pairs must hold is
  // within skin of it, so within skin of (x_b, r_b): the old particle's pairs cover the new one.
  for (const std::uint32_t s : renewed) {
    r_at_build_[s] -= norm(p.x[s] - x_at_build_[s]);
    x_at_build_[s] = p.x[s];
    reach_tracked_.push_back(s);
  }
  reach_of_appended(p, n_old, *final_radius, reach_tracked_);
  // (the breakage module asked for the pairs of its parents, which are the renewed slots)
  const std::vector<std::uint32_t> fresh_pairs =
      flagged_valid_ && flagged_by_ == is_renewed ? flagged_ : nlist_.pairs_flagged(is_renewed);
  nlist_.renew_in_place(p, x_at_build_, r_at_build_);
  flagged_valid_ = false;
  pair_state.renew(fresh_pairs, nlist_.size());
  pause_pruning();  // (as after update_in_place)
  // wall candidates: those of a renewed slot are the new particle's, afresh; the appended
  // fragments' found at their reach spheres
  walls_.renew(p, walls, skin, is_renewed, n_old, x_at_build_, r_at_build_, wall_state);
  return true;
}

double PairTracker::reach_change(const ParticleStore& p, std::size_t i) const {
  return norm(p.x[i] - x_at_build_[i]) + p.radius[i] - r_at_build_[i];
}

double PairTracker::reach_margin(const ParticleStore& p, std::size_t i, double skin) const {
  if (stale_ || i >= x_at_build_.size()) return 0;
  return 0.5 * skin - reach_change(p, i);
}

void PairTracker::save(Archive& a) const {
  a.put("pairs/first", nlist_.first);
  a.put("pairs/second", nlist_.second);
  a.put("pairs/ids", nlist_.ids_at_build());
  a.put("pairs/labels", nlist_.labels_at_build());
  a.put("pairs/large", nlist_.large());
  a.put("pairs/x_at_build", x_at_build_);
  a.put("pairs/r_at_build", r_at_build_);
  a.put("pairs/reach_tracked", reach_tracked_);
  walls_.save(a);
  a.put_value("sim/rebuilds", rebuilds_);
  a.put_value("sim/appended_since_sort", appended_since_sort_);
  a.put_value("sim/max_disp2", max_disp2_);
  a.put_value("sim/travel_bound", travel_bound_);
  a.put_value("sim/exact_drift", static_cast<std::uint8_t>(exact_drift_));
  a.put_value("sim/steps_since_measure", steps_since_measure_);
  a.put_value("sim/need_rebuild", static_cast<std::uint8_t>(stale_));
}

namespace {
[[noreturn]] void corrupt(const std::string& entry, const std::string& what) {
  throw Error("checkpoint entry '" + entry + "' " + what);
}
}  // namespace

void PairTracker::load(const Archive& a, const ParticleStore& p, double skin,
                       std::size_t n_ghosts) {
  // Everything is checked before it is used: a crafted or mixed-up checkpoint must not index out
  // of range. The lists describe the particles at the last build (n_build of them); while they
  // are current (not stale) that is the particle count.
  auto first = a.get<std::uint32_t>("pairs/first");
  auto second = a.get<std::uint32_t>("pairs/second");
  auto ids = a.get<std::uint64_t>("pairs/ids");
  auto large = a.get<std::uint8_t>("pairs/large");
  // (absent from checkpoints written before periodic boundaries: no labels)
  auto labels =
      a.has("pairs/labels") ? a.get<std::uint64_t>("pairs/labels") : std::vector<std::uint64_t>{};
  auto x_build = a.get<Vec3>("pairs/x_at_build");
  auto r_build = a.get<double>("pairs/r_at_build");
  auto tracked = a.get<std::uint32_t>("pairs/reach_tracked");
  const bool stale = a.get_value<std::uint8_t>("sim/need_rebuild") != 0;
  const std::size_t n_build = ids.size();
  if (!stale && n_build != p.size() + n_ghosts)
    corrupt("pairs/ids", fmt::format("holds {} particles, the checkpoint {} and {} ghosts", n_build,
                                     p.size(), n_ghosts));
  if (!labels.empty() && labels.size() != n_build)
    corrupt("pairs/labels",
            fmt::format("holds {} labels for {} particles", labels.size(), n_build));
  if (second.size() != first.size())
    corrupt("pairs/second",
            fmt::format("holds {} pairs, 'pairs/first' {}", second.size(), first.size()));
  if (large.size() != n_build || x_build.size() != n_build || r_build.size() != n_build)
    corrupt("pairs/large", fmt::format("the build arrays (large {}, x_at_build {}, r_at_build {}) "
                                       "do not match the {} particles of the build",
                                       large.size(), x_build.size(), r_build.size(), n_build));
  for (std::size_t k = 0; k < first.size(); ++k) {
    if (first[k] >= n_build || second[k] >= n_build || first[k] == second[k])
      corrupt("pairs/first", fmt::format("pair {} ({}, {}) is not a pair of two of the {} "
                                         "particles",
                                         k, first[k], second[k], n_build));
    if (k > 0 && first[k] < first[k - 1])
      corrupt("pairs/first", fmt::format("pair {} is not grouped by its owner", k));
  }
  for (std::uint32_t s : tracked)
    if (s >= n_build) corrupt("pairs/reach_tracked", fmt::format("slot {} is out of range", s));
  const double disp2 = a.get_value<double>("sim/max_disp2");
  if (!std::isfinite(disp2) || disp2 < 0) corrupt("sim/max_disp2", "is not a finite distance");
  // (absent in checkpoints written before the bound existed: their drifts measured every step)
  const bool has_bound = a.has("sim/travel_bound");
  const double travel_bound = has_bound ? a.get_value<double>("sim/travel_bound") : 0.0;
  if (!std::isfinite(travel_bound) || travel_bound < 0)
    corrupt("sim/travel_bound", "is not a finite distance");
  const bool exact_drift = !has_bound || a.get_value<std::uint8_t>("sim/exact_drift") != 0;
  const std::uint64_t steps_since_measure =
      has_bound ? a.get_value<std::uint64_t>("sim/steps_since_measure") : 0;
  walls_.load(a, n_build);  // (checks its entries before it changes anything)
  nlist_.restore(std::move(first), std::move(second), std::move(ids), std::move(large),
                 std::move(labels));
  flagged_valid_ = false;
  x_at_build_ = std::move(x_build);
  r_at_build_ = std::move(r_build);
  reach_tracked_ = std::move(tracked);
  if (x_at_build_.size() == p.size()) nlist_.rebuild_index(x_at_build_, r_at_build_, skin);
  rebuilds_ = a.get_value<std::uint64_t>("sim/rebuilds");
  // (absent in checkpoints written before the rule existed: their runs had not counted)
  appended_since_sort_ =
      a.has("sim/appended_since_sort") ? a.get_value<std::uint64_t>("sim/appended_since_sort") : 0;
  max_disp2_ = disp2;
  exact_drift_ = exact_drift;
  travel_bound_ = travel_bound;
  steps_since_measure_ = steps_since_measure;
  stale_ = stale;
  near_valid_ = false;  // pruned again at the next step: the same pairs touch, so the same bits
}

}  // namespace comminute
