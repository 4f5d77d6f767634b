#include "comminute/neighbor/neighbor_list.hpp"

#include <algorithm>
#include <cmath>

#include "comminute/core/memory.hpp"
#include "comminute/core/parallel.hpp"
#include "comminute/neighbor/cell_grid.hpp"

namespace comminute {

namespace {
// Loops shorter than this run on one thread (a thread team costs more).
constexpr std::size_t kThreadedLoop = 16384;
}  // namespace

void NeighborList::make_rows(std::size_t n) {
  // `first` ascends (rows by owner slot): row_[i] is the first pair whose owner is >= i. Pair k
  // sets the rows of the owners after the previous pair's owner up to its own, so the threads
  // share the pairs, not the slots (the low slots own most pairs: a pair is found from the lower
  // of its two slots at a build).
  row_.resize(n + 1);
  const std::size_t m = first.size();
  const std::size_t tail = m == 0 ? 0 : std::size_t{first[m - 1]} + 1;  // owners after the last
  const int nt = m + n >= kThreadedLoop ? max_threads() : 1;
#pragma omp parallel num_threads(nt)
  {
    const auto t = static_cast<std::size_t>(thread_id()), ut = static_cast<std::size_t>(nt);
    for (std::size_t k = m * t / ut; k < m * (t + 1) / ut; ++k)
      for (std::size_t i = k == 0 ? 0 : std::size_t{first[k - 1]} + 1; i <= first[k]; ++i)
        row_[i] = static_cast<std::uint32_t>(k);
    const std::size_t left = n + 1 - std::min(n + 1, tail);
    for (std::size_t i = tail + left * t / ut; i < tail + left * (t + 1) / ut; ++i)
      row_[i] = static_cast<std::uint32_t>(m);
  }
  first_owners_.find(first, second, n, 0);
}

void NeighborList::build(const ParticleStore& p, double skin, const std::vector<std::uint8_t>& keep,
                         const std::vector<std::uint64_t>* labels) {
  // 1. the pairs whose state is to be carried over, by their slots (the ids and labels of the last
  // build are kept aside until the plan is made); reserved to their count, as an array that
  // doubles while it fills briefly holds two copies
  saved_.clear();
  old_labelled_ = labels_.size() == ids_.size();
  const std::size_t n_keep = std::min(keep.size(), first.size());
  make_resident(saved_, static_cast<std::size_t>(std::count_if(
                            keep.begin(), keep.begin() + static_cast<std::ptrdiff_t>(n_keep),
                            [](std::uint8_t k) { return k != 0; })));  // (core/memory.hpp)
  for (std::size_t k = 0; k < n_keep; ++k)
    if (keep[k]) saved_.push_back({first[k], second[k]});
  // slots unchanged since the last build (no sort, insertion or removal, no periodic images): a
  // saved pair keeps its two slots, and neither the old ids nor an id table are needed
  same_slots_ = labels == nullptr && labels_.empty() && ids_ == p.id;
  if (!same_slots_) {
    old_ids_.swap(ids_);
    ids_ = p.id;
  }
  old_labels_.swap(labels_);
  if (labels)
    labels_ = *labels;
  else
    labels_.clear();
  const std::uint32_t n_owned = static_cast<std::uint32_t>(p.owned());

  const std::size_t n = p.size();
  large_.assign(n, 0);
  first.clear();
  second.clear();
  if (n == 0) {
    row_.assign(1, 0);
    carry_ = {};
    return;
  }

  // 2. split by size (the radius copy and the two sets live only until the grids are built)
  index_ = ReachIndex{};  // the last build's grids: replaced below, not needed meanwhile
  double r_ref = 0, r_max = 0;
  {
    std::vector<double> r = p.radius;
    r_max = *std::max_element(r.begin(), r.end());
    const std::size_t q90 = (n * 9) / 10;
    std::nth_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(q90), r.end());
    r_ref = r[q90];
  }
  if (r_max <= 1.5 * r_ref) r_ref = r_max;
  CellGrid small_grid, large_grid;
  bool has_large = false;
  {
    std::vector<std::uint32_t> small_set, large_set;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (p.radius[i] > r_ref) {
        large_[i] = 1;
        large_set.push_back(i);
      } else {
        small_set.push_back(i);
      }
    }
    small_grid.build(p.x, small_set, 2 * r_ref + skin);
    has_large = !large_set.empty();
    if (has_large) large_grid.build(p.x, large_set, 2 * r_max + skin);
  }

  // 3. rows by owner slot, built in parallel chunks and concatenated in order (deterministic).
  // Thread 0 writes straight into first/second (its rows come first), the others into their own
  // arrays, reserved for their share of the last list (untouched reserve is not resident memory),
  // so they seldom grow (a growing array briefly holds its old and new copy).
  const int nt = n >= 4096 ? max_threads() : 1;  // small systems: a thread team costs more
  auto& tf = thread_first_;
  auto& ts = thread_second_;
  tf.resize(static_cast<std::size_t>(nt));
  ts.resize(static_cast<std::size_t>(nt));
  const std::size_t share = last_pairs_ / static_cast<std::size_t>(nt);
  first.reserve(last_pairs_ + last_pairs_ / 4);
  second.reserve(last_pairs_ + last_pairs_ / 4);
  for (int t = 1; t < nt; ++t) {  // (the pages of the share resident at once: core/memory.hpp)
    tf[t].reserve(share + share / 4);
    ts[t].reserve(share + share / 4);
    prefault(tf[t].data(), share * sizeof(std::uint32_t));
    prefault(ts[t].data(), share * sizeof(std::uint32_t));
  }
