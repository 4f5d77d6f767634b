#pragma once
// Verlet neighbour list on cell grids: a half list of candidate pairs within r_i + r_j + skin,
// rebuilt when some particle has moved more than skin/2 since the last build (or after
// insertion/removal). Stored as pair arrays (first, second) grouped by `first`, so hot loops run
// over plain arrays. The list knows geometry only: per-contact state lives in the engine's
// contact-state store, which follows the pairs through the carry plans each build and in-place
// update leave behind (pairs matched by particle ids).
//
// Polydisperse beds: particles with radius <= r_ref (the 90th percentile, or all of them when
// r_max <= 1.5 r_ref) are binned in a grid of edge 2 r_ref + skin and searched with the 27-cell
// stencil; the few larger ones live in a second grid of edge 2 r_max + skin, and each of them
// scans the small-particle grid over its own reach. Work stays ~linear for a size ratio of 10.
#include <cstdint>
#include <utility>
#include <vector>

#include "comminute/neighbor/first_owners.hpp"
#include "comminute/neighbor/reach_index.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

class NeighborList {
 public:
  std::vector<std::uint32_t> first;   // slot of the pair's owner
  std::vector<std::uint32_t> second;  // slot of the other particle

  std::size_t size() const { return first.size(); }

  // Builds the list for the current positions. The pairs of the previous list flagged in `keep`
  // (by pair index; may be empty) are found again by their particle ids: carried() then tells
  // where each went. With ghosts in the store (periodic boundaries) no pair joins two ghosts, and
  // `labels` (one per slot: the periodic image label, PeriodicMap) keys the carry: a pair is found
  // again by its two ids and the difference of its two labels.
  void build(const ParticleStore& p, double skin, const std::vector<std::uint8_t>& keep = {},
             const std::vector<std::uint64_t>* labels = nullptr);
  // The carry plan of the last build: old pair from[e] is new pair to[e], listed the other way
  // round (owner and other swapped) when reversed[e]; shift[e] is how much the labels of the pair
  // changed (the owner's new label minus the old one of the same body; empty without labels).
  // Kept pairs of removed particles are absent.
  struct Carry {
    std::vector<std::uint32_t> from, to;
    std::vector<std::uint8_t> reversed;
    std::vector<std::uint64_t> shift;
  };
  const Carry& carried() const { return carry_; }
  // Frees the carry plan once the contact state has followed it (memory between rebuilds).
  void release_carry() { carry_ = Carry{}; }
  // In-place update after compact() removed particles (keeping the order of the others) and new
  // ones were appended, without a rebuild. slots_after_removal(): old slot -> new slot (none =
  // removed), empty when `p` does not start with the list's kept particles in order.
  std::vector<std::uint32_t> slots_after_removal(const ParticleStore& p) const;
  // Drops the pairs of removed particles, remaps slots (order kept) and gives each appended
  // particle s every partner j whose reach sphere at build lies within skin of its own:
  // |x_build[s] - x_build[j]| < r_build[s] + r_build[j] + skin (arrays by new slot; an appended
  // particle's reach sphere is chosen by the caller, e.g. its final radius). kept_from() then
  // gives, for each new pair, the old pair it continues (none: a new pair).
  void update_in_place(const ParticleStore& p, const std::vector<std::uint32_t>& to_new,
                       const std::vector<Vec3>& x_build, const std::vector<double>& r_build);
  const std::vector<std::uint32_t>& kept_from() const { return kept_from_; }
  // The pairs with a flagged slot (flagged[s] != 0, one flag per slot of the list), ascending;
  // found on all threads.
  std::vector<std::uint32_t> pairs_flagged(const std::vector<std::uint8_t>& flagged) const;
  // In-place update after particles were renewed in their slots (ParticleStore::renew: a fragment
  // in its parent's slot) and new ones appended, nothing removed: every pair is kept where it is,
  // and the appended particles get their rows as in update_in_place(). A renewed slot's reach
  // sphere (x_build, r_build) must lie inside the one it had at the build (the index keeps that
  // one); the pairs of the renewed slots (pairs_flagged) keep their places but not their contact
  // state. kept_from() is empty after it.
  void renew_in_place(const ParticleStore& p, const std::vector<Vec3>& x_build,
                      const std::vector<double>& r_build);
  bool can_update_in_place() const { return index_.valid(); }
  // Re-creates the spatial index of the reach spheres after restore() (checkpoints).
  void rebuild_index(const std::vector<Vec3>& x_build, const std::vector<double>& r_build,
                     double skin);
  static constexpr std::uint32_t none = 0xFFFFFFFFu;
  // Slot order that sorts particles by grid cell (memory locality); cell edge = `cell`.
  static std::vector<std::size_t> cell_order(const ParticleStore& p, double cell);
  // Ids of the slots when the list was built (for checkpoints and module look-ups).
  const std::vector<std::uint64_t>& ids_at_build() const { return ids_; }
  // Checkpoint support: restore a list exactly as saved.
  void restore(std::vector<std::uint32_t> f, std::vector<std::uint32_t> s,
               std::vector<std::uint64_t> ids, std::vector<std::uint8_t> large,
               std::vector<std::uint64_t> labels = {});
  // Periodic image labels of the slots at build (empty without periodic boundaries).
  const std::vector<std::uint64_t>& labels_at_build() const { return labels_; }
  const std::vector<std::uint8_t>& large() const { return large_; }
  // CSR offsets: the pairs owned by slot i are [rows()[i], rows()[i + 1]).
  const std::vector<std::uint32_t>& rows() const { return row_; }
  // Per slot, the lowest owner of its pairs (first_owners.hpp).
  const std::vector<std::uint32_t>& first_owner() const { return first_owners_.of_slots(); }

