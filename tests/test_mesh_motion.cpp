// Mesh motion (rotation with rpm and ramp, eccentric swing, oscillation, table), per-mesh power,
// Archard wear, checkpointed pose, case-file placement, and the moving VTK series read back with
// VTK's own reader.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>

#include "comminute/geometry/rigid_motion.hpp"
#include "comminute/io/output/timeseries_csv.hpp"
#include "comminute/io/output/vtk_writer.hpp"
#include "dem_fixture.hpp"
#include "mesh_fixture.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

std::unique_ptr<MotionModel> motion(const std::string& toml) {
  const CaseFile f = CaseFile::parse(toml);
  return make_motion(f.root());
}

IndexedMesh one_triangle() {
  IndexedMesh m;
  m.vertices = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 1, 2}};
  return m;
}

}  // namespace

TEST(MeshMotion, RampedRotationInRpmTurnsByTheIntegratedAngle) {
  auto w =
      mesh_wall(one_triangle(), motion("type = \"rotation\"\naxis = [0, 0, 2]\nspeed_rpm = 60\n"
                                       "ramp_time = 0.5\n"));
  const double dt = 1e-4;
  for (int k = 0; k < 10000; ++k) w->advance(dt);
  // 60 rpm = 2 pi rad/s reached linearly over 0.5 s, then held: angle = 2 pi (0.25 + 0.5)
  const double angle = 2 * std::numbers::pi * 0.75;
  const Vec3 v = w->surface(0).vertices[0];
  // 1e-9: the mid-step rate integrates a linear ramp exactly; round-off of 10^4 rotations
  EXPECT_NEAR(v.x, std::cos(angle), 1e-9);
  EXPECT_NEAR(v.y, std::sin(angle), 1e-9);
  EXPECT_NEAR(w->kinematics.angular_velocity.z, 2 * std::numbers::pi, 1e-12);
}

TEST(MeshMotion, EccentricOscillationAndTableMoveAsIntegrated) {
  const double dt = 1e-5;
  // eccentric shaft at 5 Hz (300 rpm), e = 10 mm, about z: after a quarter turn the centre moved
  // by e (w - u), u and w = z x u being the model's in-plane axes
  auto ecc = mesh_wall(one_triangle(),
                       motion("type = \"eccentric\"\naxis = [0, 0, 1]\neccentricity = 0.01\n"
                              "speed_rpm = 300\nswing_amplitude = 0.05\n"));
  for (int k = 0; k < 5000; ++k) ecc->advance(dt);  // 0.05 s = 1/4 turn
  const Vec3 u = perpendicular({0, 0, 1}), wv = cross(Vec3{0, 0, 1}, u);
  const Vec3 moved = ecc->kinematics.center;
  // 1e-9 m: second-order (mid-step) integration of a circle of 10 mm in 5000 steps
  EXPECT_NEAR(norm(moved - 0.01 * (wv - u)), 0.0, 1e-9);
  // swing: angle 0.05 sin(Omega t) = 0.05 after a quarter turn, about the centre
  const Vec3 v0 = ecc->surface(0).vertices[2];  // (0, 0, 1) lies on the axis: only translated
  EXPECT_NEAR(norm(v0 - (Vec3{0, 0, 1} + moved)), 0.0, 1e-12);
  // oscillation: amplitude 2 mm at 10 Hz along x reaches the amplitude after a quarter period
  auto osc = mesh_wall(one_triangle(),
                       motion("type = \"oscillation\"\ndirection = [1, 0, 0]\namplitude = 0.002\n"
                              "frequency = 10\n"));
  for (int k = 0; k < 2500; ++k) osc->advance(dt);
  // 1e-9: mid-step rule error, about dt^2/24 A omega^3 t = 5e-11
  EXPECT_NEAR(osc->kinematics.center.x, 0.002, 1e-9);
  // table: linear in between, held after the end
  auto tab = motion(
      "type = \"table\"\ntime = [0, 1, 2]\nvelocity = [0, 0, 0, 1, 0, 0, 1, 2, 0]\n"
      "angular_velocity = [0, 0, 1, 0, 0, 3, 0, 0, 3]\n");
  Vec3 v, w;
  tab->at(1.5, v, w);
  EXPECT_EQ(v, (Vec3{1, 1, 0}));
  EXPECT_EQ(w, (Vec3{0, 0, 3}));
  tab->at(7, v, w);
  EXPECT_EQ(v, (Vec3{1, 2, 0}));
}

