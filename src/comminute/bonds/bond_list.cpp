#include "comminute/bonds/bond_list.hpp"

#include <algorithm>
#include <utility>

#include "comminute/core/error.hpp"
#include "comminute/engine/parallel_threshold.hpp"

namespace comminute::bonds {

void BondList::reserve(std::size_t n) {
  id_i.reserve(n);
  id_j.reserve(n);
  slot_i.reserve(n);
  slot_j.reserve(n);
  state.reserve(n);
}

void BondList::add(std::uint64_t a, std::uint32_t sa, std::uint64_t b, std::uint32_t sb,
                   const BondState& s) {
  id_i.push_back(a);
  id_j.push_back(b);
  slot_i.push_back(sa);
  slot_j.push_back(sb);
  state.push_back(s);
}

bool BondList::current(const ParticleStore& p) const {
  const std::size_t n = p.owned();  // ghosts (periodic images) are never bonded
  const std::uint64_t* id = p.id.data();
  auto valid = [&](std::uint32_t slot, std::uint64_t want) { return slot < n && id[slot] == want; };
  const auto nb = static_cast<std::int64_t>(size());
  bool ok = true;
#pragma omp parallel for schedule(static) reduction(&& : ok) if (size() >= kParallelMin)
  for (std::int64_t bi = 0; bi < nb; ++bi) {
    const auto b = static_cast<std::size_t>(bi);
    ok = ok && valid(slot_i[b], id_i[b]) && valid(slot_j[b], id_j[b]);
  }
  return ok;
}

std::vector<std::size_t> BondList::locate(const ParticleStore& p) {
  const std::size_t n = p.owned();  // ghosts (periodic images) are never bonded
  std::vector<std::size_t> lost;
  if (current(p)) return lost;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> by_id(n);
  for (std::size_t s = 0; s < n; ++s) by_id[s] = {p.id[s], static_cast<std::uint32_t>(s)};
  std::sort(by_id.begin(), by_id.end());
  auto find = [&](std::uint64_t id) {
    auto it = std::lower_bound(by_id.begin(), by_id.end(), std::pair{id, std::uint32_t{0}});
    return it != by_id.end() && it->first == id ? it->second : none;
  };
  for (std::size_t b = 0; b < size(); ++b) {
    slot_i[b] = find(id_i[b]);
    slot_j[b] = find(id_j[b]);
    if (slot_i[b] == none || slot_j[b] == none) lost.push_back(b);
  }
  return lost;
}

void BondList::remove(const std::vector<std::uint8_t>& gone) {
  std::size_t k = 0;
  for (std::size_t b = 0; b < size(); ++b) {
    if (gone[b]) continue;
    id_i[k] = id_i[b];
    id_j[k] = id_j[b];
    slot_i[k] = slot_i[b];
    slot_j[k] = slot_j[b];
    state.move(b, k);
    ++k;
  }
  id_i.resize(k);
  id_j.resize(k);
  slot_i.resize(k);
  slot_j.resize(k);
  state.resize(k);
}

void BondList::save(Archive& a, const std::string& prefix) const {
  a.put(prefix + "id_i", id_i);
  a.put(prefix + "id_j", id_j);
  a.put(prefix + "state", state.records());  // whole records: the split is not in the file
}

void BondList::load(const Archive& a, const std::string& prefix) {
  id_i = a.get<std::uint64_t>(prefix + "id_i");
  id_j = a.get<std::uint64_t>(prefix + "id_j");
  const std::vector<BondState> records = a.get<BondState>(prefix + "state");
  if (id_j.size() != id_i.size() || records.size() != id_i.size())
    throw Error("checkpoint entries '" + prefix + "id_i', 'id_j' and 'state' differ in length");
  for (const BondState& s : records)
    if (!(s.radius > 0) || !(s.length0 > 0) || !(s.damage >= 0 && s.damage < 1) ||
        s.failed != FailureMode::none)
      throw Error("checkpoint entry '" + prefix + "state' holds an invalid bond");
  state.assign(records);
  slot_i.assign(size(), none);
  slot_j.assign(size(), none);
}

}  // namespace comminute::bonds
