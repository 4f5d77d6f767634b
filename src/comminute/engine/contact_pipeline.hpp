#pragma once
// The contact model of a simulation, assembled once: the law, optional rolling resistance and
// adhesion, and the loading and collision records when a module asks for them. One evaluate()
// serves the pair loop, the wall loop and modules that evaluate a contact at rest (breakage), so
// every contact sees the same physics. assemble() declares every sub-model's per-contact slots in a
// fixed order on a layout from which the engine's pair and wall stores are made.
#include <memory>
#include <vector>

#include "comminute/contact/cohesion.hpp"
#include "comminute/contact/collision_record.hpp"
#include "comminute/contact/contact_law.hpp"
#include "comminute/contact/loading_record.hpp"
#include "comminute/contact/rolling_resistance.hpp"
#include "comminute/core/error.hpp"
#include "comminute/engine/contact_stress.hpp"
#include "comminute/engine/module.hpp"

namespace comminute {

class ContactPipeline {
 public:
  // Fixes the sub-models and declares their slots in a fixed order: the law's, the rolling
  // model's, then each module's (Module::declare_contact_state, which may ask for the loading
  // record or declare slots of its own on module_layout()). Returns the layout (an empty store).
  const ContactStateStore& assemble(ContactLaw& law, RollingResistance* rolling, Cohesion* cohesion,
                                    const std::vector<std::unique_ptr<Module>>& modules) {
    law_ = &law;
    rolling_ = rolling;
    cohesion_ = cohesion;
    layout_ = ContactStateStore{};
    loading_.reset();
    collisions_.reset();
    stress_.reset();
    law.declare(layout_);
    if (rolling) rolling->declare(layout_);
    assembling_ = true;
    for (const auto& m : modules) m->declare_contact_state(*this);
    assembling_ = false;
    return layout_;
  }
  // For modules, during assemble(): the loading record, and slots of their own (a bond's state).
  void require_loading_record() {
    if (!loading_) {
      loading_ = std::make_unique<LoadingRecord>();
      loading_->declare(module_layout());
    }
  }
  void require_collision_record() {
    if (!collisions_) {
      collisions_ = std::make_unique<CollisionRecord>();
      collisions_->declare(module_layout());
    }
  }
  // For modules, during assemble(): per-particle contact stress and the contact list
  // (contact_stress.hpp), filled by the force loops on the steps a module arms.
  ContactStress& require_contact_stress() {
    if (!assembling_) throw Error("contact stress is asked for while the contacts are assembled");
    if (!stress_) stress_ = std::make_unique<ContactStress>();
    return *stress_;
  }
  ContactStateStore& module_layout() {
    if (!assembling_)
      throw Error("per-contact slots are declared while the contacts are assembled");
    return layout_;
  }
  bool assembled() const { return law_ != nullptr; }
  // The normal elastic energy evaluate() reports at rest (J): the law's alone (no sub-model adds
  // to it), the same bits (ContactLaw::normal_elastic_energy).
  double normal_elastic_energy(const PairParameters& p, double effective_radius,
                               double delta) const {
    return law_->normal_elastic_energy(p, effective_radius, delta);
  }
  // A rolling-resistance model is part of the contact model (the only reader of
  // ContactKinematics::relative_angular_velocity and effective_inertia; the pair loop skips them
  // without one).
  bool has_rolling() const { return rolling_ != nullptr; }
  const ContactStateStore& layout() const { return layout_; }
  // null unless a module asked for it
  const LoadingRecord* loading() const { return loading_.get(); }
  const CollisionRecord* collisions() const { return collisions_.get(); }
  // null unless a module asked for it; the force loops and modules write it (not part of the
  // contact model's constness)
  ContactStress* stress() const { return stress_.get(); }

  void evaluate(const ContactKinematics& k, const PairParameters& p, const StateRef& s,
                ContactForces& out) const {
    law_->compute(k, p, s, out);
    after_law(k, p, s, out);
  }
  // evaluate() for every contact of a batch: the law in one call, then the optional sub-models
  // contact by contact (each contact's result is the same as evaluate()'s).
  void evaluate(const ContactBatch& b) const {
    law_->compute_batch(b);
    if (!cohesion_ && !rolling_ && !loading_ && !collisions_) return;
    b.for_each([this](const ContactKinematics& k, const PairParameters& p, const StateRef& s,
                      ContactForces& out) { after_law(k, p, s, out); });
  }

 private:
  ContactLaw* law_ = nullptr;
  RollingResistance* rolling_ = nullptr;
  Cohesion* cohesion_ = nullptr;
  // The optional sub-models of one contact, after the law computed `out`.
  void after_law(const ContactKinematics& k, const PairParameters& p, const StateRef& s,
                 ContactForces& out) const {
    double normal = 0, law_force = 0;
    if (collisions_) {  // the law's normal dashpot, before adhesion changes the normal force
      normal = CollisionRecord::normal_dissipation(k, out);
      law_force = out.normal_force;
    }
    if (cohesion_) cohesion_->compute(k, p, out);
    if (rolling_) rolling_->compute(k, p, s, out);
    if (loading_) loading_->record(s, k.overlap, out);
    if (collisions_) collisions_->record(s, k, out, normal, law_force);
  }

  std::unique_ptr<LoadingRecord> loading_;
  std::unique_ptr<CollisionRecord> collisions_;
  std::unique_ptr<ContactStress> stress_;
  bool assembling_ = false;
  ContactStateStore layout_;
};

}  // namespace comminute
