#pragma once
// Which bodies may touch: the neighbour list of particle pairs and the particle–wall candidates,
// what they were built from (each particle's reach sphere: its position and radius at the build),
// when they must be rebuilt (a particle moved or grew by more than skin/2, a wall travelled as
// much, or particles were inserted or removed), and their in-place update when breakage replaces
// parents by fragments. It carries the engine's contact state through both. The wall candidates
// are a WallCandidates of their own, which it searches at each build and update.
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "comminute/contact/contact_state.hpp"
#include "comminute/core/archive.hpp"
#include "comminute/engine/wall_candidates.hpp"
#include "comminute/geometry/wall.hpp"
#include "comminute/neighbor/neighbor_list.hpp"
#include "comminute/neighbor/pruned_pairs.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

// A fragment appended by a breakage module: its id and the radius it will grow to.
struct NewFragment {
  std::uint64_t id = 0;
  double final_radius = 0;  // m
};

struct SimulationOptions {
  double skin = 0;      // m, Verlet skin (0: 0.2 x mean diameter at the first build with particles)
  int sort_every = 20;  // re-sort particles by cell every this many list rebuilds (0: never)
  // m, buffer of the pruned pair list the force loop visits (PrunedPairs); negative: a tenth of
  // the skin; 0, or not below the skin: no pruning (the force loop visits every listed pair)
  double prune_buffer = -1;
};

class PairTracker {
 public:
  using Walls = std::vector<std::unique_ptr<Wall>>;

  // The lists must be rebuilt before the next force computation.
  void invalidate() { stale_ = true; }
  bool stale() const { return stale_; }
  // The positions the drift is to measure each particle's displacement from (those at the last
  // build, one per particle while the lists are current), or nullptr while the drifts' summed
  // steps bound every displacement well enough that moved() need not be told it.
  const std::vector<Vec3>* displacement_reference() const {
    return exact_drift_ ? &x_at_build_ : nullptr;
  }
  // After a drift: the largest squared displacement since the build when the drift measured it
  // (displacement_reference() was given), the largest squared displacement of this drift (m2) and
  // the skin (m); and the distance wall k moved this step (m).
  void moved(const ParticleStore& p, double from_build2, double step2, double skin);
  void wall_moved(std::size_t k, double distance) { walls_.moved(k, distance); }
  // Whether the lists must be rebuilt before the next force computation: they are stale or some
  // reach changed by more than skin/2 (marks them stale).
  bool due(const ParticleStore& p, const SimulationOptions& options);
  // Before a rebuild: sets a zero skin from the particles and sorts them by cell every
  // options.sort_every rebuilds, or sooner when the fragments appended since the last sort are
  // more than an eighth of the store (see appended()). update() calls it unless the store holds
  // ghosts (periodic runs call it before their ghosts are made).
  void prepare(ParticleStore& p, SimulationOptions& options);
  // Breakage appended n fragments at the end of the store. Until a sort they sit there, away from
  // their neighbours in memory, and the slot-split loops give all their work to the last thread.
  void appended(std::size_t n) { appended_since_sort_ += n; }
  // Rebuilds the lists when due(); the contact state follows. Returns true when it rebuilt. With
  // periodic boundaries, `labels` holds each slot's image label (the store holds its ghosts, and
  // prepare() has run): the carry follows pairs across wraps and ghost rebuilds.
  bool update(ParticleStore& p, const Walls& walls, SimulationOptions& options,
              ContactStateStore& pair_state, ContactStateStore& wall_state,
              const std::vector<std::uint64_t>* labels = nullptr);
  // After breakage replaced parents by fragments: updates both lists in place. Either the parents
  // were removed by compact() and all fragments appended (`renewed` empty), or one fragment of
  // each parent took its parent's slot (ParticleStore::renew; `renewed` lists those slots) and the
  // others were appended, nothing removed: then every pair stays where it is and only the renewed
  // slots' contacts start afresh. Each appended fragment gets every partner within skin of its
  // sphere at its final radius, so the skin/2 trigger stays exact and growth needs no rebuild.
  // `fragments` lists every fragment, renewed or appended. False when an update in place is not
  // possible (the caller then invalidates).
  bool replace(const ParticleStore& p, const Walls& walls, double skin,
               const std::vector<NewFragment>& fragments, const std::vector<std::uint32_t>& renewed,
               ContactStateStore& pair_state, ContactStateStore& wall_state);
  // How much particle i may still move or grow (m) before the lists stop covering it.
  double reach_margin(const ParticleStore& p, std::size_t i, double skin) const;

