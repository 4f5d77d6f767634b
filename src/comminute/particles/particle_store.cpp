#include "comminute/particles/particle_store.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>

#include "comminute/core/error.hpp"
#include "comminute/core/memory.hpp"
#include "comminute/core/units.hpp"

namespace comminute {

std::uint64_t ParticleStore::add(const ParticleInit& p) {
  const double m = p.density * units::sphere_volume(p.radius);
  return add_with_mass(p, m);
}

std::uint64_t ParticleStore::add_with_mass(const ParticleInit& p, double m) {
  if (!ghost_owner.empty()) throw Error("ParticleStore::add() with ghosts present");
  x.push_back(p.x);
  v.push_back(p.v);
  w.push_back(p.w);
  f.push_back({});
  t.push_back({});
  radius.push_back(p.radius);
  mass.push_back(m);
  inertia.push_back(0.4 * m * p.radius * p.radius);
  id.push_back(next_id_);
  material.push_back(p.material);
  flags.push_back(p.flags);
  for (std::size_t k = 0; k < fields_.size(); ++k) fields_[k].push_back(field_defaults_[k]);
  return next_id_++;
}

std::uint64_t ParticleStore::renew(std::size_t i, const ParticleInit& p, double m) {
  if (!ghost_owner.empty()) throw Error("ParticleStore::renew() with ghosts present");
  put(i, p, m, next_id_);
  return next_id_++;
}

void ParticleStore::put(std::size_t i, const ParticleInit& p, double m, std::uint64_t new_id) {
  x[i] = p.x;
  v[i] = p.v;
  w[i] = p.w;
  f[i] = {};
  t[i] = {};
  radius[i] = p.radius;
  mass[i] = m;
  inertia[i] = 0.4 * m * p.radius * p.radius;
  id[i] = new_id;
  material[i] = p.material;
  flags[i] = p.flags;
  for (std::size_t k = 0; k < fields_.size(); ++k) fields_[k][i] = field_defaults_[k];
}

std::uint64_t ParticleStore::take_ids(std::size_t n) {
  const std::uint64_t first = next_id_;
  next_id_ += n;
  return first;
}

template <class Op>
void ParticleStore::each_array(Op&& op, bool threaded) {
  std::vector<std::function<void()>> jobs{[&] { op(x, Vec3{}); },
                                          [&] { op(v, Vec3{}); },
                                          [&] { op(w, Vec3{}); },
                                          [&] { op(f, Vec3{}); },
                                          [&] { op(t, Vec3{}); },
                                          [&] { op(radius, 0.0); },
                                          [&] { op(mass, 0.0); },
                                          [&] { op(inertia, 0.0); },
                                          [&] { op(id, std::uint64_t{0}); },
                                          [&] { op(material, std::uint16_t{0}); },
                                          [&] { op(flags, std::uint32_t{0}); }};
  for (std::size_t k = 0; k < fields_.size(); ++k)
    jobs.emplace_back([&op, this, k] { op(fields_[k], field_defaults_[k]); });
  const auto n_jobs = static_cast<std::ptrdiff_t>(jobs.size());
#pragma omp parallel for schedule(dynamic) if (threaded)
  for (std::ptrdiff_t k = 0; k < n_jobs; ++k) jobs[static_cast<std::size_t>(k)]();
}

void ParticleStore::extend(std::size_t n) {
  if (!ghost_owner.empty()) throw Error("ParticleStore::extend() with ghosts present");
  const std::size_t to = size() + n;
  // threaded from a size where the copy of a reallocation and the first touch of fresh pages
  // outweigh starting the threads; the new elements' pages made resident in one call per array
  // (core/memory.hpp: fragments are appended every step of a breakage run)
  each_array(
      [to](auto& a, const auto& fresh) {
        make_resident(a, to);
        a.resize(to, fresh);
      },
      to >= 16384);
}

namespace {
template <class T>
// Drops the elements at `removed` (ascending slots): the runs between them are moved down in
// blocks (memmove), the same result as an element-by-element compaction.
void compact_vector(std::vector<T>& a, const std::vector<std::size_t>& removed) {
  if (removed.empty()) return;
  auto out = a.begin() + static_cast<std::ptrdiff_t>(removed[0]);
  for (std::size_t k = 0; k < removed.size(); ++k) {
    const std::size_t from = removed[k] + 1,
                      to = k + 1 < removed.size() ? removed[k + 1] : a.size();
    out = std::move(a.begin() + static_cast<std::ptrdiff_t>(from),
                    a.begin() + static_cast<std::ptrdiff_t>(to), out);
  }
  a.erase(out, a.end());
}
template <class T>
void permute_vector(std::vector<T>& a, const std::vector<std::size_t>& order, std::vector<T>& tmp) {
  tmp.resize(a.size());
  for (std::size_t k = 0; k < order.size(); ++k) tmp[k] = a[order[k]];
  a.swap(tmp);
}
}  // namespace

void ParticleStore::add_ghost(std::size_t owner, const Vec3& gx, const Vec3& gv, const Vec3& gw) {
  const std::size_t o = owner;
  x.push_back(gx);
  v.push_back(gv);
  w.push_back(gw);
  f.push_back({});
  t.push_back({});
  radius.push_back(radius[o]);
  mass.push_back(mass[o]);
  inertia.push_back(inertia[o]);
  id.push_back(id[o]);
  material.push_back(material[o]);
  flags.push_back(flags[o] | pflag::ghost);
  for (auto& fld : fields_) fld.push_back(fld[o]);
  ghost_owner.push_back(static_cast<std::uint32_t>(o));
}

void ParticleStore::drop_ghosts() {
  const std::size_t n = owned();
  x.resize(n);
  v.resize(n);
  w.resize(n);
  f.resize(n);
  t.resize(n);
  radius.resize(n);
  mass.resize(n);
  inertia.resize(n);
  id.resize(n);
  material.resize(n);
  flags.resize(n);
  for (auto& fld : fields_) fld.resize(n);
  ghost_owner.clear();
}

std::size_t ParticleStore::compact() {
  if (!ghost_owner.empty()) throw Error("ParticleStore::compact() with ghosts present");
  const std::size_t before = size();
  std::vector<std::size_t> fl;  // the slots to remove
  for (std::size_t i = 0; i < before; ++i)
    if (flags[i] & pflag::remove) fl.push_back(i);
  if (fl.empty()) return 0;
  each_array([&fl](auto& a, const auto&) { compact_vector(a, fl); }, before >= 16384);
  return before - size();
}

void ParticleStore::permute(const std::vector<std::size_t>& order) {
  if (!ghost_owner.empty()) throw Error("ParticleStore::permute() with ghosts present");
  std::vector<Vec3> tv;
  std::vector<double> td;
  permute_vector(x, order, tv);
  permute_vector(v, order, tv);
  permute_vector(w, order, tv);
  permute_vector(f, order, tv);
  permute_vector(t, order, tv);
  permute_vector(radius, order, td);
  permute_vector(mass, order, td);
  permute_vector(inertia, order, td);
  for (auto& fld : fields_) permute_vector(fld, order, td);
  std::vector<std::uint64_t> ti;
  permute_vector(id, order, ti);
  std::vector<std::uint16_t> tm;
  permute_vector(material, order, tm);
  std::vector<std::uint32_t> tf;
  permute_vector(flags, order, tf);
}

void ParticleStore::clear_forces() {
  for (auto& a : f) a = {};
  for (auto& a : t) a = {};
}

std::size_t ParticleStore::add_field(const std::string& name, double initial_value) {
  for (std::size_t k = 0; k < field_names_.size(); ++k)
    if (field_names_[k] == name) return k;
  field_names_.push_back(name);
  field_defaults_.push_back(initial_value);
  fields_.emplace_back(size(), initial_value);
  if (name == mass_scale_field) scale_ = fields_.size() - 1;
  return fields_.size() - 1;
}

std::size_t ParticleStore::field_index(const std::string& name) const {
  for (std::size_t k = 0; k < field_names_.size(); ++k)
    if (field_names_[k] == name) return k;
  throw Error(fmt::format("no per-particle field named '{}'", name));
}

bool ParticleStore::has_field(const std::string& name) const {
  for (const auto& n : field_names_)
    if (n == name) return true;
  return false;
}

double ParticleStore::total_mass() const {
  double m = 0;
  for (std::size_t i = 0; i < owned(); ++i) m += physical_mass(i);
  return m;
}

Vec3 ParticleStore::total_momentum() const {
  Vec3 p;
  for (std::size_t i = 0; i < owned(); ++i) p += mass[i] * v[i];
  return p;
}

}  // namespace comminute
