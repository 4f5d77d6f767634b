#pragma once
// Writes a module's Dataset (engine/dataset.hpp) for ParaView: a structured grid as
// <directory>/<name>.vts, line segments as <directory>/<name>.vtp, with field data TimeValue [s].
#include <filesystem>

#include "comminute/engine/dataset.hpp"

namespace comminute::io {

void write_dataset(const std::filesystem::path& directory, const Dataset& d, double time);

}  // namespace comminute::io
