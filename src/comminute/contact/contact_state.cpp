#include "comminute/contact/contact_state.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <limits>

#include "comminute/core/error.hpp"
#include "comminute/core/memory.hpp"
#include "comminute/core/parallel.hpp"

namespace comminute {

namespace {

template <class T>
T swapped(const T& v, SwapRule rule) {
  return rule == SwapRule::negate ? -v : v;
}
}  // namespace

template <class T>
SlotId ContactStateStore::declare(std::vector<Column<T>>& cols, const std::string& name,
                                  SwapRule swap) {
  for (SlotId s = 0; s < cols.size(); ++s)
    if (cols[s].name == name) {
      if (cols[s].swap != swap)
        throw Error(
            fmt::format("contact-state slot '{}' declared twice with different rules", name));
      return s;
    }
  for (const auto& other : slot_names())
    if (other == name)
      throw Error(fmt::format("contact-state slot '{}' declared twice with different types", name));
  if (cols.size() == Slots::max_slots)
    throw Error(fmt::format("contact-state slot '{}': more than {} slots of one kind", name,
                            Slots::max_slots));
  cols.push_back({name, swap, std::vector<T>(size(), T{})});
  refresh();
  return static_cast<SlotId>(cols.size() - 1);
}

SlotId ContactStateStore::declare_vec3(const std::string& name, SwapRule swap) {
  return declare(vec3_, name, swap);
}
SlotId ContactStateStore::declare_f32(const std::string& name, SwapRule swap) {
  return declare(f32_, name, swap);
}
SlotId ContactStateStore::declare_f64(const std::string& name, SwapRule swap) {
  return declare(f64_, name, swap);
}

namespace {
template <class Cols>
SlotId find_slot(const Cols& cols, const std::string& name) {
  for (SlotId s = 0; s < cols.size(); ++s)
    if (cols[s].name == name) return s;
  throw Error(fmt::format("no contact-state slot '{}' is declared", name));
}
}  // namespace

SlotId ContactStateStore::vec3_slot(const std::string& name) const {
  return find_slot(vec3_, name);
}
SlotId ContactStateStore::f32_slot(const std::string& name) const {
  return find_slot(f32_, name);
}

void ContactStateStore::refresh() {
  for (std::size_t s = 0; s < vec3_.size(); ++s) slots_.vec3[s] = vec3_[s].data.data();
  for (std::size_t s = 0; s < f32_.size(); ++s) slots_.f32[s] = f32_[s].data.data();
  for (std::size_t s = 0; s < f64_.size(); ++s) slots_.f64[s] = f64_[s].data.data();
}

ContactScratch::ContactScratch() {
  for (std::size_t s = 0; s < Slots::max_slots; ++s) {
    slots_.vec3[s] = &vec3_[s];
    slots_.f32[s] = &f32_[s];
    slots_.f64[s] = &f64_[s];
  }
}

ContactScratch::ContactScratch(const ContactStateStore& store, std::size_t k) : ContactScratch() {
  for (std::size_t s = 0; s < store.vec3_.size(); ++s) vec3_[s] = store.vec3_[s].data[k];
  for (std::size_t s = 0; s < store.f32_.size(); ++s) f32_[s] = store.f32_[s].data[k];
  for (std::size_t s = 0; s < store.f64_.size(); ++s) f64_[s] = store.f64_[s].data[k];
}

void ContactScratch::clear(const ContactStateStore& layout) {
  std::fill_n(vec3_.begin(), layout.vec3_.size(), Vec3{});
  std::fill_n(f32_.begin(), layout.f32_.size(), 0.0f);
  std::fill_n(f64_.begin(), layout.f64_.size(), 0.0);
}

void ContactStateStore::clear(std::size_t k) {
  active[k] = 0;
  for (auto& c : vec3_) c.data[k] = Vec3{};
  for (auto& c : f32_) c.data[k] = 0.0f;
  for (auto& c : f64_) c.data[k] = 0.0;
}

void ContactStateStore::renew(const std::vector<std::uint32_t>& fresh, std::size_t size) {
  for (const std::uint32_t k : fresh) clear(k);
  // (the pairs of appended fragments: their pages made resident in one call, core/memory.hpp)
  const auto grow = [size](auto& column, auto fresh_value) {
    make_resident(column, size);
    column.resize(size, fresh_value);
  };
  grow(active, std::uint8_t{0});
  for (auto& c : vec3_) grow(c.data, Vec3{});
  for (auto& c : f32_) grow(c.data, 0.0f);
  for (auto& c : f64_) grow(c.data, 0.0);
  refresh();
}

void ContactStateStore::move(std::size_t from, std::size_t to) {
  for (auto& c : vec3_) c.data[to] = c.data[from];
  for (auto& c : f32_) c.data[to] = c.data[from];
  for (auto& c : f64_) c.data[to] = c.data[from];
  active[to] = 1;
  clear(from);
}

namespace {
// `data` becomes `size` copies of `fresh`. A column that must grow is released before the larger
// one is allocated (std::vector::assign would hold both): what it held is no longer needed, and the
// peak memory of a neighbour rebuild stays one column, not two. It is reserved 1/8 larger, so that
// the next lists, a little longer, are carried in place (reserve that is never written is not
// resident memory).
template <class T>
void refill(std::vector<T>& data, std::size_t size, T fresh) {
  if (size > data.capacity()) {
    std::vector<T>().swap(data);
    data.reserve(size + size / 8);
  }
  make_resident(data, size);  // (fresh pages: core/memory.hpp)
  data.assign(size, fresh);
}

// Loops over this many contacts or more run on all threads.
constexpr std::size_t kThreadedCarry = 16384;

// The carry e' that reads old slot q (from[e'] == q), or from.size() when none does: from[] rises,
// and the carry that reads the slot another carry e writes is found near e (the lists keep their
// order, so the slots of a pair drift little between builds), so it is searched outwards from e
// in doubling steps, then bisected.
std::size_t source_near(const std::vector<std::uint32_t>& from, std::size_t q, std::size_t e) {
  const std::size_t m = from.size();
  std::size_t lo = 0, hi = m;  // from[lo - 1] < q <= from[hi]: the answer lies in [lo, hi)
  if (from[e] < q) {
    std::size_t step = 1;
    lo = e + 1;
    while (lo + step - 1 < m && from[lo + step - 1] < q) {
      lo += step;
      step *= 2;
    }
    hi = std::min(m, lo + step - 1);
  } else {
    std::size_t step = 1;
    hi = e;
    while (hi >= step && from[hi - step] >= q) {
      hi -= step;
      step *= 2;
    }
    lo = hi >= step ? hi - step + 1 : 0;
  }
  const auto it = std::lower_bound(from.begin() + static_cast<std::ptrdiff_t>(lo),
                                   from.begin() + static_cast<std::ptrdiff_t>(hi), q);
  return it != from.end() && *it == q ? static_cast<std::size_t>(it - from.begin()) : m;
}

// Column c of the new list: fresh everywhere but at to[e], which takes old from[e]. When the
// column has room and from[] rises (the neighbour list's plans), the values move in place along
// chains: the value that leaves for to[e] displaces the one there, which the carry whose source
// that is takes next, so each value is read before it is overwritten and no second copy of the
// column or of the carried values is held. Else the carried values are gathered first, so only
// they are held twice, not the whole column.
//
// The chains are disjoint (each slot is written by one carry and read by at most one), so they
// are followed on all threads: a thread walks the chains that start in its share of the carries
// (a chain starts at a carry whose source slot no carry writes), never a slot of another's chain.
// What is left are closed cycles, walked on one thread after. The result is that of any order.
template <class T>
void carry_column(std::vector<T>& data, SwapRule rule, const std::vector<std::uint32_t>& from,
                  const std::vector<std::uint32_t>& to, const std::vector<std::uint8_t>& reversed,
                  const std::vector<std::uint8_t>& carried_to, std::size_t size, bool rising) {
  const std::size_t m = from.size();
  const int nt = std::max(m, size) >= kThreadedCarry ? max_threads() : 1;
  const auto sm = static_cast<std::ptrdiff_t>(m), ssize = static_cast<std::ptrdiff_t>(size);
  if (!rising || size > data.capacity()) {
    std::vector<T> kept;
    make_resident(kept, m);  // (fresh pages: core/memory.hpp)
    kept.resize(m);
#pragma omp parallel for schedule(static) num_threads(nt)
    for (std::ptrdiff_t e = 0; e < sm; ++e)
      kept[e] = reversed[e] ? swapped(data[from[e]], rule) : data[from[e]];
    refill(data, size, T{});
#pragma omp parallel for schedule(static) num_threads(nt)
    for (std::ptrdiff_t e = 0; e < sm; ++e) data[to[e]] = kept[e];
    return;
  }
  if (size > data.size()) data.resize(size, T{});  // within the capacity: no copy
  const std::size_t n_read = data.size();          // slots a carry may read: below this
  std::vector<std::uint8_t> done(m, 0);
  auto walk = [&](std::size_t e) {
    T v = reversed[e] ? swapped(data[from[e]], rule) : data[from[e]];
    while (true) {
      done[e] = 1;
      const std::size_t q = to[e];
      const std::size_t next = q < n_read ? source_near(from, q, e) : m;
      if (next == m || done[next]) {
        data[q] = v;
        break;
      }
      const T w = data[q];  // still the old value: its carry has not run
      data[q] = v;
      e = next;
      v = reversed[e] ? swapped(w, rule) : w;
    }
  };
#pragma omp parallel for schedule(static) num_threads(nt)
  for (std::ptrdiff_t e = 0; e < sm; ++e) {
    const std::size_t src = from[e];
    if (src >= size || !carried_to[src]) walk(static_cast<std::size_t>(e));  // a chain's start
  }
  for (std::size_t e = 0; e < m; ++e)  // closed cycles
    if (!done[e]) walk(e);
  data.resize(size);
#pragma omp parallel for schedule(static) num_threads(nt)
  for (std::ptrdiff_t q = 0; q < ssize; ++q)
    if (!carried_to[q]) data[q] = T{};
}

// True when every carried contact k takes an old contact from[k] >= k (the in-place updates of
// breakage: pairs of removed particles dropped, order kept, new pairs appended): a pass in
// rising k then reads each old value before it is overwritten.
bool gathers_forward(const std::vector<std::uint32_t>& from) {
  const auto n = static_cast<std::ptrdiff_t>(from.size());
  bool forward = true;
#pragma omp parallel for schedule(static) reduction(&& : forward) if (n >= static_cast <std::ptrdiff_t>(kThreadedCarry))
  for (std::ptrdiff_t k = 0; k < n; ++k)
    forward =
        forward && (from[k] == ContactStateStore::none || from[k] >= static_cast<std::size_t>(k));
  return forward;
}

// Contacts [to, to + length) of a forward gather take old contacts [from, from + length)
// (from == none: fresh ones).
struct GatherRun {
  std::size_t to, from, length;
};

// The runs of contacts [k0, k1), each cut where its sources reach `limit`.
std::vector<GatherRun> forward_runs(const std::vector<std::uint32_t>& from, std::size_t k0,
                                    std::size_t k1, std::size_t limit) {
  constexpr std::uint32_t none = ContactStateStore::none;
  std::vector<GatherRun> runs;
  for (std::size_t k = k0; k < k1;) {
    std::size_t e = k + 1;
    if (from[k] == none) {
      while (e < k1 && from[e] == none) ++e;
    } else {
      const bool above = from[k] >= limit;
      while (e < k1 && from[e] != none && from[e] == from[e - 1] + 1 && (from[e] >= limit) == above)
        ++e;
    }
    runs.push_back({k, from[k], e - k});
    k = e;
  }
  return runs;
}

// Appends to `saved` the old values the runs read at or above `limit` (before they are
// overwritten).
template <class T>
void save_runs(const std::vector<T>& data, const std::vector<GatherRun>& runs, std::size_t limit,
               std::vector<std::byte>& saved) {
  for (const GatherRun& r : runs)
    if (r.from != ContactStateStore::none && r.from >= limit) {
      const std::size_t at = saved.size();
      saved.resize(at + r.length * sizeof(T));
      std::memcpy(&saved[at], &data[r.from], r.length * sizeof(T));
    }
}

// Moves the runs in rising order (a run's sources lie at or after its contacts): those read at or
// above `limit` from `saved`, in order.
template <class T>
void move_runs(std::vector<T>& data, const std::vector<GatherRun>& runs, std::size_t limit,
               const std::vector<std::byte>& saved) {
  std::size_t at = 0;
  for (const GatherRun& r : runs) {
    if (r.from == ContactStateStore::none) {
      std::fill_n(data.begin() + static_cast<std::ptrdiff_t>(r.to), r.length, T{});
    } else if (r.from >= limit) {
      std::memcpy(&data[r.to], &saved[at], r.length * sizeof(T));
      at += r.length * sizeof(T);
    } else if (r.from != r.to) {
      std::memmove(&data[r.to], &data[r.from], r.length * sizeof(T));
    }
  }
}

// Contact k of the new column takes old contact from[k] (none: fresh), copied into a new column
// (reserved 1/8 larger, so that the next lists are gathered in place); the old one is freed.
template <class T>
void gather_copy(std::vector<T>& data, const std::vector<std::uint32_t>& from) {
  const std::size_t n = from.size();
  std::vector<T> out;
  out.reserve(n + n / 8);
  out.resize(n);
  const int nt = n >= kThreadedCarry ? max_threads() : 1;
#pragma omp parallel for schedule(static) num_threads(nt)
  for (std::size_t k = 0; k < n; ++k)
    out[k] = from[k] == ContactStateStore::none ? T{} : data[from[k]];
  data.swap(out);
}
}  // namespace

void ContactStateStore::carry(const std::vector<std::uint32_t>& from,
                              const std::vector<std::uint32_t>& to,
                              const std::vector<std::uint8_t>& reversed, std::size_t size) {
  // the new flags first: they tell the columns which contacts are fresh (each carry writes its
  // own flag: distinct slots, on all threads)
  refill(active, size, std::uint8_t{0});
  const auto m = static_cast<std::ptrdiff_t>(to.size());
#pragma omp parallel for schedule(static) if (m >= static_cast <std::ptrdiff_t>(kThreadedCarry))
  for (std::ptrdiff_t e = 0; e < m; ++e) active[to[e]] = 1;
  const bool rising = std::adjacent_find(from.begin(), from.end(),
                                         [](auto a, auto b) { return a >= b; }) == from.end();
  for (auto& c : vec3_) carry_column(c.data, c.swap, from, to, reversed, active, size, rising);
  for (auto& c : f32_) carry_column(c.data, c.swap, from, to, reversed, active, size, rising);
  for (auto& c : f64_) carry_column(c.data, c.swap, from, to, reversed, active, size, rising);
  refresh();
}

// A forward gather within a column's capacity moves the values in place, a run of consecutive
// sources at a time (memmove), so no second column is allocated or kept; any other gather copies
// (gather_copy). In place, thread t of nt takes contacts [n t / nt, n (t + 1) / nt) of every such
// column: it first saves the old values it reads in a later thread's range (at or above its own
// range's end), then, once all have, moves its runs; the result is that of one thread.
void ContactStateStore::gather(const std::vector<std::uint32_t>& from) {
  const std::size_t n = from.size();
  const bool forward = gathers_forward(from);
  auto each = [this](auto&& f) {
    for (auto& c : vec3_) f(c.data);
    for (auto& c : f32_) f(c.data);
    for (auto& c : f64_) f(c.data);
    f(active);
  };
  std::vector<std::uint8_t> in_place;  // per column, in the order of each()
  each([&](auto& data) {
    in_place.push_back(forward && n <= data.capacity());
    if (in_place.back() && n > data.size()) data.resize(n);  // within the capacity: no copy
  });
  const int nt = n >= kThreadedCarry ? max_threads() : 1;
  if (std::find(in_place.begin(), in_place.end(), 1) != in_place.end()) {
#pragma omp parallel num_threads(nt)
    {
      const auto t = static_cast<std::size_t>(thread_id()), m = static_cast<std::size_t>(nt);
      const std::size_t k1 = n * (t + 1) / m;
      const std::size_t limit = t + 1 < m ? k1 : std::numeric_limits<std::size_t>::max();
      const std::vector<GatherRun> runs = forward_runs(from, n * t / m, k1, limit);
      std::vector<std::vector<std::byte>> saved(in_place.size());
      std::size_t c = 0;
      each([&](auto& data) {
        if (in_place[c]) save_runs(data, runs, limit, saved[c]);
        ++c;
      });
#pragma omp barrier
      c = 0;
      each([&](auto& data) {
        if (in_place[c]) move_runs(data, runs, limit, saved[c]);
        ++c;
      });
    }
  }
  std::size_t c = 0;
  each([&](auto& data) {
    if (in_place[c++])
      data.resize(n);
    else
      gather_copy(data, from);
  });
  refresh();
}

ContactStateStore ContactStateStore::same_layout() const {
  ContactStateStore s;
  for (const auto& c : vec3_) s.vec3_.push_back({c.name, c.swap, {}});
  for (const auto& c : f32_) s.f32_.push_back({c.name, c.swap, {}});
  for (const auto& c : f64_) s.f64_.push_back({c.name, c.swap, {}});
  s.refresh();
  return s;
}

std::size_t ContactStateStore::bytes_per_contact() const {
  return vec3_.size() * sizeof(Vec3) + f32_.size() * sizeof(float) + f64_.size() * sizeof(double) +
         sizeof(std::uint8_t);
}

std::vector<std::string> ContactStateStore::slot_names() const {
  std::vector<std::string> out;
  for (const auto& c : vec3_) out.push_back(c.name);
  for (const auto& c : f32_) out.push_back(c.name);
  for (const auto& c : f64_) out.push_back(c.name);
  return out;
}

void ContactStateStore::save(Archive& a, const std::string& prefix) const {
  for (const auto& c : vec3_) a.put(prefix + c.name, c.data);
  for (const auto& c : f32_) a.put(prefix + c.name, c.data);
  for (const auto& c : f64_) a.put(prefix + c.name, c.data);
  a.put(prefix + "active", active);
}

namespace {
template <class T>
void load_column(const Archive& a, const std::string& entry, std::size_t size,
                 std::vector<T>& out) {
  out = a.get<T>(entry);
  if (out.size() != size)
    throw Error(fmt::format("checkpoint entry '{}' holds {} contacts, the contact list {}", entry,
                            out.size(), size));
}
}  // namespace

void ContactStateStore::load(const Archive& a, const std::string& prefix, std::size_t size) {
  for (auto& c : vec3_) load_column(a, prefix + c.name, size, c.data);
  for (auto& c : f32_) load_column(a, prefix + c.name, size, c.data);
  for (auto& c : f64_) load_column(a, prefix + c.name, size, c.data);
  load_column(a, prefix + "active", size, active);
  refresh();
}

}  // namespace comminute
