#pragma once
// Modules take part in the time step without the loop knowing what they are: insertion, bonds,
// breakage, observers. The step is
//   half kick + drift  ->  pre_force  ->  forces (contacts, walls, gravity)  ->  post_force
//   ->  half kick  ->  end_of_step
// A module that inserts or removes particles calls Simulation::particles_changed() so that the
// neighbour list is rebuilt (contact history survives: it is keyed by particle ids).
#include <string>
#include <vector>

#include "comminute/core/archive.hpp"

namespace comminute {

class Simulation;
class ContactPipeline;
class SeriesSource;
struct ParticleSize;

// Where a module runs within each hook of a step. Modules run stage by stage in this order; within
// a stage, in the order they were added.
enum class ModuleStage : int {
  insertion = 0,    // adds particles (fill, pour)
  physics = 1,      // changes particles or forces (breakage, bonds)
  observation = 2,  // measures (size distributions, statistics)
  output = 3,       // writes what the others measured
};

class Module {
 public:
  virtual ~Module() = default;
  virtual std::string name() const = 0;
  virtual ModuleStage stage() const { return ModuleStage::physics; }
  // Asks for per-contact state (the loading record, or slots of its own on
  // ContactPipeline::module_layout()) while the contact model is assembled: once, at set-up or
  // before a checkpoint is read.
  virtual void declare_contact_state(ContactPipeline&) {}
  virtual void setup(Simulation&) {}
  virtual void pre_force(Simulation&) {}
  virtual void post_force(Simulation&) {}
  virtual void end_of_step(Simulation&) {}
  // Checkpoint: put/get the module's state under names prefixed with name() + "/".
  virtual void save(Archive&) const {}
  virtual void load(const Archive&) {}
  // Adds the particle sizes the module can create, for the time-step policy (before set-up).
  virtual void announce_sizes(std::vector<ParticleSize>&, const Simulation&) const {}
  // After a checkpoint was read (every module loaded; setup() is not called again).
  virtual void restored(Simulation&) {}
  // The tables this module offers to the outputs (series_source.hpp), or null.
  virtual SeriesSource* series_source() { return nullptr; }
};

}  // namespace comminute
