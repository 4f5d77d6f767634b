#pragma once
// A named collection of plain arrays: how simulation state is checkpointed. Each part of the
// state (particles, contacts, walls, modules) puts its arrays under its own names; io/checkpoint
// writes the archive to HDF5 and reads it back bit-for-bit.
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "comminute/core/error.hpp"

namespace comminute {

class Archive {
 public:
  template <class T>
  void put(const std::string& name, const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(v.data());
    data_[name].assign(bytes, bytes + v.size() * sizeof(T));
  }
  template <class T>
  void put_value(const std::string& name, const T& x) {
    put(name, std::vector<T>{x});
  }
  template <class T>
  std::vector<T> get(const std::string& name) const {
    auto it = data_.find(name);
    if (it == data_.end()) throw Error("checkpoint has no entry '" + name + "'");
    if (it->second.size() % sizeof(T) != 0)
      throw Error("checkpoint entry '" + name + "' has a wrong size");
    std::vector<T> v(it->second.size() / sizeof(T));
    if (!v.empty()) std::memcpy(v.data(), it->second.data(), it->second.size());
    return v;
  }
  template <class T>
  T get_value(const std::string& name) const {
    auto v = get<T>(name);
    if (v.size() != 1) throw Error("checkpoint entry '" + name + "' is not a single value");
    return v[0];
  }
  bool has(const std::string& name) const { return data_.count(name) > 0; }
  const std::map<std::string, std::vector<std::uint8_t>>& entries() const { return data_; }
  std::map<std::string, std::vector<std::uint8_t>>& entries() { return data_; }

 private:
  std::map<std::string, std::vector<std::uint8_t>> data_;
};

}  // namespace comminute
