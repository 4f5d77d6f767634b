#pragma once
// A spatial dataset a module offers to the outputs (SeriesSource::datasets): a structured grid
// of cells (cells > 0 in every direction: the lattice of (cells+1) corner points, first index
// fastest) or a set of line segments (force chains), with per-cell arrays. The output module
// writes it as <directory>/<name>.vts (grid) or .vtp (lines) for ParaView.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/core/vec3.hpp"

namespace comminute {

struct DatasetArray {
  std::string name;
  int components = 1;
  std::vector<double> values;  // components per cell, cell after cell
};

struct Dataset {
  std::string name;  // file stem under the output directory (may hold a folder: "chains/c_10")
  std::array<std::size_t, 3> cells{};  // a structured grid when all are > 0
  std::vector<Vec3> points;            // m
  std::vector<std::array<std::uint32_t, 2>> lines;
  std::vector<DatasetArray> cell_data;
  bool structured() const { return cells[0] > 0 && cells[1] > 0 && cells[2] > 0; }
};

}  // namespace comminute
