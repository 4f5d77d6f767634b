#pragma once
// Per-contact state with an owner. The engine owns one store for particle pairs and one for
// particle–wall contacts; the neighbour list knows geometry only. Each contact sub-model (the
// tangential spring of a law, a rolling spring, breakage's loading record, bonds next) declares
// the slots it needs and how each transforms when the two bodies swap roles; a run pays only for
// the slots its models declared (bytes_per_contact()).
//
// Layout: one plain array per slot (structure of arrays), indexed like the contact list. Hot
// loops take a Slots table of raw pointers once per loop, then StateRef{table, k} per contact.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/core/archive.hpp"
#include "comminute/core/vec3.hpp"

namespace comminute {

// How a slot transforms when contact (i, j) is listed as (j, i): a displacement or torque of i
// relative to j changes sign (negate); a magnitude such as the largest overlap does not (keep).
enum class SwapRule : std::uint8_t { keep, negate };

using SlotId = std::uint32_t;

// Raw pointers to every slot array of a store, valid until its next resize. At most
// max_slots slots of each kind.
struct Slots {
  static constexpr std::size_t max_slots = 16;
  std::array<Vec3*, max_slots> vec3{};
  std::array<float*, max_slots> f32{};
  std::array<double*, max_slots> f64{};
};

// The slots of one contact k, as the contact models see them.
struct StateRef {
  const Slots* slots = nullptr;
  std::size_t k = 0;
  Vec3& vec3(SlotId s) const { return slots->vec3[s][k]; }
  float& f32(SlotId s) const { return slots->f32[s][k]; }
  double& f64(SlotId s) const { return slots->f64[s][k]; }
};

class ContactStateStore;

// One contact's slots held on the stack: fresh (zero), or a copy of contact k of a store, to
// evaluate a contact without touching the store (breakage's energies at rest).
class ContactScratch {
 public:
  ContactScratch();
  ContactScratch(const ContactStateStore& store, std::size_t k);
  ContactScratch(const ContactScratch&) = delete;
  ContactScratch& operator=(const ContactScratch&) = delete;
  StateRef ref() const { return {&slots_, 0}; }
  // Fresh again (zero) in the slots `layout` declares: one scratch kept for many evaluations,
  // cheaper than a new one, which zeroes every slot it could hold.
  void clear(const ContactStateStore& layout);

 private:
  std::array<Vec3, Slots::max_slots> vec3_{};
  std::array<float, Slots::max_slots> f32_{};
  std::array<double, Slots::max_slots> f64_{};
  Slots slots_;
};

class ContactStateStore {
 public:
  static constexpr std::uint32_t none = 0xFFFFFFFFu;

  // Declares a slot (or returns the one already declared under `name` with the same kind and
  // rule; a clash throws). New slots start at zero for every contact.
  SlotId declare_vec3(const std::string& name, SwapRule swap);
  SlotId declare_f32(const std::string& name, SwapRule swap);
  SlotId declare_f64(const std::string& name, SwapRule swap);

  // The slot declared under `name` (throws when there is none).
  SlotId vec3_slot(const std::string& name) const;
  SlotId f32_slot(const std::string& name) const;

  std::size_t size() const { return active.size(); }
  // 1 when the contact touched in the last force computation (its slots hold state), else 0.
  std::vector<std::uint8_t> active;

  // Pointer table for the hot loops; rebuilt by every operation that resizes.
  const Slots& slots() const { return slots_; }
  StateRef at(std::size_t k) const { return {&slots_, k}; }
  // Zeroes every slot of contact k and marks it inactive (the bodies separated).
  void clear(std::size_t k);
  // Maps every vector slot of contact k by f: a contact carried to a rotated periodic image (a
  // sector) turns its springs with it. Every vec3 slot is a vector in the global frame.
  template <class F>
  void map_vectors(std::size_t k, F f) {
    for (auto& c : vec3_) c.data[k] = f(c.data[k]);
  }
  // Contact `to` takes the slots of contact `from` (the same contact under a new key: a sphere
  // rolling onto the next triangle of a mesh) and is active; `from` is cleared.
  void move(std::size_t from, std::size_t to);
  // A new list of `size` contacts, all fresh, but for the carried ones: contact to[e] takes the
  // slots of old contact from[e] (transformed by each slot's rule when reversed[e]) and is active.
  void carry(const std::vector<std::uint32_t>& from, const std::vector<std::uint32_t>& to,
             const std::vector<std::uint8_t>& reversed, std::size_t size);
  // A new list where contact k takes old contact from[k] (none: fresh). In place when every
  // from[k] >= k (breakage's in-place list updates) and the arrays have room; else a parallel
  // copy into new arrays. No spare array is kept between calls.
  void gather(const std::vector<std::uint32_t>& from);
  // The same contacts, those listed in `fresh` (ascending) started afresh, and fresh contacts
  // appended up to `size` (breakage's fragments renewed in their parents' slots).
  void renew(const std::vector<std::uint32_t>& fresh, std::size_t size);
  // An empty store with the same slots.
  ContactStateStore same_layout() const;

  // Bytes of state per contact: every slot plus the active flag.
  std::size_t bytes_per_contact() const;
  std::vector<std::string> slot_names() const;

  // Checkpoint: the slots under prefix + name, and prefix + "active".
  void save(Archive& a, const std::string& prefix) const;
  // Reads what save() wrote; every array must hold `size` contacts (names the entry if not).
  void load(const Archive& a, const std::string& prefix, std::size_t size);

 private:
  template <class T>
  struct Column {
    std::string name;
    SwapRule swap = SwapRule::keep;
    std::vector<T> data;
  };
  std::vector<Column<Vec3>> vec3_;
  std::vector<Column<float>> f32_;
  std::vector<Column<double>> f64_;
  Slots slots_;
  friend class ContactScratch;
  void refresh();
  template <class T>
  SlotId declare(std::vector<Column<T>>& cols, const std::string& name, SwapRule swap);
};

}  // namespace comminute