  // After update(): the pairs the force loop must visit, pruned again when particles may have
  // moved half the prune buffer since the last prune (pairs flagged in `active` are kept: the loop
  // ends their contacts; so are the pairs of growing particles); null when the options ask for no
  // pruning.
  const PrunedPairs* near_pairs(const ParticleStore& p, const SimulationOptions& options,
                                const std::vector<std::uint8_t>& active);
  std::uint64_t prunes() const { return prunes_; }
  const NeighborList& pairs() const { return nlist_; }
  NeighborList& pairs() { return nlist_; }
  // The pairs with a flagged slot (NeighborList::pairs_flagged). The answer is kept until the list
  // changes: replace() with exactly these slots renewed takes it instead of scanning again.
  const std::vector<std::uint32_t>& pairs_flagged(const std::vector<std::uint8_t>& flags);
  // The particle–wall candidates, searched at each build and in-place update.
  const WallCandidates& wall_candidates() const { return walls_; }
  // Periodic wraps: f(record, index) may change a touching wall contact's feature key before the
  // next search carries its state (WallCandidates::rekey).
  template <class F>
  void rekey_wall_contacts(const ContactStateStore& state, F f) {
    walls_.rekey(state, f);
  }
  std::uint64_t rebuilds() const { return rebuilds_; }

  void save(Archive& a) const;
  // Needs the particles already loaded (to re-create the reach index), the skin and the number of
  // ghosts the lists were built with (periodic runs; ghosts are not in the store between steps).
  void load(const Archive& a, const ParticleStore& p, double skin, std::size_t n_ghosts = 0);

 private:
  void rebuild(ParticleStore& p, const Walls& walls, SimulationOptions& options,
               ContactStateStore& pair_state, ContactStateStore& wall_state,
               const std::vector<std::uint64_t>* labels);
  double reach_change(const ParticleStore& p, std::size_t i) const;  // |x - x_b| + r - r_b
  // replace() with fragments in their parents' slots.
  bool renew(const ParticleStore& p, const Walls& walls, double skin,
             const std::vector<NewFragment>& fragments, const std::vector<std::uint32_t>& renewed,
             ContactStateStore& pair_state, ContactStateStore& wall_state);
  // The fragments' final radii by id; nothing when a slot from n_kept on holds another particle.
  static std::optional<std::unordered_map<std::uint64_t, double>> final_radii(
      const ParticleStore& p, const std::vector<NewFragment>& fragments, std::size_t n_kept);
  // Reach spheres of the fragments appended from slot n_kept on (tracked from now on).
  void reach_of_appended(const ParticleStore& p, std::size_t n_kept,
                         const std::unordered_map<std::uint64_t, double>& final_radius,
                         std::vector<std::uint32_t>& tracked);
  void pause_pruning();  // the whole list is visited until the next rebuild

  NeighborList nlist_;
  WallCandidates walls_;
  // Reach at the last build: a particle's pairs cover every sphere within skin of the sphere
  // (x_at_build_, r_at_build_); fragments appended in place get theirs at insertion.
  std::vector<Vec3> x_at_build_;
  std::vector<double> r_at_build_;
  std::vector<std::uint32_t> reach_tracked_;  // slots whose radius or reach changed since the build
  std::vector<Vec3> x_spare_;                 // replace() builds the next reach spheres in these
  std::vector<double> r_spare_;
  bool stale_ = true;
  std::uint64_t rebuilds_ = 0;
  std::uint64_t appended_since_sort_ = 0;  // fragments appended since the last sort
  // The largest |x - x_build|^2 (m2), or the square of a bound on it below (skin/2)^2, which
  // decides due() as the exact value would. The bound: the largest displacement last measured
  // plus the drifts' largest steps since (m), while the drifts do not measure it themselves
  // (exact_drift_: from a measure within kMeasureAgain steps of the last measure or the build,
  // until the next build; a drift's measure reads the build positions, a pass of its own reads them
  // and the positions, so the bound spares that read on most steps of a bed that moves slowly).
  double max_disp2_ = 0;
  double travel_bound_ = 0;
  bool exact_drift_ = true;
  std::uint64_t steps_since_measure_ = 0;
  static constexpr std::uint64_t kMeasureAgain = 4;
  double largest_displacement2(const ParticleStore& p) const;
  // The pruned list: valid until a rebuild or an in-place update; the sum of the drifts' largest
  // displacements since it was made (m, bounds every particle's); the steps since; whether pruning
  // waits for the next rebuild (it had to prune again too soon to pay, or particles were replaced)
  PrunedPairs near_;
  bool near_valid_ = false;
  double prune_travel_ = 0;
  std::uint64_t steps_since_prune_ = 0;
  bool prune_paused_ = false;
  std::uint64_t prunes_ = 0;
  // the last pairs_flagged() answer and its flags, while the list is unchanged
  std::vector<std::uint8_t> flagged_by_;
  std::vector<std::uint32_t> flagged_;
  bool flagged_valid_ = false;
};

}  // namespace comminute
