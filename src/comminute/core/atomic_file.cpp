#include "comminute/core/atomic_file.hpp"

#include <fmt/format.h>

#include "comminute/core/error.hpp"

namespace comminute {

AtomicFile::AtomicFile(std::filesystem::path path, std::ios::openmode mode)
    : path_(std::move(path)), tmp_(path_.string() + ".part") {
  if (path_.has_parent_path()) std::filesystem::create_directories(path_.parent_path());
  out_.open(tmp_, mode | std::ios::out | std::ios::trunc);
  if (!out_) throw Error(fmt::format("cannot open '{}' for writing", tmp_.string()));
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
  }
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw Error(fmt::format("write to '{}' failed", tmp_.string()));
  out_.close();
  std::filesystem::rename(tmp_, path_);
  committed_ = true;
}

}  // namespace comminute
