// Every model registered by name has its row in the docs: for each registry below, every name of
// Registry::names() starts a table row "| `name`" of its doc file. Another registry is one line of
// kFamilies.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "comminute/contact/cohesion.hpp"
#include "comminute/contact/contact_law.hpp"
#include "comminute/contact/rolling_resistance.hpp"
#include "comminute/geometry/wall.hpp"
#include "comminute/particles/size_distribution.hpp"

using namespace comminute;

namespace {

struct Family {
  const char* registry;
  std::vector<std::string> (*names)();  // called in the test, after every model registered
  const char* doc;                      // relative to the source tree
};

const Family kFamilies[] = {
    {"ContactLawRegistry", &ContactLawRegistry::names, "docs/case-file.md"},
    {"RollingResistanceRegistry", &RollingResistanceRegistry::names, "docs/case-file.md"},
    {"CohesionRegistry", &CohesionRegistry::names, "docs/case-file.md"},
    {"SizeDistributionRegistry", &SizeDistributionRegistry::names, "docs/case-file.md"},
    {"WallRegistry", &WallRegistry::names, "docs/case-file.md"},
};

std::string read_doc(const std::string& relative) {
  std::ifstream in(std::string(COMMINUTE_SOURCE_DIR) + "/" + relative);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST(RegisteredModels, EveryNameHasItsRowInTheDocs) {
  for (const Family& f : kFamilies) {
    const std::string doc = "\n" + read_doc(f.doc);
    ASSERT_GT(doc.size(), 1u) << f.doc << " is missing or empty";
    const std::vector<std::string> names = f.names();
    EXPECT_FALSE(names.empty()) << f.registry << " has no models";
    for (const std::string& name : names)
      EXPECT_NE(doc.find("\n| `" + name + "`"), std::string::npos)
          << f.registry << " model \"" << name << "\" has no row \"| `" << name << "`\" in "
          << f.doc;
  }
}
