// Every model registered by name has its row in the docs: for each registry below, every name of
// Registry::names() starts a table row "| `name`" of its doc file. Another registry is one line of
// kFamilies.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "comminute/bonds/bond_law.hpp"
#include "comminute/contact/cohesion.hpp"
#include "comminute/contact/contact_law.hpp"
#include "comminute/contact/rolling_resistance.hpp"
#include "comminute/geometry/motion_model.hpp"
#include "comminute/geometry/wall.hpp"
#include "comminute/geometry/wall_group.hpp"
#include "comminute/particles/size_distribution.hpp"
#include "source_file.hpp"

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
    {"MotionRegistry", &MotionRegistry::names, "docs/case-file.md"},
    {"WallGroupRegistry", &WallGroupRegistry::names, "docs/case-file.md"},
    {"BondLawRegistry", &bonds::BondLawRegistry::names, "docs/case-file.md"},
};

}  // namespace

TEST(RegisteredModels, EveryNameHasItsRowInTheDocs) {
  for (const Family& f : kFamilies) {
    std::string doc = "\n";  // so that a row on the first line starts after a newline too
    doc += comminute::testing::read_source_file(f.doc);
    ASSERT_GT(doc.size(), 1u) << f.doc << " is missing or empty";
    const std::vector<std::string> names = f.names();
    EXPECT_FALSE(names.empty()) << f.registry << " has no models";
    for (const std::string& name : names)
      EXPECT_NE(doc.find(std::string("\n| `") + name + "`"), std::string::npos)
          << f.registry << " model \"" << name << "\" has no row \"| `" << name << "`\" in "
          << f.doc;
  }
}