#pragma omp parallel num_threads(nt)
  {
    const int t = thread_id();
    const std::size_t i0 = n * t / nt, i1 = n * (t + 1) / nt;
    auto& F = t == 0 ? first : tf[t];
    auto& S = t == 0 ? second : ts[t];
    F.clear();
    S.clear();
    for (std::size_t ii = i0; ii < i1; ++ii) {
      const auto i = static_cast<std::uint32_t>(ii);
      const Vec3 xi = p.x[i];
      const double ri = p.radius[i];
      auto consider = [&](std::uint32_t j) {
        if (i >= n_owned && j >= n_owned) return;  // two ghosts: each pair is seen once
        const double cut = ri + p.radius[j] + skin;
        if (norm2(xi - p.x[j]) < cut * cut) {
          F.push_back(i);
          S.push_back(j);
        }
      };
      if (!large_[i]) {
        small_grid.visit_around(small_grid.cell_of(xi), 1, [&](std::uint32_t j) {
          if (j > i) consider(j);
        });
      } else {
        large_grid.visit_around(large_grid.cell_of(xi), 1, [&](std::uint32_t j) {
          if (j > i) consider(j);
        });
        const double cells = std::ceil((ri + r_ref + skin) / small_grid.edge());
        const int reach = cells > 0 ? static_cast<int>(std::min(cells, 1e9)) : 0;
        small_grid.visit_around(small_grid.cell_of(xi), reach, consider);
      }
    }
  }
  if (nt > 1) {
    std::size_t total = first.size();
    for (int t = 1; t < nt; ++t) total += tf[t].size();
    std::size_t at = first.size();
    first.resize(total);
    second.resize(total);
    for (int t = 1; t < nt; ++t) {
      std::copy(tf[t].begin(), tf[t].end(), first.begin() + static_cast<std::ptrdiff_t>(at));
      std::copy(ts[t].begin(), ts[t].end(), second.begin() + static_cast<std::ptrdiff_t>(at));
      at += tf[t].size();
      // released before the contact state is carried into new arrays, which lowers the peak
      // memory of a rebuild (they are allocated anew at the next)
      std::vector<std::uint32_t>().swap(tf[t]);
      std::vector<std::uint32_t>().swap(ts[t]);
    }
  }
  last_pairs_ = first.size();
  make_rows(n);
  plan_carry(p, keep, labels);
  // the saved pairs, their old ids and the id table served plan_carry only: released for the same
  // reason
  std::vector<SavedPair>().swap(saved_);
  std::vector<std::uint64_t>().swap(old_ids_);
  std::vector<std::uint64_t>().swap(old_labels_);
  std::vector<std::pair<std::uint64_t, std::uint32_t>>().swap(slot_of_id_);
  std::vector<std::uint32_t>().swap(slot_by_id_);
  skin_ = skin;
  index_.adopt(std::move(small_grid), std::move(large_grid), has_large, r_ref, r_max, n);
}

