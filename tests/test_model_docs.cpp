// Every model registered in a model family's registry has its row in the docs: a markdown table
// row "| `name` |" in the section of the doc file that lists the family. To cover another family,
// add one line to kModelDocs.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "comminute/breakage/criteria/breakage_criterion.hpp"
#include "comminute/breakage/placement/placement_model.hpp"
#include "comminute/breakage/progeny/progeny_model.hpp"
#include "comminute/pbm/breakage_function.hpp"
#include "comminute/pbm/critical_stress.hpp"
#include "comminute/pbm/mill_model.hpp"
#include "comminute/pbm/selection_function.hpp"

using namespace comminute;

namespace {

struct ModelDocs {
  const char* family;                   // for messages
  std::vector<std::string> (*names)();  // the registry's names()
  const char* doc;                      // file under docs/
  const char* section;                  // heading line that starts the family's section
};

// (registry, doc file, section): one line per model family.
const ModelDocs kModelDocs[] = {
    {"breakage criterion", &breakage::CriterionRegistry::names, "breakage.md",
     "### `[materials.<name>.breakage]`"},
    {"breakage progeny", &breakage::ProgenyRegistry::names, "breakage.md",
     "### `[materials.<name>.breakage.progeny]`"},
    {"breakage placement", &breakage::PlacementRegistry::names, "breakage.md", "### `[breakage]`"},
    {"pbm breakage function", &pbm::BreakageFunctionRegistry::names, "pbm.md", "### `[breakage]`"},
    {"pbm rate", &pbm::SelectionFunctionRegistry::names, "pbm.md", "### `[rate]`"},
    {"pbm strength", &pbm::CriticalStressRegistry::names, "pbm.md", "### `[rate]`"},
    {"pbm mill model", &pbm::MillRegistry::names, "pbm.md", "### `[solver]`"},
};

std::string read_doc(const std::string& name) {
  std::ifstream in(std::string(COMMINUTE_SOURCE_DIR) + "/docs/" + name);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The text from the heading line `heading` to the next heading of level 2 or 3 (empty if absent).
std::string section(const std::string& doc, const std::string& heading) {
  const auto start = doc.find("\n" + heading);
  if (start == std::string::npos) return {};
  const auto body = doc.find('\n', start + 1);
  if (body == std::string::npos) return {};
  auto end = doc.size();
  for (const char* next : {"\n## ", "\n### "}) end = std::min(end, doc.find(next, body));
  return doc.substr(body, end - body);
}

}  // namespace

TEST(ModelDocs, EveryRegisteredModelHasItsRow) {
  for (const ModelDocs& f : kModelDocs) {
    const std::string doc = read_doc(f.doc);
    ASSERT_FALSE(doc.empty()) << "docs/" << f.doc;
    const std::string text = section(doc, f.section);
    ASSERT_FALSE(text.empty()) << "docs/" << f.doc << " has no section " << f.section;
    const auto names = f.names();
    EXPECT_FALSE(names.empty()) << f.family << ": nothing registered";
    for (const std::string& name : names)
      EXPECT_NE(text.find("\n| `" + name + "` |"), std::string::npos)
          << f.family << " '" << name << "' has no row \"| `" << name << "` |\" in docs/" << f.doc
          << " section " << f.section;
  }
}
