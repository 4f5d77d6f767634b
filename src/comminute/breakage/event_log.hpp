#pragma once
// The breakage event log: one record per logged stressing event (every breakage; with
// log_all_events also the events that did not break), one record per fragment of every breakage,
// and the event and breakage counters. It writes nothing: BreakageSeries turns it into tables.
// Checkpointed as breakage/log, breakage/fragments and breakage/counters.
#include <cstdint>
#include <vector>

#include "comminute/core/archive.hpp"
#include "comminute/core/memory.hpp"

namespace comminute::breakage {

// One row of the event log (SI units; strength in the criterion's unit).
struct EventRecord {
  double time = 0;  // s
  std::uint64_t parent_id = 0;
  std::uint32_t material = 0;
  std::uint32_t generation = 0;  // 0 for particles of the initial set
  double diameter = 0;           // m
  double mass = 0;               // kg, of the parent
  double specific_energy = 0;    // J/kg absorbed in the event (up to fracture when broken)
  double stressing_energy = 0;   // J/kg, the event's stressing energy (>= specific_energy)
  double peak_force = 0;         // N
  double strength = 0;           // J/kg (energy criteria) or N (force criteria) before the event
  double damage_before = 0;      // accumulated damage before the event
  std::uint32_t broken = 0;      // 1 if it broke
  std::uint32_t fragments = 0;   // resolved fragments
  std::uint32_t fines_particles = 0;
  std::uint32_t reserved = 0;  // explicit padding: checkpoint bytes are fully initialised
  double fines_mass = 0;       // kg booked as mass
  double t10 = 0;              // %
};
static_assert(sizeof(EventRecord) == 14 * 8, "EventRecord must have no padding (checkpoints)");

// One fragment of a breakage (SI units): with the event's fines_mass, the fragments of a parent
// give its progeny size distribution exactly (their masses and the fines add up to the parent's).
struct FragmentRecord {
  double time = 0;  // s, of the breakage
  std::uint64_t parent_id = 0;
  std::uint64_t fragment_id = 0;  // the fragment's particle id
  double diameter = 0;            // m, at its final (full) size
  double mass = 0;                // kg
  std::uint32_t generation = 0;   // the fragment's: parent's + 1
  std::uint32_t fines = 0;        // 1 for a fines particle (non-breakable)
};
static_assert(sizeof(FragmentRecord) == 6 * 8, "FragmentRecord must have no padding (checkpoints)");

class EventLog {
 public:
  // A stressing event ended (broken or not).
  void count_event() { ++events_; }
  // An event that did not break (logged only with log_all_events).
  void add(const EventRecord& r) { records_.push_back(r); }
  // A parent replaced by its fragments.
  void add_breakage(const EventRecord& r) {
    ++breakages_;
    records_.push_back(r);
  }

  // A fragment of the breakage being replaced.
  void add_fragment(const FragmentRecord& f) { fragments_.push_back(f); }
  // Room for this many more breakages and fragments, their pages resident (core/memory.hpp): the
  // log grows by a burst of replacements at a time.
  void make_room(std::size_t breakages, std::size_t fragments) {
    make_resident(records_, records_.size() + breakages);
    make_resident(fragments_, fragments_.size() + fragments);
  }

  const std::vector<EventRecord>& records() const { return records_; }
  const std::vector<FragmentRecord>& fragments() const { return fragments_; }
  std::uint64_t breakages() const { return breakages_; }
  std::uint64_t events() const { return events_; }

  void save(Archive& a) const;
  void load(const Archive& a);

 private:
  std::vector<EventRecord> records_;
  std::vector<FragmentRecord> fragments_;
  std::uint64_t breakages_ = 0, events_ = 0;
};

}  // namespace comminute::breakage
