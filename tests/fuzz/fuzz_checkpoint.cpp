// Fuzzes the checkpoint loaders (Simulation::load: particles, pair tracker, contact state, walls,
// modules incl. breakage and insertion) with crafted states whose checksums are valid: the input
// is a list of edits of a real checkpoint of examples/breakage/bed_impact.toml. A crafted state
// must be refused with an Error or load into a state that runs; never an out-of-range access, a
// crash or a hang.
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

#include "comminute/core/archive.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/breakage_case.hpp"
#include "comminute/io/case/dem_case.hpp"

namespace {

using namespace comminute;

io::DemCase build() {
  const CaseFile file =
      CaseFile::load(std::string(COMMINUTE_SOURCE_DIR) + "/examples/breakage/bed_impact.toml");
  io::DemCase dem = io::build_dem_case(file.root());
  io::add_breakage(file.root(), dem);
  io::decide_time_step(dem);
  return dem;
}

const Archive& reference() {
  static const Archive a = [] {
    io::DemCase dem = build();
    dem.sim->setup();
    dem.sim->run(300);
    Archive out;
    dem.sim->save(out);
    return out;
  }();
  return a;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Archive a = reference();
  std::vector<std::string> names;
  for (const auto& [name, bytes] : a.entries()) names.push_back(name);
  // edits: [op][entry][pos lo][pos hi][len][len bytes]
  std::size_t k = 0;
  while (k + 5 <= size) {
    const std::uint8_t op = data[k] % 4;
    const std::string& name = names[data[k + 1] % names.size()];
    const std::size_t pos = data[k + 2] | (std::size_t{data[k + 3]} << 8);
    const std::size_t len = data[k + 4];
    k += 5;
    const std::size_t n = std::min(len, size - k);
    const std::uint8_t* bytes = data + k;
    k += n;
    if (!a.has(name)) continue;
    auto& b = a.entries()[name];
    if (op == 0) {
      for (std::size_t j = 0; j < n && pos + j < b.size(); ++j) b[pos + j] = bytes[j];
    } else if (op == 1) {
      if (pos < b.size()) b.resize(pos);
    } else if (op == 2) {
      b.insert(b.end(), bytes, bytes + n);
    } else {
      a.entries().erase(name);
    }
  }
  io::DemCase dem = build();
  try {
    dem.sim->load(a);
  } catch (const Error&) {
    return 0;  // refused: fine
  }
  try {
    dem.sim->run(3);
  } catch (const Error&) {
  }
  return 0;
}
