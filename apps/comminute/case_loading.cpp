#include "case_loading.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include "case_kind.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/bonds_case.hpp"
#include "comminute/io/case/breakage_case.hpp"
#include "comminute/io/case/cluster_case.hpp"
#include "comminute/io/case/coarse_graining_case.hpp"
#include "comminute/io/case/texture_case.hpp"

namespace comminute::app {

void check_output_directory(const LoadedCase& c, const std::string& option) {
  const std::filesystem::path dir = c.output.directory;
  std::string key = option;
  long line = 0;
  std::string file = "<command line>";
  if (key.empty()) {
    key = "output.directory";
    file = c.file.path().string();
    if (auto t = c.file.root().optional_table("output"); t && t->has("directory"))
      line = t->line("directory");
  }
  auto refuse = [&](const std::string& message) {
    throw InputError(file, key, line, fmt::format("output folder '{}' {}", dir.string(), message));
  };
  if (dir.empty()) refuse("is empty");
  std::error_code ec;
  // the folder, or the nearest folder above it that exists (the run creates the rest)
  std::filesystem::path probe = dir;
  while (!std::filesystem::exists(probe, ec)) {
    if (!probe.has_parent_path() || probe.parent_path() == probe) {
      probe = ".";
      break;
    }
    probe = probe.parent_path();
  }
  if (!std::filesystem::is_directory(probe, ec))
    refuse(probe == dir ? "is a file, not a folder"
                        : fmt::format("cannot be created: '{}' is a file", probe.string()));
  if (::access(probe.c_str(), W_OK | X_OK) != 0)
    refuse(fmt::format("is not writable ('{}' does not allow writing)", probe.string()));
  // per-particle fields: the modules registered theirs while the case was read
  const ParticleStore& p = c.dem.sim->particles;
  if (c.output.fields)
    for (const auto& name : *c.output.fields)
      if (!p.has_field(name))
        throw InputError(
            c.file.path().string(), "output.fields", c.output.fields_line,
            fmt::format("'{}' is not a per-particle field of this case (known: {})", name,
                        p.field_names().empty()
                            ? std::string("none")
                            : fmt::format("{}", fmt::join(p.field_names(), ", "))));
}

LoadedCase load_dem_case(const std::filesystem::path& path) {
  require_case_kind(path, {CaseKind::dem});
  CaseFile file = CaseFile::load(path);
  io::DemCase dem = io::build_dem_case(file.root());
  const auto output_table = file.root().optional_table("output");
  io::OutputOptions output = output_table ? io::read_output_options(*output_table)
                                          : io::default_output_options(file.path());
  const bonds::BondsModule* bonded = io::add_bonds(file.root(), dem);
  io::add_grain_breakage(file.root(), dem, bonded);
  io::add_breakage(file.root(), dem);
  io::add_texture(file.root(), dem);
  io::decide_time_step(dem);
  file.reject_unknown();
  output.case_fingerprint = file.fingerprint();
  output.coarse_scale = io::coarse_graining_of(file.root()).scale;
  return {std::move(file), std::move(dem), std::move(output)};
}

}  // namespace comminute::app