TEST(MeshMotion, PoseAndWearRestartBitForBit) {
  auto make = [] {
    return mesh_wall(tiled_square(2, 0.01),
                     motion("type = \"rotation\"\naxis = [1, 1, 0]\nangular_speed = 3\n"
                            "ramp_time = 0.01\n"),
                     ArchardWear{1e-3, 1e9});
  };
  auto a = make(), b = make();
  a->kinematics.center = b->kinematics.center = {0.01, 0.02, 0};
  for (int k = 0; k < 777; ++k) a->advance(1e-5);
  a->wear(3, 2.0, 1e-3);
  Archive ar;
  a->save(ar, "walls/0/");
  b->load(ar, "walls/0/");
  for (int k = 0; k < 1000; ++k) {
    a->advance(1e-5);
    b->advance(1e-5);
  }
  EXPECT_EQ(a->surface(0).vertices, b->surface(0).vertices);
  EXPECT_EQ(a->wear_volume(), b->wear_volume());
  EXPECT_EQ(a->wear_volume()[3], 1e-3 * 2.0 * 1e-3 / 1e9);  // Archard: k F s / H
}

namespace {

std::vector<std::vector<double>> read_csv_rows(const std::filesystem::path& p) {
  std::ifstream f(p);
  std::string line;
  std::getline(f, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(f, line)) {
    std::vector<double> r;
    std::size_t s = 0;
    while (s <= line.size()) {
      const std::size_t e = std::min(line.find(',', s), line.size());
      r.push_back(std::stod(line.substr(s, e - s)));
      s = e + 1;
    }
    rows.push_back(r);
  }
  return rows;
}

// A simulation under gravity with one moving mesh wall named `name`.
std::unique_ptr<Simulation> with_moving_mesh(DemSetup s, const IndexedMesh& mesh,
                                             const std::string& motion_toml,
                                             const std::string& name) {
  s.gravity = {0, 0, -9.81};
  auto sim = make_simulation(s);
  sim->walls.push_back(mesh_wall(mesh, motion(motion_toml)));
  sim->walls[0]->name = name;
  return sim;
}

// Index of a time-series column by name (the column set grows; tests must not count).
std::size_t column(const std::string& wall, const std::string& name) {
  const auto cols = io::TimeSeriesWriter::columns({wall});
  for (std::size_t k = 0; k < cols.size(); ++k)
    if (cols[k].name == name) return k;
  throw std::logic_error("no time-series column " + name);
}

}  // namespace

TEST(MeshMotion, ElevatorPowerIsWeightTimesSpeed) {
  // A sphere resting on a mesh plate that rises at 10 mm/s: the plate carries the weight, the
  // sphere pushes it down with m g and the drive delivers P = m g v.
  const TestDir dir;
  DemSetup s;
  s.youngs = 1e9;
  auto sim = with_moving_mesh(s, tiled_square(2, 0.01),
                              "type = \"translation\"\nvelocity = [0, 0, 0.01]\n", "lift");
  const double r = 0.005;
  add_sphere(*sim, {0.01, 0.01, r}, r);
  sim->dt = 1e-5;
  sim->setup();
  sim->run(30000);  // 0.3 s: the contact oscillation (period ~ 10 ms, e = 0.5) has died out
  io::TimeSeriesWriter ts(dir / "ts.csv", {"lift"});
  ts.start_fresh();
  ts.append(sim->observe(), sim->walls);
  const auto row = read_csv_rows(dir / "ts.csv").at(0);
  const double m = sim->particles.mass[0];
  // 1e-6: the residual oscillation of the contact after 30 periods at e = 0.5 (about 0.5^30)
  EXPECT_NEAR(row.at(column("lift", "lift_Fz")), -m * 9.81, 1e-6 * m * 9.81);  // lift_Fz
  EXPECT_NEAR(row.at(column("lift", "lift_P")), m * 9.81 * 0.01, 1e-6 * m * 9.81 * 0.01);  // lift_P
  std::printf("elevator power %.9g W, m g v = %.9g W\n", row.at(column("lift", "lift_P")),
              m * 9.81 * 0.01);
}

