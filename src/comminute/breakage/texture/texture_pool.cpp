#include "comminute/breakage/texture/texture_pool.hpp"

#include <algorithm>

#include "comminute/core/error.hpp"

namespace comminute::breakage::texture {

TexturePool::TexturePool(std::size_t phases) : phases_(phases) {
  if (phases_ < 1 || phases_ > 255) throw Error("texture pool: 1 to 255 phases");
  bits_ = phases_ <= 2 ? 1 : phases_ <= 4 ? 2 : phases_ <= 16 ? 4 : 8;  // divides 64: no straddling
}

std::size_t TexturePool::words_for(std::size_t n) const {
  return (n * n * n * bits_ + 63) / 64;
}

void TexturePool::put(std::uint64_t owner, const Cube& c) {
  if (c.labels.size() != c.n * c.n * c.n || c.n == 0)
    throw Error("texture pool: cube size mismatch");
  erase(owner);
  Entry e{words_.size(), static_cast<std::uint32_t>(c.n)};
  const std::size_t w = words_for(c.n);
  words_.resize(words_.size() + w, 0);
  const unsigned per_word = 64 / bits_;
  for (std::size_t v = 0; v < c.labels.size(); ++v) {
    if (c.labels[v] >= phases_) throw Error("texture pool: label out of range");
    words_[e.offset + v / per_word] |= std::uint64_t{c.labels[v]} << ((v % per_word) * bits_);
  }
  entries_[owner] = e;
  live_words_ += w;
}

Cube TexturePool::get(std::uint64_t owner) const {
  const auto it = entries_.find(owner);
  if (it == entries_.end())
    throw Error("texture pool: no texture for particle " + std::to_string(owner));
  Cube c;
  c.n = it->second.n;
  c.labels.resize(c.n * c.n * c.n);
  const unsigned per_word = 64 / bits_;
  const std::uint64_t mask = (std::uint64_t{1} << bits_) - 1;
  for (std::size_t v = 0; v < c.labels.size(); ++v)
    c.labels[v] = static_cast<std::uint8_t>(
        (words_[it->second.offset + v / per_word] >> ((v % per_word) * bits_)) & mask);
  return c;
}

std::size_t TexturePool::resolution(std::uint64_t owner) const {
  const auto it = entries_.find(owner);
  return it == entries_.end() ? 0 : it->second.n;
}

std::vector<std::uint64_t> TexturePool::counts(std::uint64_t owner) const {
  std::vector<std::uint64_t> n(phases_, 0);
  for (std::uint8_t l : get(owner).labels) ++n[l];
  return n;
}

void TexturePool::erase(std::uint64_t owner) {
  const auto it = entries_.find(owner);
  if (it == entries_.end()) return;
  live_words_ -= words_for(it->second.n);
  entries_.erase(it);
  if (words_.size() > 2 * live_words_ + 1024) reclaim();
}

void TexturePool::reclaim() {
  std::vector<std::pair<std::uint64_t, Entry>> order(entries_.begin(), entries_.end());
  std::sort(order.begin(), order.end(),
            [](const auto& a, const auto& b) { return a.second.offset < b.second.offset; });
  std::vector<std::uint64_t> packed;
  packed.reserve(live_words_);
  for (auto& [owner, e] : order) {
    const std::size_t w = words_for(e.n);
    const std::size_t at = packed.size();
    packed.insert(packed.end(), words_.begin() + static_cast<std::ptrdiff_t>(e.offset),
                  words_.begin() + static_cast<std::ptrdiff_t>(e.offset + w));
    entries_[owner].offset = at;
  }
  words_ = std::move(packed);
}

std::size_t TexturePool::bytes() const {
  // packed labels plus the index: a hash node holds the key, the entry and about two pointers
  return live_bytes() +
         entries_.size() * (sizeof(std::uint64_t) + sizeof(Entry) + 2 * sizeof(void*));
}

std::vector<std::uint64_t> TexturePool::owners() const {
  std::vector<std::uint64_t> o;
  o.reserve(entries_.size());
  for (const auto& entry : entries_) o.push_back(entry.first);
  std::sort(o.begin(), o.end());
  return o;
}

void TexturePool::save(Archive& a, const std::string& prefix) const {
  // Entries sorted by owner so the archive does not depend on the hash order.
  const std::vector<std::uint64_t> owners = this->owners();
  std::vector<std::uint32_t> n;
  std::vector<std::uint64_t> packed;
  for (std::uint64_t o : owners) {
    const Entry& e = entries_.at(o);
    n.push_back(e.n);
    packed.insert(packed.end(), words_.begin() + static_cast<std::ptrdiff_t>(e.offset),
                  words_.begin() + static_cast<std::ptrdiff_t>(e.offset + words_for(e.n)));
  }
  a.put(prefix + "owners", owners);
  a.put(prefix + "resolution", n);
  a.put(prefix + "words", packed);
  a.put_value(prefix + "phases", static_cast<std::uint32_t>(phases_));
}

void TexturePool::load(const Archive& a, const std::string& prefix) {
  const auto phases = a.get_value<std::uint32_t>(prefix + "phases");
  if (phases != phases_)
    throw Error("checkpoint texture pool has " + std::to_string(phases) + " phases, the case " +
                std::to_string(phases_));
  const auto owners = a.get<std::uint64_t>(prefix + "owners");
  const auto n = a.get<std::uint32_t>(prefix + "resolution");
  words_ = a.get<std::uint64_t>(prefix + "words");
  if (n.size() != owners.size()) throw Error("checkpoint texture pool: size mismatch");
  entries_.clear();
  live_words_ = 0;
  for (std::size_t k = 0; k < owners.size(); ++k) {
    entries_[owners[k]] = {live_words_, n[k]};
    live_words_ += words_for(n[k]);
  }
  if (live_words_ != words_.size()) throw Error("checkpoint texture pool: word count mismatch");
}

}  // namespace comminute::breakage::texture
