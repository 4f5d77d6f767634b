#pragma once
// Reads a TIFF stack as a texture volume: a multi-page baseline TIFF (TIFF 6.0, Adobe 1992), one
// page per z slice, each page 8-bit single-channel, uncompressed, in strips; the pixel value is
// the phase label (x = column, y = row from the top, z = page). Both byte orders. Tiles,
// compression, other bit depths and pages of different sizes are refused with the file's name.
// TIFF carries no physical voxel size: the caller gives it.
#include <string>
#include <vector>

#include "comminute/breakage/texture/texture_volume.hpp"

namespace comminute::breakage::texture {

TextureVolume read_tiff_texture(const std::string& path, double voxel_size,
                                std::vector<Phase> phases);

}  // namespace comminute::breakage::texture