void NeighborList::plan_carry(const ParticleStore& p, const std::vector<std::uint8_t>& keep,
                              const std::vector<std::uint64_t>* labels) {
  // 4. find the saved pairs in the new rows, by particle ids (a ghost carries its owner's id: the
  // labels tell the copies apart)
  const std::size_t n = same_slots_ ? 0 : p.size();  // no id table needed with the same slots
  // slot of each id: without ghosts each id has one slot, and when the ids are dense (at most two
  // per slot, the usual case) a table by id - min id holds it in 4 B per id; else a sorted
  // (id, slot) table of 16 B per slot, which also lists the copies of a ghost's id
  std::uint64_t id_lo = 0, id_hi = 0;
  if (n > 0) {
    const auto [lo, hi] = std::minmax_element(p.id.begin(), p.id.end());
    id_lo = *lo;
    id_hi = *hi;
  }
  const bool direct = labels == nullptr && n > 0 && id_hi - id_lo < 2 * n;
  auto& slot = slot_of_id_;
  auto& slot_by_id = slot_by_id_;
  if (direct) {
    make_resident(slot_by_id, id_hi - id_lo + 1);  // (core/memory.hpp)
    slot_by_id.assign(id_hi - id_lo + 1, none);
    for (std::uint32_t i = 0; i < n; ++i) slot_by_id[p.id[i] - id_lo] = i;
  } else {
    make_resident(slot, n);
    slot.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) slot[i] = {p.id[i], i};
    std::sort(slot.begin(), slot.end());
  }
  // the slots holding `id` as a range of (id, slot) entries
  using Entry = std::pair<std::uint64_t, std::uint32_t>;
  auto copies = [&](std::uint64_t id, Entry& one) -> std::pair<const Entry*, const Entry*> {
    if (direct) {
      const bool known = id >= id_lo && id <= id_hi && slot_by_id[id - id_lo] != none;
      one = {id, known ? slot_by_id[id - id_lo] : none};
      return {&one, &one + (known ? 1 : 0)};
    }
    const auto [b, e] =
        std::equal_range(slot.begin(), slot.end(), std::make_pair(id, std::uint32_t{0}),
                         [](const auto& x, const auto& y) { return x.first < y.first; });
    return {slot.data() + (b - slot.begin()), slot.data() + (e - slot.begin())};
  };
  auto label = [labels](std::uint32_t s) { return labels ? (*labels)[s] : std::uint64_t{0}; };
  // the copies (a, b) of the saved pair's bodies whose label difference is the saved one
  auto find_pair = [&](const SavedIds& e, std::uint32_t& a, std::uint32_t& b) {
    Entry one_a, one_b;
    const auto [a0, a1] = copies(e.a, one_a);
    const auto [b0, b1] = copies(e.b, one_b);
    for (auto ia = a0; ia != a1; ++ia)
      for (auto ib = b0; ib != b1; ++ib)
        if (label(ib->second) - label(ia->second) == e.lb - e.la &&
            (ia->second < p.owned() || ib->second < p.owned())) {
          a = ia->second;
          b = ib->second;
          return true;
        }
    return false;
  };
  carry_.from.clear();
  carry_.to.clear();
  carry_.reversed.clear();
  carry_.shift.clear();
  carry_.from.reserve(saved_.size());
  carry_.to.reserve(saved_.size());
  carry_.reversed.reserve(saved_.size());
  if (labels) carry_.shift.reserve(saved_.size());
  std::size_t pair = 0;  // the old index of saved pair e: the e-th flagged in `keep`
  for (const auto& s : saved_) {
    while (!keep[pair]) ++pair;
    const auto old_pair = static_cast<std::uint32_t>(pair++);
    std::uint32_t a = s.a, b = s.b;
    std::uint64_t la = 0;
    if (!same_slots_) {
      const bool lab = old_labelled_;
      const SavedIds e{old_ids_[s.a], old_ids_[s.b], lab ? old_labels_[s.a] : 0,
                       lab ? old_labels_[s.b] : 0, old_pair};
      if (!find_pair(e, a, b)) continue;  // removed particle (or its image is gone)
      la = e.la;
    }
    const std::uint64_t shift = label(a) - la;
    // owner: the large one of a mixed pair, else the smaller slot (pairs added by an in-place
    // update are owned by the fragment: look in the other row too)
    const std::uint32_t saved_owner = a;
    if (large_[a] == large_[b] ? b < a : large_[b] != 0) std::swap(a, b);
    bool found = false;
    for (int attempt = 0; attempt < 2 && !found; ++attempt, std::swap(a, b))
      for (std::uint32_t k = row_[a]; k < row_[a + 1]; ++k)
        if (second[k] == b) {
          carry_.from.push_back(old_pair);
          carry_.to.push_back(k);
          carry_.reversed.push_back(a != saved_owner ? 1 : 0);
          if (labels) carry_.shift.push_back(shift);
          found = true;
          break;
        }
  }
}

