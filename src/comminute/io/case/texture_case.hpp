#pragma once
// Builds the texture module and the liberation observer from a case file: the [texture] table
// (phases, an image file or a generator, resolution per material) and the optional [liberation]
// table. Every key: docs/breakage.md ("Texture") and docs/case-file.md.
#include "comminute/breakage/texture/texture_module.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/io/case/dem_case.hpp"

namespace comminute::io {

// When the case has a [texture] table, appends a TextureModule (after the breakage module, so
// fragments get their texture in the step they are born) and, with [liberation], a
// LiberationObserver, and returns the texture module; otherwise nullptr ([liberation] without
// [texture] is refused). Call after add_breakage and before CaseFile::reject_unknown().
breakage::texture::TextureModule* add_texture(const CaseTable& root, DemCase& dem);

}  // namespace comminute::io
