// Run front end: the progress line, the stop flag set by SIGINT/SIGTERM, the [output] table.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>

#include "comminute/core/error.hpp"
#include "comminute/io/case/output_case.hpp"
#include "comminute/run/progress_reporter.hpp"
#include "comminute/run/stop_request.hpp"

using namespace comminute;

namespace {

// Captures what the reporter prints.
struct Capture {
  char* buf = nullptr;
  std::size_t size = 0;
  std::FILE* f = open_memstream(&buf, &size);
  ~Capture() {
    std::fclose(f);
    std::free(buf);
  }
  std::string text() {
    std::fflush(f);
    return std::string(buf, size);
  }
};

}  // namespace

TEST(ProgressReporter, PlainLinesAreThrottledAndCarryRateAndEta) {
  Capture out;
  double now = 100.0;  // fake wall clock, s
  run::ProgressReporter p(
      0.0, 1.0, out.f, false, [&] { return now; }, 0.5, 5.0);
  // 1000 particles, 1e-4 s steps, 1000 steps per wall second: 1e6 particle-steps/s.
  for (int s = 1; s <= 12000; ++s) {
    now = 100.0 + s * 1e-3;
    p.update({s * 1e-4, std::uint64_t(s), 1000, 345});
  }
  const std::string text = out.text();
  // Lines at 5 s and 10 s of wall time only (not every step): two lines.
  ASSERT_EQ(std::count(text.begin(), text.end(), '\n'), 2) << text;
  EXPECT_EQ(text.find('\r'), std::string::npos);
  // At 5 s: t = 0.5 s of 1 s (50 %), 5 s more to go, rate 1e6.
  EXPECT_NE(text.find("t = 0.5 s of 1 s (50.0 %)  ETA 0:00:05  1e+06 particle-steps/s  1000 "
                      "particles  345 contacts"),
            std::string::npos)
      << text;
  p.finish({1.0, 10000, 1000, 0});
  EXPECT_NE(out.text().find("(100.0 %)  ETA 0:00:00"), std::string::npos) << out.text();
}

TEST(ProgressReporter, TerminalRefreshesInPlace) {
  Capture out;
  double now = 0.0;
  run::ProgressReporter p(
      0.0, 2.0, out.f, true, [&] { return now; }, 0.5, 5.0);
  for (int s = 1; s <= 20; ++s) {
    now = 0.1 * s;
    p.update({0.1 * s, std::uint64_t(s), 10, 0});
  }
  p.finish({2.0, 20, 10, 0});
  const std::string text = out.text();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\r'), 5) << text;  // at 0.5,1,1.5,2 s + finish
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;  // only the last line ends
}

TEST(StopRequest, SignalSetsFlagInsteadOfKilling) {
  {
    run::StopRequest stop;
    EXPECT_FALSE(stop.requested());
    std::raise(SIGINT);  // would end the test program without the handler
    EXPECT_TRUE(stop.requested());
    EXPECT_EQ(stop.exit_code(), 130);
    EXPECT_STREQ(stop.signal_name(), "SIGINT");
    EXPECT_THROW(run::StopRequest second, Error);
  }
  run::StopRequest again;  // a new request starts clear
  EXPECT_FALSE(again.requested());
  std::raise(SIGTERM);
  EXPECT_EQ(again.exit_code(), 143);
}

TEST(OutputCase, ReadsEveryKey) {
  auto file = CaseFile::parse(R"(
[output]
directory = "results"
particles = true
particles_every = 500
walls = false
wall_extent = 0.2
fields = ["damage"]
timeseries_interval = 1e-4
checkpoint_interval = 0.05
)",
                              "/cases/box.toml");
  const auto o = io::read_output_options(file.root().table("output"));
  file.reject_unknown();
  EXPECT_EQ(o.directory, std::filesystem::path("/cases/results"));
  EXPECT_EQ(o.particles_cadence.steps, 500u);
  EXPECT_EQ(o.particles_cadence.interval, 0.0);
  EXPECT_FALSE(o.walls);
  EXPECT_EQ(o.wall_extent, 0.2);
  ASSERT_TRUE(o.fields.has_value());
  EXPECT_EQ(*o.fields, std::vector<std::string>{"damage"});
  EXPECT_EQ(o.fields_line, 8);
  EXPECT_EQ(o.timeseries_cadence.interval, 1e-4);
  EXPECT_EQ(o.checkpoint_cadence.interval, 0.05);
}

TEST(OutputCase, DefaultsAndBadInput) {
  auto empty = CaseFile::parse("[output]\n", "/cases/a.toml");
  const auto d = io::read_output_options(empty.root().table("output"));
  EXPECT_EQ(d.directory, std::filesystem::path("/cases/output"));
  EXPECT_TRUE(d.particles && d.walls && !d.fields);
  EXPECT_FALSE(d.particles_cadence.is_set() || d.timeseries_cadence.is_set() ||
               d.checkpoint_cadence.is_set());
  auto expect_input_error = [](const std::string& text, const std::string& key,
                               const std::string& words) {
    auto f = CaseFile::parse(text, "case.toml");
    try {
      io::read_output_options(f.root().table("output"));
      f.reject_unknown();
      FAIL() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_GT(e.line(), 0);
    }
  };
  expect_input_error("[output]\nparticles_interval = 0.1\nparticles_every = 10\n",
                     "output.particles_every", "not both");
  expect_input_error("[output]\ntimeseries_interval = -1\n", "output.timeseries_interval", "-1");
  expect_input_error("[output]\ncheckpoint_every = 0\n", "output.checkpoint_every", "0");
  expect_input_error("[output]\nfields = \"damage\"\n", "output.fields", "array");
  expect_input_error("[output]\nparticle_interval = 0.1\n", "output.particle_interval",
                     "unknown key");
}
