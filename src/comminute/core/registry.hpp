#pragma once
// A registry by name for one model family (LAMMPS-style plug-ins). A model file registers itself
//   static const bool reg = ContactLawRegistry::add("hertz_mindlin", &make_hertz_mindlin);
// and the case file picks it by name. The library is an OBJECT library, so these statics always
// run. Unknown names fail with the list of known ones; a second model under a name already taken is
// refused (std::logic_error, at start-up: two files claiming one name is a programming error).
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace comminute {

template <class Interface, class... Args>
class Registry {
 public:
  using Factory = std::function<std::unique_ptr<Interface>(Args...)>;

  static bool add(const std::string& name, Factory f) {
    if (!table().emplace(name, std::move(f)).second)
      throw std::logic_error("two models registered under the name \"" + name + "\"");
    return true;
  }
  static bool contains(const std::string& name) { return table().count(name) > 0; }
  // Returns nullptr when the name is unknown; callers turn that into an InputError naming the
  // key (they know the file and line), listing names().
  static std::unique_ptr<Interface> create(const std::string& name, Args... args) {
    auto it = table().find(name);
    if (it == table().end()) return nullptr;
    return it->second(std::forward<Args>(args)...);
  }
  static std::vector<std::string> names() {
    std::vector<std::string> out;
    for (const auto& [k, v] : table()) out.push_back(k);
    return out;
  }

 private:
  static std::map<std::string, Factory>& table() {
    static std::map<std::string, Factory> t;
    return t;
  }
};

}  // namespace comminute