TEST(MeshMotion, TurntablePowerIsTorqueTimesOmegaAndSumsToTheWallWork) {
  // A sphere dropped off-axis on a mesh turntable (2 rad/s about z through its centre) is dragged
  // along by friction. The reported power -(F.v + T.omega) = -T.omega summed over the steps is
  // the work the turntable did, which the energy ledger books contact by contact.
  const TestDir dir;
  DemSetup s;
  s.friction = 0.5;
  auto sim = with_moving_mesh(s, tiled_square(4, 0.01, -0.02, -0.02),
                              "type = \"rotation\"\nangular_speed = 2\n", "table");
  add_sphere(*sim, {0.012, 0.003, 0.0051}, 0.005);  // not touching at set-up
  sim->dt = 1e-6;
  sim->setup();
  io::TimeSeriesWriter ts(dir / "ts.csv", {"table"});
  ts.start_fresh();
  for (int k = 0; k < 20000; ++k) {
    sim->step();
    ts.append(sim->observe(), sim->walls);
  }
  double work = 0;
  for (const auto& row : read_csv_rows(dir / "ts.csv"))
    work += row.at(column("table", "table_P")) * sim->dt;
  const double booked = sim->observe().ledger.wall_work;
  ASSERT_GT(booked, 1e-7);
  // 1e-9 relative: the same sum in another order (the CSV's shortest round-trip digits are exact)
  EXPECT_NEAR(work, booked, 1e-9 * booked);
  std::printf("turntable: sum of P dt %.12g J, ledger wall work %.12g J\n", work, booked);
}

TEST(MeshMotion, ArchardWearOfASlidingSphere) {
  // A sphere resting on a plate with speed v0 and no spin slides until it rolls: the slip speed
  // falls at (1 + 5/2) mu g, so the sliding distance is v0^2 / (7 mu g), and Archard's law
  // (V = k F_n s / H) gives a worn volume k m v0^2 / (7 mu H) on the triangles it slid over.
  DemSetup s;
  s.gravity = {0, 0, -9.81};
  s.friction = 0.3;
  auto sim = make_simulation(s);
  const double k = 1e-4, hardness = 2e9;
  sim->walls.push_back(mesh_wall(tiled_square(8, 0.01), nullptr, ArchardWear{k, hardness}));
  const double r = 0.005, v0 = 0.2;
  const double m = 2500 * 4.0 / 3.0 * M_PI * r * r * r;
  const double estar = 1e7 / (2 * (1 - 0.09));
  const double delta = std::pow(m * 9.81 / (4.0 / 3.0 * estar * std::sqrt(r)), 2.0 / 3.0);
  add_sphere(*sim, {0.01, 0.04, r - delta}, r, {v0, 0, 0});
  sim->dt = 1e-6;
  sim->setup();
  sim->run(100000);
  const auto* mesh = dynamic_cast<const MeshWall*>(sim->walls[0].get());
  double worn = 0;
  for (double v : mesh->wear_volume()) worn += v;
  const double expect = k * m * v0 * v0 / (7 * 0.3 * hardness);
  // 2 %: the tangential spring stores a little elastic slip at the stick transition, and the
  // normal force oscillates slightly about m g while sliding
  EXPECT_NEAR(worn, expect, 0.02 * expect);
  std::printf("Archard wear: %.6g m3, analytic %.6g m3 (%+.3f %%)\n", worn, expect,
              100 * (worn / expect - 1));
  // the wear depth drawn on the triangles is the volume over each triangle's area
  const SurfaceMesh sm = mesh->surface(0);
  EXPECT_NEAR(sm.wear_depth[0] * 0.5e-4, mesh->wear_volume()[0], 1e-30);
}

