// Core utilities: random streams, registry, atomic files, case-file validation.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "comminute/core/atomic_file.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/core/registry.hpp"
#include "comminute/core/rng.hpp"

using namespace comminute;

namespace {
struct Shape {
  virtual ~Shape() = default;
  virtual int sides() const = 0;
};
struct Triangle final : Shape {
  int sides() const override { return 3; }
};
using ShapeRegistry = Registry<Shape>;
}  // namespace

TEST(Registry, RefusesASecondModelUnderATakenName) {
  ASSERT_TRUE(ShapeRegistry::add("triangle", [] { return std::make_unique<Triangle>(); }));
  EXPECT_THROW(ShapeRegistry::add("triangle", [] { return std::make_unique<Triangle>(); }),
               std::logic_error);
  EXPECT_EQ(ShapeRegistry::create("triangle")->sides(), 3);  // the first stays
  EXPECT_EQ(ShapeRegistry::create("square"), nullptr);
}

TEST(Rng, SameSeedSameStreamRepeats) {
  Rng a(42, 1), b(42, 1), c(42, 2);
  for (int i = 0; i < 100; ++i) {
    auto x = a.next_u64();
    EXPECT_EQ(x, b.next_u64());
    EXPECT_NE(x, c.next_u64());
  }
}

// Per-item streams (a broken parent's, keyed by its id): the same seed, stream and key give the
// same numbers; another key, stream or seed, or the plain stream, others.
TEST(Rng, KeyedStreamsDependOnSeedStreamAndKeyOnly) {
  Rng a(42, 2, 7), b(42, 2, 7);
  std::vector<Rng> others{Rng(42, 2, 8), Rng(42, 3, 7), Rng(43, 2, 7), Rng(42, 2)};
  for (int i = 0; i < 100; ++i) {
    const auto x = a.next_u64();
    EXPECT_EQ(x, b.next_u64());
    for (auto& o : others) EXPECT_NE(x, o.next_u64());
  }
}

TEST(Rng, UniformAndNormalMoments) {
  // 1e6 draws: standard error of the mean is 1/sqrt(12e6)=2.9e-4 (uniform) and 1e-3 (normal);
  // 5-sigma bands below.
  Rng r(7);
  const int n = 1000000;
  double su = 0, sn = 0, sn2 = 0;
  for (int i = 0; i < n; ++i) {
    double u = r.uniform();
    ASSERT_GT(u, 0.0);
    ASSERT_LT(u, 1.0);
    su += u;
    double z = r.normal();
    sn += z;
    sn2 += z * z;
  }
  EXPECT_NEAR(su / n, 0.5, 5 * 2.9e-4);
  EXPECT_NEAR(sn / n, 0.0, 5e-3);
  EXPECT_NEAR(sn2 / n, 1.0, 5 * std::sqrt(2.0 / n));
}

TEST(Rng, BelowIsInRangeAndCoversIt) {
  Rng r(3);
  int hits[7] = {};
  for (int i = 0; i < 7000; ++i) {
    auto k = r.below(7);
    ASSERT_LT(k, 7u);
    ++hits[k];
  }
  for (int h : hits) EXPECT_GT(h, 800);  // expected 1000, sd ~29
}

TEST(AtomicFile, UncommittedLeavesNothing) {
  auto dir = std::filesystem::temp_directory_path() / "comminute_atomic";
  std::filesystem::remove_all(dir);
  {
    AtomicFile f(dir / "a.txt");
    f.stream() << "half";
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "a.txt"));
  EXPECT_FALSE(std::filesystem::exists(dir / "a.txt.part"));
  {
    AtomicFile f(dir / "a.txt");
    f.stream() << "whole";
    f.commit();
  }
  std::ifstream in(dir / "a.txt");
  std::string s;
  in >> s;
  EXPECT_EQ(s, "whole");
}

TEST(CaseTable, ReadsTypedValuesWithDefaults) {
  auto f = CaseFile::parse("[sim]\ndt = 1e-5\nsteps = 10\nname = \"x\"\ng = [0, 0, -9.81]\n");
  auto sim = f.root().table("sim");
  EXPECT_DOUBLE_EQ(sim.number("dt", Limits::positive()), 1e-5);
  EXPECT_EQ(sim.integer("steps", 1, 100), 10);
  EXPECT_EQ(sim.string("name"), "x");
  EXPECT_DOUBLE_EQ(sim.vec3("g").z, -9.81);
  EXPECT_DOUBLE_EQ(sim.number("missing", Limits::any(), 3.0), 3.0);
  EXPECT_NO_THROW(f.reject_unknown());
}

TEST(CaseTable, ErrorsNameFileKeyLineAndValue) {
  auto f = CaseFile::parse("[sim]\ndt = -1.0\nradius = nan\nkind = \"hertz\"\n", "case.toml");
  auto sim = f.root().table("sim");
  try {
    sim.number("dt", Limits::positive());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "sim.dt");
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(std::string(e.what()).find("case.toml:2"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("-1"), std::string::npos);
  }
  EXPECT_THROW(sim.number("radius"), InputError);
  try {
    sim.choice("kind", {"hertz_mindlin", "linear"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hertz_mindlin"), std::string::npos);
  }
}

TEST(CaseTable, UnknownKeyIsRejectedWithSuggestion) {
  auto f = CaseFile::parse("[sim]\ndt = 1.0\ndensty = 2500\n", "c.toml");
  auto sim = f.root().table("sim");
  sim.number("dt");
  sim.number("density", Limits::positive(), 1.0);
  try {
    f.reject_unknown();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "sim.densty");
    EXPECT_EQ(e.line(), 3);
  }
}

TEST(CaseTable, SyntaxErrorHasLine) {
  try {
    CaseFile::parse("a = 1\nb = = 2\n", "bad.toml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2);
  }
}