 private:
  std::vector<std::uint64_t> ids_;        // p.id at build
  std::vector<std::uint8_t> large_;       // 1 for particles in the large-particle grid
  std::vector<std::uint32_t> row_;        // CSR offsets of rows by owner slot (size n+1)
  FirstOwners first_owners_;              // first_owner(), by slot (size n)
  ReachIndex index_;                      // reach spheres at build, for in-place updates
  double skin_ = 0;                       // m, of the last build
  Carry carry_;                           // of the last build
  std::vector<std::uint32_t> kept_from_;  // of the last in-place update
  // ids_ = p.id after an in-place update.
  void follow_ids(const ParticleStore& p);
  // Rows of the appended particles n_kept .. n - 1 (update_in_place, renew_in_place).
  void append_rows(std::size_t n_kept, std::size_t n, const std::vector<Vec3>& x_build,
                   const std::vector<double>& r_build);
  // scratch reused between builds
  void plan_carry(const ParticleStore& p, const std::vector<std::uint8_t>& keep,
                  const std::vector<std::uint64_t>* labels);
  struct SavedIds {
    std::uint64_t a, b;    // ids of owner and other of a kept pair
    std::uint64_t la, lb;  // their labels (periodic images; 0 without)
    std::uint32_t pair;    // its index in the old list
  };
  std::vector<std::uint64_t> labels_;  // labels at build (periodic runs)
  struct SavedPair {     // a kept pair by its slots in the last build (ids in old_ids_): 8 B; its
    std::uint32_t a, b;  // index in the old list is its rank among the flags of `keep`
  };
  std::vector<SavedPair> saved_;
  std::vector<std::uint64_t> old_ids_, old_labels_;  // ids_, labels_ of the last build
  bool old_labelled_ = false;
  bool same_slots_ = false;  // the last build's slots hold the same particles (no id look-up)
  std::vector<std::uint32_t> spare_first_, spare_second_;  // in-place updates copy into these
  std::vector<std::vector<std::uint32_t>> thread_first_, thread_second_;
  std::size_t last_pairs_ = 0;  // pairs of the last build: the threads' arrays are reserved from it
  std::vector<std::pair<std::uint64_t, std::uint32_t>> slot_of_id_;
  std::vector<std::uint32_t> slot_by_id_;  // slot by id - lowest id (dense ids, no ghosts)
  void make_rows(std::size_t n);
};

}  // namespace comminute
