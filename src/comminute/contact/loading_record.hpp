#pragma once
// The loading record of a contact, kept for breakage models: the largest overlap so far, the
// elastic work of the normal force up to it, and the elastic normal force of the last step. It is
// a contact sub-model like a rolling spring: its slots exist only when a module asks for it
// (single precision: a dense bed holds several hundred thousand contacts).
#include "comminute/contact/contact_law.hpp"

namespace comminute {

class LoadingRecord {
 public:
  void declare(ContactStateStore& layout) {
    max_overlap_ = layout.declare_f32("loading_max_overlap", SwapRule::keep);
    work_ = layout.declare_f32("loading_work", SwapRule::keep);
    force_ = layout.declare_f32("loading_normal_force", SwapRule::keep);
  }
  // After the law computed `out` at `overlap` (m).
  void record(const StateRef& s, double overlap, const ContactForces& out) const {
    float& largest = s.f32(max_overlap_);
    if (overlap > largest) {
      largest = static_cast<float>(overlap);
      s.f32(work_) = static_cast<float>(out.normal_elastic_energy);
    }
    s.f32(force_) = static_cast<float>(out.elastic_normal_force);
  }
  float max_overlap(const StateRef& s) const { return s.f32(max_overlap_); }  // m
  float loading_work(const StateRef& s) const { return s.f32(work_); }        // J
  float normal_force(const StateRef& s) const { return s.f32(force_); }       // N

 private:
  SlotId max_overlap_ = 0, work_ = 0, force_ = 0;
};

}  // namespace comminute
