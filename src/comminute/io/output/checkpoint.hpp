#pragma once
// Checkpoints: an Archive (the simulation's state as named byte arrays) in one HDF5 file.
//
// Layout: root attributes format_version, comminute_version, time [s], step, threads, entries;
// group /entries with one uint8 dataset per archive entry ("000000", "000001", ... in name
// order), each with attributes `name` (the archive name) and `fnv1a64` (checksum of the bytes).
// Entries are stored as raw bytes so that the state comes back bit for bit.
//
// Written atomically: to "<path>.part", then renamed onto <path>, so a run killed while writing
// keeps its previous checkpoint. Reading checks the format version, the entry count and every
// checksum; a missing, truncated or corrupt file gives an Error that says so.
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "comminute/core/archive.hpp"

namespace comminute::io {

inline constexpr int checkpoint_format_version = 5;  // 5: outlet and sampling-plane logs as one
// record (engine/particle_record.hpp); 4: bond energies in the ledger, periodic image labels of
// pairs; 3: case fingerprint; 2: state by slot

struct CheckpointInfo {
  int format_version = checkpoint_format_version;
  std::string comminute_version;  // of the program that wrote it
  double time = 0;                // s, simulated time of the state
  std::uint64_t step = 0;
  int threads = 0;  // OpenMP threads of the run (bit-for-bit restarts need the same count)
};

// Writes `a` with `info` (its format_version and comminute_version are filled in here).
void write_checkpoint(const std::filesystem::path& path, const Archive& a, CheckpointInfo info);
Archive read_checkpoint(const std::filesystem::path& path, CheckpointInfo* info = nullptr);
CheckpointInfo read_checkpoint_info(const std::filesystem::path& path);

// The case fingerprint as archive entries "case/<section>" (see CaseFile::fingerprint()).
void put_case_fingerprint(Archive& a,
                          const std::vector<std::pair<std::string, std::string>>& fingerprint);
// Throws InputError (file: the checkpoint) naming every section of the case that differs from
// the one the checkpoint was written for.
void check_case_fingerprint(const Archive& a,
                            const std::vector<std::pair<std::string, std::string>>& fingerprint,
                            const std::filesystem::path& checkpoint);

}  // namespace comminute::io