std::vector<std::uint32_t> NeighborList::slots_after_removal(const ParticleStore& p) const {
  const std::size_t n_old = ids_.size(), n = p.size();
  std::vector<std::uint32_t> to_new(n_old, none);
  std::size_t q = 0;
  for (std::size_t old = 0; old < n_old; ++old)
    if (q < n && p.id[q] == ids_[old]) to_new[old] = static_cast<std::uint32_t>(q++);
  // every kept particle must have been matched: the rest of `p` holds only appended ones, whose
  // ids (never reused, increasing) are above all ids at the build
  const std::uint64_t max_id = ids_.empty() ? 0 : *std::max_element(ids_.begin(), ids_.end());
  for (std::size_t s = q; s < n; ++s)
    if (p.id[s] <= max_id) return {};
  return to_new;
}

void NeighborList::update_in_place(const ParticleStore& p, const std::vector<std::uint32_t>& to_new,
                                   const std::vector<Vec3>& x_build,
                                   const std::vector<double>& r_build) {
  const std::size_t n = p.size();
  // keep the pairs of kept particles (slots remapped, order kept): each thread counts its share
  // of the list, then copies it to its offset in spare arrays, which are swapped in
  const std::size_t m = first.size();
  const int nt = m >= kThreadedLoop ? max_threads() : 1;
  std::vector<std::size_t> kept(static_cast<std::size_t>(nt) + 1, 0);
  auto range = [m, nt](int t) {
    return std::make_pair(m * static_cast<std::size_t>(t) / static_cast<std::size_t>(nt),
                          m * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(nt));
  };
  auto keeps = [&](std::size_t k) { return to_new[first[k]] != none && to_new[second[k]] != none; };
#pragma omp parallel num_threads(nt)
  {
    const int t = thread_id();
    const auto [k0, k1] = range(t);
    std::size_t c = 0;
    for (std::size_t k = k0; k < k1; ++k) c += keeps(k) ? 1 : 0;
    kept[static_cast<std::size_t>(t) + 1] = c;
#pragma omp barrier
#pragma omp single
    {
      for (int u = 0; u < nt; ++u) kept[u + 1] += kept[u];
      spare_first_.resize(kept[nt]);
      spare_second_.resize(kept[nt]);
      kept_from_.resize(kept[nt]);
    }
    std::size_t w = kept[static_cast<std::size_t>(t)];
    for (std::size_t k = k0; k < k1; ++k) {
      if (!keeps(k)) continue;  // a pair of a removed particle
      spare_first_[w] = to_new[first[k]];
      spare_second_[w] = to_new[second[k]];
      kept_from_[w] = static_cast<std::uint32_t>(k);
      ++w;
    }
  }
  first.swap(spare_first_);
  second.swap(spare_second_);
  index_.remap(to_new);
  // kept slots come first, in order: the new slot of the last kept one tells how many there are
  std::size_t n_kept = 0;
  for (std::size_t old = to_new.size(); old-- > 0;)
    if (to_new[old] != none) {
      n_kept = std::size_t{to_new[old]} + 1;
      break;
    }
  append_rows(n_kept, n, x_build, r_build);
  kept_from_.resize(first.size(), none);
  std::vector<std::uint8_t> large(n, 0);
  const auto n_old = static_cast<std::ptrdiff_t>(to_new.size());
#pragma omp parallel for schedule(static) if (to_new.size() >= kThreadedLoop)
  for (std::ptrdiff_t old = 0; old < n_old; ++old)
    if (to_new[static_cast<std::size_t>(old)] != none)
      large[to_new[static_cast<std::size_t>(old)]] = large_[static_cast<std::size_t>(old)];
  large_ = std::move(large);
  follow_ids(p);
  make_rows(n);
}

