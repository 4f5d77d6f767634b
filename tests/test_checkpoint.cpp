// Checkpoint files: an Archive goes to HDF5 and comes back byte for byte; broken files give
// clear errors instead of wrong states.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <fstream>
#include <iterator>

#include "comminute/core/error.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/io/output/checkpoint.hpp"
#include "temp_dir.hpp"

using namespace comminute;

namespace {

// Random entries: sizes 0..5000 bytes, names with the characters state names use ('/', '.').
Archive random_archive(Rng& rng, int n) {
  Archive a;
  for (int k = 0; k < n; ++k) {
    const std::string name = "module" + std::to_string(rng.below(5)) + "/part." + std::to_string(k);
    auto& b = a.entries()[name];
    b.resize(rng.below(5001));
    for (auto& c : b) c = static_cast<std::uint8_t>(rng.below(256));
  }
  a.entries()["empty"];  // zero-length entry
  a.put("particles/x", std::vector<double>{0.1, -0.0, 1e-310, 6.02e23});
  a.put("step", std::vector<std::uint64_t>{~std::uint64_t{0}, 42});
  return a;
}

std::vector<char> slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
void spill(const std::filesystem::path& p, const std::vector<char>& b) {
  std::ofstream(p, std::ios::binary).write(b.data(), static_cast<std::streamsize>(b.size()));
}

void expect_error(const std::filesystem::path& p, const std::string& words) {
  try {
    io::read_checkpoint(p);
    FAIL() << "no error reading " << p;
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(p.filename().string()), std::string::npos) << m;
    EXPECT_NE(m.find(words), std::string::npos) << m;
  }
}

}  // namespace

TEST(Checkpoint, RandomArchiveRoundTripIsByteIdentical) {
  const comminute::testing::TestDir dir;
  Rng rng(2024);
  const Archive a = random_archive(rng, 40);
  io::CheckpointInfo info;
  info.time = 0.1 + 0.2;
  info.step = 123456789012ull;
  info.threads = 2;
  io::write_checkpoint(dir / "c.h5", a, info);
  EXPECT_FALSE(std::filesystem::exists(dir / "c.h5.part"));
  io::CheckpointInfo back;
  const Archive b = io::read_checkpoint(dir / "c.h5", &back);
  EXPECT_TRUE(a.entries() == b.entries());  // same names, same bytes
  EXPECT_EQ(b.entries().size(), 43u);
  EXPECT_EQ(back.time, 0.1 + 0.2);
  EXPECT_EQ(back.step, 123456789012ull);
  EXPECT_EQ(back.threads, 2);
  EXPECT_EQ(back.format_version, io::checkpoint_format_version);
  EXPECT_EQ(back.comminute_version, COMMINUTE_VERSION);
  EXPECT_EQ(b.get<std::uint64_t>("step"), (std::vector<std::uint64_t>{~std::uint64_t{0}, 42}));
  EXPECT_EQ(io::read_checkpoint_info(dir / "c.h5").step, 123456789012ull);
  // Overwriting replaces the file as a whole.
  io::write_checkpoint(dir / "c.h5", Archive{}, info);
  EXPECT_TRUE(io::read_checkpoint(dir / "c.h5").entries().empty());
}

TEST(Checkpoint, TruncatedFileIsAnError) {
  const comminute::testing::TestDir dir;
  Rng rng(1);
  io::write_checkpoint(dir / "c.h5", random_archive(rng, 20), {});
  auto bytes = slurp(dir / "c.h5");
  for (double keep : {0.9, 0.5, 0.01}) {
    spill(dir / "cut.h5",
          {bytes.begin(), bytes.begin() + std::ptrdiff_t(keep * double(bytes.size()))});
    expect_error(dir / "cut.h5", "truncated or corrupt");
  }
}

TEST(Checkpoint, CorruptDataIsAnError) {
  const comminute::testing::TestDir dir;
  Archive a;
  std::vector<std::uint8_t> pattern(4096);
  Rng rng(9);
  for (auto& c : pattern) c = static_cast<std::uint8_t>(rng.below(256));
  a.put("contacts/history", pattern);
  io::write_checkpoint(dir / "c.h5", a, {});
  auto bytes = slurp(dir / "c.h5");
  const auto at = std::search(bytes.begin(), bytes.end(), pattern.begin(), pattern.end(),
                              [](char x, std::uint8_t y) { return std::uint8_t(x) == y; });
  ASSERT_NE(at, bytes.end());
  at[1000] = char(at[1000] ^ 0x10);  // one bit flipped in the stored state
  spill(dir / "bad.h5", bytes);
  expect_error(dir / "bad.h5", "'contacts/history' is corrupt");
}

TEST(Checkpoint, MissingOrForeignFileIsAnError) {
  const comminute::testing::TestDir dir;
  expect_error(dir / "none.h5", "no such file");
  std::ofstream(dir / "text.h5") << "not hdf5 at all\n";
  expect_error(dir / "text.h5", "truncated or corrupt");
}

TEST(Checkpoint, AnotherFormatVersionIsRefused) {
  // A checkpoint of another format version (another layout of the state, e.g. the outlet and
  // sampling-plane logs before format 5) is refused by its version attribute, with both numbers
  // in the message, instead of being read as this version's layout.
  const comminute::testing::TestDir dir;
  Rng rng(3);
  io::write_checkpoint(dir / "c.h5", random_archive(rng, 5), {});
  const int older = io::checkpoint_format_version - 1;
  {
    const hid_t f = H5Fopen((dir / "c.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const hid_t version = H5Aopen(f, "format_version", H5P_DEFAULT);
    ASSERT_GE(version, 0);
    EXPECT_GE(H5Awrite(version, H5T_NATIVE_INT, &older), 0);
    H5Aclose(version);
    H5Fclose(f);
  }
  const std::string words = "format version " + std::to_string(older) +
                            " is not the supported version " +
                            std::to_string(io::checkpoint_format_version);
  expect_error(dir / "c.h5", words);
  EXPECT_THROW(io::read_checkpoint_info(dir / "c.h5"), Error);
}
