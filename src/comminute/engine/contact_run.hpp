#pragma once
// A run of touching contacts waiting for the contact pipeline, shared by the pair and the wall
// force loops: a loop gathers up to kSize contacts (their kinematics, pair parameters and places in
// the contact-state store, and what it needs to hand out their forces: `Who`), evaluate() hands
// them to ContactPipeline::evaluate(ContactBatch) in one call (the law inlined in its vector loop),
// and the loop then adds the forces in run order, which is the order it gathered the contacts in:
// the same sums as evaluating them one by one.
#include <array>
#include <cstddef>

#include "comminute/engine/contact_pipeline.hpp"

namespace comminute {

template <class Who>
struct ContactRun {
  static constexpr std::size_t kSize = kBatchSize;  // contacts per call of the contact pipeline
  KinematicsColumns kinematics;                     // the contacts' kinematics, by component
  std::array<const PairParameters*, kSize> parameters;
  std::array<std::size_t, kSize> index;  // the contacts' places in the contact-state store
  ForceColumns forces;                   // zero until evaluate() (the pipeline adds to them)
  std::array<Who, kSize> who;
  std::size_t size = 0;

  bool full() const { return size == kSize; }
  // The contact model for contacts [0, size): their forces into forces.
  void evaluate(const ContactPipeline& pipeline, const Slots& slots) {
    pipeline.evaluate(
        ContactBatch{size, &kinematics, parameters.data(), index.data(), &slots, &forces});
  }
  // Empties the run; the forces it used back to zero.
  void clear() {
    forces.clear(size);
    size = 0;
  }
};

}  // namespace comminute