void NeighborList::follow_ids(const ParticleStore& p) {
  const std::size_t n = p.size();
  ids_.resize(n);  // ids_ = p.id, on all threads
#pragma omp parallel for schedule(static) if (n >= kThreadedLoop)
  for (std::size_t s = 0; s < n; ++s) ids_[s] = p.id[s];
}

void NeighborList::append_rows(std::size_t n_kept, std::size_t n, const std::vector<Vec3>& x_build,
                               const std::vector<double>& r_build) {
  // rows of the appended particles (the highest slots) follow the kept rows: grouping by owner
  // holds; each row sorted, so the list does not depend on the index's layout. Appended particle
  // s pairs with every kept particle and every appended one before it (j < s): all are indexed
  // first, then the rows are searched on all threads and concatenated in slot order, the same
  // list as inserting them one by one.
  for (std::size_t s = n_kept; s < n; ++s)
    index_.insert(static_cast<std::uint32_t>(s), x_build[s], r_build[s]);
  const std::size_t n_new = n - std::min(n, n_kept);
  std::vector<std::vector<std::uint32_t>> rows(n_new);
#pragma omp parallel for schedule(dynamic, 16) if (n_new >= 64)
  for (std::size_t q = 0; q < n_new; ++q) {
    const std::size_t s = n_kept + q;
    auto& row = rows[q];
    index_.visit_near(x_build[s], r_build[s], skin_, [&](std::uint32_t j) {
      if (j >= s) return;
      const double cut = r_build[s] + r_build[j] + skin_;
      if (norm2(x_build[s] - x_build[j]) < cut * cut) row.push_back(j);
    });
    std::sort(row.begin(), row.end());
  }
  std::size_t appended = 0;
  for (const auto& row : rows) appended += row.size();
  make_resident(first, first.size() + appended);  // (core/memory.hpp)
  make_resident(second, second.size() + appended);
  for (std::size_t q = 0; q < n_new; ++q)
    for (std::uint32_t j : rows[q]) {
      first.push_back(static_cast<std::uint32_t>(n_kept + q));
      second.push_back(j);
    }
}

std::vector<std::uint32_t> NeighborList::pairs_flagged(
    const std::vector<std::uint8_t>& flagged) const {
  return parallel_filter(
      first.size(), [&](std::size_t k) { return (flagged[first[k]] | flagged[second[k]]) != 0; },
      kThreadedLoop);
}

void NeighborList::renew_in_place(const ParticleStore& p, const std::vector<Vec3>& x_build,
                                  const std::vector<double>& r_build) {
  const std::size_t n_old = ids_.size(), n = p.size(), m_old = first.size();
  append_rows(n_old, n, x_build, r_build);
  first_owners_.find(first, second, n, m_old);  // (the kept pairs stay where they were)
  large_.resize(n, 0);
  follow_ids(p);  // (the renewed slots' ids and the appended ones' are new)
  // the rows of the kept owners are unchanged; the appended owners' rows follow
  row_.resize(n + 1);
  std::size_t k = m_old;
  for (std::size_t i = n_old; i <= n; ++i) {
    while (k < first.size() && first[k] < i) ++k;
    row_[i] = static_cast<std::uint32_t>(k);
  }
  kept_from_.clear();
}

void NeighborList::rebuild_index(const std::vector<Vec3>& x_build,
                                 const std::vector<double>& r_build, double skin) {
  skin_ = skin;
  index_.build(x_build, r_build, skin);
}

std::vector<std::size_t> NeighborList::cell_order(const ParticleStore& p, double cell) {
  std::vector<std::uint32_t> all(p.size());
  for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  CellGrid g;
  g.build(p.x, all, cell);
  std::vector<std::size_t> order(g.items().begin(), g.items().end());
  return order;
}

void NeighborList::restore(std::vector<std::uint32_t> f, std::vector<std::uint32_t> s,
                           std::vector<std::uint64_t> ids, std::vector<std::uint8_t> large,
                           std::vector<std::uint64_t> labels) {
  labels_ = std::move(labels);
  first = std::move(f);
  second = std::move(s);
  ids_ = std::move(ids);
  large_ = std::move(large);
  make_rows(ids_.size());
  index_.clear();
}

}  // namespace comminute
