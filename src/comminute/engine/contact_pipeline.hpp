#pragma once
// The contact model of a simulation, assembled once: the law, optional rolling resistance and
// adhesion, and the loading record when a module asks for it. One evaluate() serves the pair
// loop, the wall loop and modules that evaluate a contact at rest (breakage), so every contact
// sees the same physics. assemble() declares every sub-model's per-contact slots in a fixed order
// on a layout from which the engine's pair and wall stores are made.
#include <memory>

#include "comminute/contact/cohesion.hpp"
#include "comminute/contact/contact_law.hpp"
#include "comminute/contact/loading_record.hpp"
#include "comminute/contact/rolling_resistance.hpp"

namespace comminute {

class ContactPipeline {
 public:
  // Asks for the loading record (before assemble()).
  void require_loading_record() { want_loading_ = true; }
  // Fixes the sub-models and declares their slots; returns the layout (an empty store).
  const ContactStateStore& assemble(ContactLaw& law, RollingResistance* rolling,
                                    Cohesion* cohesion) {
    law_ = &law;
    rolling_ = rolling;
    cohesion_ = cohesion;
    layout_ = ContactStateStore{};
    law.declare(layout_);
    if (rolling) rolling->declare(layout_);
    if (want_loading_) {
      loading_ = std::make_unique<LoadingRecord>();
      loading_->declare(layout_);
    }
    return layout_;
  }
  bool assembled() const { return law_ != nullptr; }
  const ContactStateStore& layout() const { return layout_; }
  // null unless a module asked for it
  const LoadingRecord* loading() const { return loading_.get(); }

  void evaluate(const ContactKinematics& k, const PairParameters& p, const StateRef& s,
                ContactForces& out) const {
    law_->compute(k, p, s, out);
    if (cohesion_) cohesion_->compute(k, p, out);
    if (rolling_) rolling_->compute(k, p, s, out);
    if (loading_) loading_->record(s, k.overlap, out);
  }

 private:
  ContactLaw* law_ = nullptr;
  RollingResistance* rolling_ = nullptr;
  Cohesion* cohesion_ = nullptr;
  std::unique_ptr<LoadingRecord> loading_;
  bool want_loading_ = false;
  ContactStateStore layout_;
};

}  // namespace comminute
