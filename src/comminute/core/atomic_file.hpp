#pragma once
// Writes a file so that a killed run never leaves a half-written file that looks complete:
// everything goes to "<path>.part" and is renamed onto <path> by commit() (rename is atomic on
// POSIX). If the writer is destroyed without commit() the partial file is removed.
#include <filesystem>
#include <fstream>
#include <string>

namespace comminute {

// Forces a written file (or a folder's entries, after a rename into it) onto the disk; throws
// Error naming the path when the system reports a failure (a full disk shows up here at the
// latest).
void sync_to_disk(const std::filesystem::path& path);
// Renames tmp onto path durably: fsync of tmp, rename, fsync of the folder.
void durable_rename(const std::filesystem::path& tmp, const std::filesystem::path& path);

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path path, std::ios::openmode mode = std::ios::out);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  const std::filesystem::path& temp_path() const { return tmp_; }
  void commit();  // flush, fsync, rename to the final path, fsync the folder; Error on failure

 private:
  std::filesystem::path path_, tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace comminute
