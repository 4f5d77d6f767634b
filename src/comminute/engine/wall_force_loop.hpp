#pragma once
// The particle–wall force loop over the candidates of the pair tracker. Candidates are sorted by
// particle and cut into chunks of about 256 at particle boundaries, so a chunk's particles are its
// own. A thread takes the chunks that start in its particle range (particle_ranges.hpp: the
// ranges of the integration and the pair loop), so that it works on particles whose values its
// core already holds. Those ranges balance the pairs' cost, not the walls': where the wall contacts
// gather in one thread's particles, that thread does more of this loop; on the 20k drum, keeping
// each particle on one core weighed more than an even share of chunks taken as they come free
// (dynamic schedule, before: 3–4 % more step time on two threads). Wall forces and tallies are
// summed per chunk and combined in chunk order, so the result depends neither on which thread
// took which chunk nor on the number of threads. Touching contacts wait in runs (contact_run.hpp)
// for the contact pipeline's batch (the law inlined in its vector loop, as in the pair loop) and
// their forces are added in candidate order: the same bits as evaluating them one by one. A contact
// that moves to an adjacent feature of the same wall in one step (a sphere rolling from one
// triangle of a mesh onto the next: Wall::continues) keeps its history (tangential spring), and
// sliding on a wall that tracks wear is reported to it after the loop, in chunk order.
#include <memory>
#include <vector>

#include "comminute/contact/contact_state.hpp"
#include "comminute/engine/contact_pipeline.hpp"
#include "comminute/engine/contact_run.hpp"
#include "comminute/engine/ended_contact.hpp"
#include "comminute/engine/energy_tally.hpp"
#include "comminute/engine/particle_ranges.hpp"
#include "comminute/engine/wall_contact.hpp"
#include "comminute/engine/wall_element_lists.hpp"
#include "comminute/geometry/wall.hpp"
#include "comminute/particles/material.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

class WallForceLoop {
 public:
  // Adds the wall contact forces to p.f, p.t and their reactions to each wall's force and torque,
  // updates `state`, books the dissipation and the walls' work in `ledger`, adds the elastic
  // energy to `elastic` (J), and lists the touching contacts in `touching`. When the pipeline
  // keeps the collision record, appends the contacts that ended to `ended`, in candidate order.
  // A particle's contacts on a wall are looked up among its listed elements where `elements`
  // has a list for it (the same result), else by the wall's own search.
  void run(ParticleStore& p, const MaterialTable& materials,
           const std::vector<std::unique_ptr<Wall>>& walls,
           const std::vector<WallContactRecord>& candidates, const WallElementLists& elements,
           const ContactPipeline& pipeline, ContactStateStore& state, double dt,
           EnergyLedger& ledger, double& elastic, std::vector<WallContactRecord>& touching,
           std::vector<EndedContact>& ended, const ParticleRanges& ranges);

 private:
  struct WallTally {  // one thread's share of a step; kept from step to step for its capacity
    EnergyTally energy;
    std::vector<Vec3> force, torque;
    std::vector<WallContactRecord> touching;
    struct Wear {
      std::uint32_t wall;
      int element;
      double fn, slip;  // N, m
    };
    std::vector<Wear> wear;
    std::vector<EndedContact> ended;
    std::vector<ContactStart> starts;
    std::vector<ContactRecord> contacts;
  };
  struct Touch {  // a touching contact of a run (its index: the candidate), who receives its force
    std::uint32_t particle;
    WallContact hit;
    Vec3 wall_velocity;  // m/s, of the wall at the contact point
    double lever;        // m, the particle's radius less the overlap
  };
  struct LookUp {  // one thread's scratch: the look-up of one particle's candidates, and the run
    std::vector<WallContact> found, hits;
    ContactRun<Touch> run;
  };
  std::vector<WallTally> parts_;          // per chunk of candidates
  std::vector<LookUp> scratch_;           // per thread
  std::vector<std::size_t> begin_;        // the chunks' first candidates
  std::vector<std::size_t> first_chunk_;  // each thread's first chunk
};

}  // namespace comminute
