#pragma once
// Bonded particles as an engine module (physics stage): makes the bonds once (at `create_at`,
// every neighbour pair whose gap is at most `gap_tolerance`, optionally of some materials only),
// then each step, after the contact forces, moves every bond with its particles, asks the bond
// law for its force and moment, adds them to the two particles (the contact law acts in parallel),
// removes failed bonds and logs each failure. Energy: the strain energy held in the bonds and the
// energy they dissipated are booked in the engine's ledger (bond_elastic, bond_dissipated).
#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "comminute/bonds/bond_failure.hpp"
#include "comminute/bonds/bond_law.hpp"
#include "comminute/bonds/bond_list.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/series_source.hpp"

namespace comminute::bonds {

struct BondOptions {
  double create_at = 0;                  // s
  double gap_tolerance = 0;              // m
  std::vector<std::uint16_t> materials;  // empty: all
  bool within_grain = false;  // bond only pairs with the same per-particle field `grain` (≥ 0)
};

// One row of bonds.csv (plain data: checkpointed as is).
struct BondSample {
  double time = 0;
  std::uint64_t intact = 0, tensile = 0, shear = 0, removed = 0;
  double mean_damage = 0, max_damage = 0, elastic = 0, dissipated = 0;
};

// One row of bond_damage.csv: a damaged bond at a sample time.
struct BondDamageRow {
  double time = 0;
  std::uint64_t id_i = 0, id_j = 0;
  double damage = 0;
};

class BondsModule final : public Module, public SeriesSource {
 public:
  BondsModule(std::unique_ptr<BondLaw> law, BondOptions options);

  std::string name() const override { return "bonds"; }
  void setup(Simulation& sim) override;
  void post_force(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  SeriesSource* series_source() override { return this; }
  void sample(const Simulation& sim) override;
  std::vector<Table> tables(const Simulation& sim) const override;

  const BondLaw& law() const { return *law_; }
  const BondList& bonds() const { return bonds_; }
  const std::vector<BondFailure>& failures() const { return failures_; }
  bool created() const { return created_; }
  // Bytes of the per-step scratch at its capacity (flags, loads, per-particle bond index, the
  // ids the slots were resolved against).
  std::size_t scratch_bytes() const;
  // Makes the bonds now (post_force does it at create_at); public for tests and builders.
  void create_bonds(Simulation& sim);
  // Bonds the listed pairs of particle slots now, with this module's law (a grain template's
  // pairs when a pour inserts a grain: bonds/grain_pour.hpp). Each pair is bonded once: a later
  // create_bonds() skips pairs that are bonded already. Throws SimulationError when a bond needs
  // a smaller time step.
  void bond_pairs(Simulation& sim, const std::vector<std::array<std::uint32_t, 2>>& slots);

 private:
  void apply(Simulation& sim);
  // Bonds slots i and j (ids a < b) with the law's new state; checks the time step.
  void make_bond(Simulation& sim, std::uint32_t i, std::uint32_t j);
  void fail(Simulation& sim, std::size_t b, FailureCause cause, const Vec3& at);

  std::unique_ptr<BondLaw> law_;
  BondOptions options_;
  BondList bonds_;
  Rng rng_;
  bool created_ = false;
  std::vector<BondFailure> failures_;
  std::vector<BondSample> samples_;
  std::vector<BondDamageRow> damage_rows_;
  void index_by_particle(std::size_t n);
  void add_to_particles(ParticleStore& p) const;

  // Scratch of a step, per bond: removal flag (1: particle gone, 2: failed); the force on j (N)
  // and the torques on i and j (N m), per bond on a step that measures stress, else per waiting
  // bond (deferred_; none on one thread); per range of kRange bonds, what the range adds up to.
  std::vector<std::uint8_t> gone_;
  std::vector<Vec3> force_, torque_i_, torque_j_;
  std::vector<BondStepSums> range_sums_;
  // Each particle's bonds, in bond order (CSR: bonds of slot k are entries first_[k] ..
  // first_[k + 1], entry = bond << 1 | 1 where k is the bond's j): the loads are added per
  // particle on all threads in the order of a serial pass over the bonds. Rebuilt when bonds
  // are made or removed or the slots move.
  std::vector<std::uint32_t> first_, entry_;
  bool indexed_ = false;
  // The owned particles' ids when the slots were last resolved (locate): while the store's ids
  // equal these, the bonds' cached slots are current.
  std::vector<std::uint64_t> ids_at_index_;
  // The bond ranges of block k of `blocks` (one block per thread), and per bond which ends'
  // loads wait until the threads join (BondStep::defer: a particle takes its loads directly
  // only from the first block whose bonds load it), for `blocks` blocks (blocks_; 0: not marked).
  static std::pair<std::size_t, std::size_t> block_ranges(std::size_t k, std::size_t blocks,
                                                          std::size_t ranges);
  void mark_deferred(std::size_t blocks, std::size_t ranges);
  std::vector<std::uint8_t> defer_;
  std::vector<std::uint32_t> deferred_;  // the bonds with a waiting end, in bond order
  std::size_t blocks_ = 0;
};

}  // namespace comminute::bonds
