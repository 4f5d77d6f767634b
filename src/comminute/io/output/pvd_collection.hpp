#pragma once
// A ParaView data collection (.pvd): the list of (time, file) of one output series. It is
// rewritten atomically after each snapshot, and a snapshot is added only after its own file was
// committed, so a killed run leaves a valid collection that lists only complete files.
#include <filesystem>
#include <string>
#include <vector>

namespace comminute::io {

class PvdCollection {
 public:
  struct Entry {
    double time = 0;   // s
    std::string file;  // relative to the .pvd's folder
  };

  explicit PvdCollection(std::filesystem::path path) : path_(std::move(path)) {}

  // Restart: reads the existing collection (if any) and keeps the entries with time <= t_end.
  // Throws Error if the file exists but is not a collection written by comminute.
  void resume(double t_end);
  // Fresh series: forgets all entries and removes the collection file.
  void clear();
  // Adds a snapshot (file relative to the .pvd's folder) and rewrites the collection.
  void add(double time, const std::string& file);
  const std::vector<Entry>& entries() const { return entries_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  void write() const;

  std::filesystem::path path_;
  std::vector<Entry> entries_;
};

}  // namespace comminute::io