TEST(MeshMotion, CaseFilePlacesTheStlWithUnitScaleRotationAndTranslation) {
  const TestDir dir;
  IndexedMesh m;
  m.vertices = {{0, 0, 0}, {10, 0, 0}, {0, 20, 0}};  // mm
  m.triangles = {{0, 1, 2}};
  write_ascii_stl(dir / "tri.stl", m);
  const CaseFile f =
      CaseFile::parse(fmt::format("type = \"mesh\"\nfile = \"{}\"\nunit_scale = 0.001\nscale = 2\n"
                                  "rotate = [0, 0, 90]\ntranslate = [1, 2, 3]\n",
                                  (dir / "tri.stl").string()));
  f.root().mark_used("type");  // read by the case builder
  auto w = WallRegistry::create("mesh", f.root());
  const auto v = w->surface(0).vertices;
  // (10 mm, 0) -> 20 mm along x -> turned 90 degrees about z: along y -> shifted
  EXPECT_NEAR(norm(v[1] - Vec3{1, 2.02, 3}), 0, 1e-15);
  EXPECT_NEAR(norm(v[2] - Vec3{1 - 0.04, 2, 3}), 0, 1e-15);
  f.reject_unknown();
  // a scale that makes the placed mesh overflow is refused naming the key
  const CaseFile huge = CaseFile::parse(fmt::format(
      "type = \"mesh\"\nfile = \"{}\"\nunit_scale = 1e300\n", (dir / "tri.stl").string()));
  try {
    WallRegistry::create("mesh", huge.root());
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("after unit_scale, scale, rotate and translate"),
              std::string::npos)
        << e.what();
  }
}

TEST(MeshMotion, VtkSeriesMovesWithTheMeshAndCarriesWear) {
  const TestDir dir;
  std::vector<std::unique_ptr<Wall>> walls;
  walls.push_back(mesh_wall(tiled_square(1, 0.1),
                            motion("type = \"rotation\"\naxis = [0, 0, 1]\nangular_speed = 1\n"),
                            ArchardWear{1e-3, 1e9}));
  walls[0]->name = "drum";
  io::VtkWriter out(dir.path(), std::nullopt);
  out.start_fresh();
  std::vector<std::string> steps;
  for (int s = 0; s < 3; ++s) {
    const double t = 0.5 * s;
    out.write_walls(walls, t, static_cast<std::uint64_t>(s), 1.0);
    const SurfaceMesh sm = walls[0]->surface(0);
    std::vector<std::string> pts;
    for (const Vec3& p : sm.vertices) pts.push_back(fmt::format("[{},{},{}]", p.x, p.y, p.z));
    steps.push_back(fmt::format(R"({{"time":{},"points":[{}],"wear":[{}]}})", t,
                                fmt::join(pts, ","), fmt::join(sm.wear_depth, ",")));
    for (int k = 0; k < 5000; ++k) walls[0]->advance(1e-4);  // 0.5 rad
    walls[0]->wear(1, 1.0, 1e-3 * (s + 1));
  }
  std::ofstream(dir / "expected.json") << "[" << fmt::format("{}", fmt::join(steps, ",")) << "]";
  const std::string cmd =
      fmt::format("/usr/bin/python3 {}/tests/scripts/check_mesh_vtk.py {} {}", COMMINUTE_SOURCE_DIR,
                  dir.path().string(), (dir / "expected.json").string());
  const int status = std::system(cmd.c_str());
  const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (rc == 77) GTEST_SKIP() << "python3-vtk9 not installed";
  EXPECT_EQ(rc, 0);
}

TEST(MeshMotion, SimulationWithARampedMeshRestartsBitForBit) {
  // Spheres on a tilted mesh turntable that speeds up: save mid-run, load into a fresh
  // simulation, continue both: every position, velocity and the mesh force agree exactly.
  auto make = [] {
    DemSetup s;
    s.friction = 0.5;
    auto sim = with_moving_mesh(s, tiled_square(4, 0.01, -0.02, -0.02),
                                "type = \"rotation\"\naxis = [0.1, 0, 1]\nspeed_rpm = 40\n"
                                "ramp_time = 0.002\n",
                                "table");
    for (int k = 0; k < 4; ++k) add_sphere(*sim, {-0.012 + 0.008 * k, 0.003, 0.00399}, 0.004);
    sim->dt = 1e-6;
    return sim;
  };
  auto a = make(), b = make();
  a->setup();
  a->run(2000);
  Archive ar;
  a->save(ar);
  b->load(ar);
  a->run(3000);
  b->run(3000);
  ASSERT_EQ(a->wall_contacts().size(), 4u);  // every sphere is pressed and dragged by the mesh
  for (std::size_t i = 0; i < a->particles.size(); ++i) {
    EXPECT_EQ(a->particles.x[i], b->particles.x[i]);
    EXPECT_EQ(a->particles.w[i], b->particles.w[i]);
  }
  EXPECT_EQ(a->walls[0]->force, b->walls[0]->force);
  EXPECT_EQ(a->walls[0]->surface(0).vertices, b->walls[0]->surface(0).vertices);
}
