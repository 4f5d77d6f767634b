// ParaView output: written files are read back with VTK's own reader (python3-vtk9) and every
// value must come back exactly; collections list only complete files and resume after restart.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "comminute/core/error.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/io/output/vtk_writer.hpp"
#include "temp_dir.hpp"

using namespace comminute;

namespace {

// A unit square in the plane z = z0 (two triangles), enough to exercise the wall output.
class SquareWall : public Wall {
 public:
  explicit SquareWall(double z0) : z0_(z0) {}
  std::string type() const override { return "square"; }
  int contacts(const Vec3&, double, double, std::vector<WallContact>&) const override { return 0; }
  void advance(double) override {}
  void save(Archive&, const std::string&) const override {}
  void load(const Archive&, const std::string&) override {}
  SurfaceMesh surface(double extent) const override {
    const double h = extent / 2;
    return {
        {{-h, -h, z0_}, {h, -h, z0_}, {h, h, z0_}, {-h, h, z0_}}, {{{0, 1, 2}}, {{0, 2, 3}}}, {}};
  }

 private:
  double z0_;
};

std::string num(double x) {
  return fmt::format("{:.17g}", x);
}
std::string vec(const Vec3& a) {
  return fmt::format("[{},{},{}]", num(a.x), num(a.y), num(a.z));
}
template <class T, class F>
std::string list(const std::vector<T>& v, F f) {
  std::vector<std::string> s;
  for (const auto& x : v) s.push_back(f(x));
  return fmt::format("[{}]", fmt::join(s, ","));
}

std::string particles_json(const ParticleStore& p, double time) {
  std::vector<double> d;
  for (double r : p.radius) d.push_back(2 * r);
  std::vector<std::string> fields;
  for (std::size_t k = 0; k < p.field_names().size(); ++k)
    fields.push_back(fmt::format("\"{}\":{}", p.field_names()[k], list(p.field(k), num)));
  auto u = [](auto i) { return std::to_string(i); };
  return fmt::format(
      R"({{"time":{},"id":{},"position":{},"radius":{},"diameter":{},"mass":{},"velocity":{},)"
      R"("angular_velocity":{},"force":{},"material":{},"fields":{{{}}}}})",
      num(time), list(p.id, u), list(p.x, vec), list(p.radius, num), list(d, num),
      list(p.mass, num), list(p.v, vec), list(p.w, vec), list(p.f, vec), list(p.material, u),
      fmt::join(fields, ","));
}

std::string walls_json(const std::vector<std::unique_ptr<Wall>>& walls, double time) {
  std::vector<std::string> names;
  std::vector<Vec3> f, t;
  std::vector<int> cells;
  for (std::size_t k = 0; k < walls.size(); ++k) {
    names.push_back("\"" + walls[k]->name + "\"");
    f.push_back(walls[k]->force);
    t.push_back(walls[k]->torque);
    cells.push_back(int(k));
    cells.push_back(int(k));
  }
  return fmt::format(
      R"({{"time":{},"points":{},"triangles":{},"names":[{}],"wall_force":{},"wall_torque":{},)"
      R"("cell_wall_index":{}}})",
      num(time), 4 * walls.size(), 2 * walls.size(), fmt::join(names, ","), list(f, vec),
      list(t, vec), list(cells, [](int i) { return std::to_string(i); }));
}

// Random particles with awkward values (tiny, huge, negative) so any conversion would show.
void fill(ParticleStore& p, Rng& rng, int n) {
  for (int i = 0; i < n; ++i) {
    ParticleInit q;
    q.x = {rng.uniform(-1, 1), rng.uniform(-1e-9, 1e-9), rng.uniform(0, 1e6)};
    q.v = {rng.normal(), -rng.uniform(), 1e-300 * rng.uniform()};
    q.w = {rng.normal(0, 1e3), 0.0, -rng.uniform()};
    q.radius = rng.uniform(1e-4, 1e-2);
    q.density = 2650;
    q.material = static_cast<std::uint16_t>(rng.below(3));
    p.add(q);
  }
  for (std::size_t i = 0; i < p.size(); ++i) p.f[i] = {rng.normal(), rng.normal(), 1e20};
  auto& damage = p.field(p.add_field("damage", 0.0));
  for (auto& d : damage) d = rng.uniform();
}

int run_checker(const std::filesystem::path& dir, const std::string& expected) {
  const auto exp_path = dir / "expected.json";
  std::ofstream(exp_path) << expected;
  const std::string cmd =
      fmt::format("/usr/bin/python3 {}/tests/scripts/check_vtk_readback.py {} {}",
                  COMMINUTE_SOURCE_DIR, dir.string(), exp_path.string());
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST(VtkWriter, ReadBackWithVtkReaderIsExact) {
  const comminute::testing::TestDir dir;
  Rng rng(11);
  ParticleStore p;
  fill(p, rng, 57);
  std::vector<std::unique_ptr<Wall>> walls;
  walls.push_back(std::make_unique<SquareWall>(0.0));
  walls.push_back(std::make_unique<SquareWall>(0.5));
  walls[0]->name = "bottom";
  walls[1]->name = "lid";
  walls[1]->force = {0.25, -1e-12, 3.5};
  walls[1]->torque = {1, 2, 3};

  io::VtkWriter out(dir.path(), std::nullopt);
  out.start_fresh();
  std::vector<std::string> pj, wj;
  for (int s = 0; s < 3; ++s) {
    const double t = 0.1 * s;
    if (s == 2) {  // particles removed between snapshots: the files must follow
      for (std::size_t i = 0; i < p.size(); i += 4) p.flags[i] |= pflag::remove;
      p.compact();
    }
    out.write_particles(p, t, std::uint64_t(1000 * s));
    out.write_walls(walls, t, std::uint64_t(1000 * s), 2.0);
    pj.push_back(particles_json(p, t));
    wj.push_back(walls_json(walls, t));
    walls[0]->force.z += 1.5;
  }
  const std::string expected =
      fmt::format(R"({{"particles":[{}],"walls":[{}]}})", fmt::join(pj, ","), fmt::join(wj, ","));
  const int rc = run_checker(dir.path(), expected);
  if (rc == 77) GTEST_SKIP() << "python3-vtk9 not installed";
  EXPECT_EQ(rc, 0);
}

TEST(VtkWriter, EmptyStoreAndSelectedFields) {
  const comminute::testing::TestDir dir;
  ParticleStore p;
  p.add_field("damage", 0.0);
  p.add_field("unused", 0.0);
  io::VtkWriter out(dir.path(), std::vector<std::string>{"damage"});
  out.start_fresh();
  out.write_particles(p, 0.0, 0);  // no particles yet (a pour that has not started)
  Rng rng(5);
  fill(p, rng, 4);  // adds random damage values
  out.write_particles(p, 1e-3, 7);
  // Only the selected field is expected.
  ParticleStore expect_empty;
  expect_empty.add_field("damage", 0.0);
  ParticleStore expect_full = p;
  std::string full = particles_json(expect_full, 1e-3);
  const std::string unused = fmt::format(",\"unused\":{}", list(p.field(1), num));
  full.erase(full.find(unused), unused.size());
  const std::string expected =
      fmt::format(R"({{"particles":[{},{}]}})", particles_json(expect_empty, 0.0), full);
  const int rc = run_checker(dir.path(), expected);
  if (rc == 77) GTEST_SKIP() << "python3-vtk9 not installed";
  EXPECT_EQ(rc, 0);
}

TEST(VtkWriter, UnknownFieldIsAnError) {
  const comminute::testing::TestDir dir;
  ParticleStore p;
  io::VtkWriter out(dir.path(), std::vector<std::string>{"damgae"});
  try {
    out.write_particles(p, 0.0, 0);
    FAIL() << "no error for an unknown field";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'damgae'"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "particles.pvd"));
}

TEST(VtkWriter, CollectionListsOnlyCommittedFilesAndResumes) {
  const comminute::testing::TestDir dir;
  ParticleStore p;
  Rng rng(3);
  fill(p, rng, 3);
  {
    io::VtkWriter out(dir.path(), std::nullopt);
    out.start_fresh();
    for (int s = 0; s < 4; ++s) out.write_particles(p, 0.5 * s, std::uint64_t(s));
  }
  // A run killed while writing the next snapshot leaves only its .part file behind.
  std::ofstream(dir / "particles" / "particles_0000000004.vtp.part") << "<?xml half";
  // Restart from a checkpoint at t = 1 s: later snapshots are dropped from the collection.
  io::VtkWriter again(dir.path(), std::nullopt);
  again.resume(1.0);
  ASSERT_EQ(again.particles_collection().entries().size(), 3u);
  EXPECT_EQ(again.particles_collection().entries().back().time, 1.0);
  again.write_particles(p, 1.25, 99);
  io::PvdCollection reread(dir / "particles.pvd");
  reread.resume(1e300);
  ASSERT_EQ(reread.entries().size(), 4u);
  const double times[] = {0.0, 0.5, 1.0, 1.25};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(reread.entries()[k].time, times[k]);
    EXPECT_TRUE(std::filesystem::exists(dir / reread.entries()[k].file));
  }
  // A fresh run in the same folder removes the old series.
  io::VtkWriter fresh(dir.path(), std::nullopt);
  fresh.start_fresh();
  EXPECT_FALSE(std::filesystem::exists(dir / "particles.pvd"));
  EXPECT_FALSE(std::filesystem::exists(dir / "particles" / "particles_0000000099.vtp"));
}
