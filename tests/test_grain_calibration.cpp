// Single-grain compression and calibration (issue 11 point 6): a small bonded grain pressed
// between a floor and a platen gives a force–displacement curve; `comminute calibrate`'s grain
// mode fits bond parameters to it. The "measured" curve is made here by the same compression at
// known parameters; the fit, started from the case's other values and random starts, must
// recover them.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "case_docs_check.hpp"
#include "case_sections.hpp"
#include "comminute/calibrate/multistart.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/grain_compression_case.hpp"
#include "source_file.hpp"
#include "temp_dir.hpp"

using namespace comminute;

namespace {

constexpr double kR = 5e-4;  // m, sub-sphere radius

// A grain of four sub-spheres: three touching on the floor, one resting in their hollow (a
// tetrahedron). The platen pushes the top sphere down; it wedges the three apart, so the three
// base bonds are pulled and fail in tension at the peak force.
void write_grain(const std::filesystem::path& file) {
  std::ofstream d(file);
  d << "# four sub-spheres, a tetrahedron on the floor\n\n4 atoms\n1 atom types\n\nAtoms # "
       "sphere\n\n";
  const double rho = 2 * kR / std::sqrt(3.0);  // base centres from the axis: touching
  for (int k = 0; k < 3; ++k) {
    const double a = 2 * std::numbers::pi * k / 3;
    d << fmt::format("{} 1 {} 1450 {:.15g} {:.15g} {:.15g}\n", k + 1, 2 * kR, rho * std::cos(a),
                     rho * std::sin(a), kR);
  }
  d << fmt::format("4 1 {} 1450 0 0 {:.15g}\n", 2 * kR, kR + 2 * kR * std::sqrt(2.0 / 3.0));
}

std::string case_text(double stiffness, double strength, bool calibration) {
  const double top = 2 * kR + 2 * kR * std::sqrt(2.0 / 3.0) + 1e-6;  // 1 um above the grain
  using namespace comminute::testing;
  std::string s = dem_sections({3, 0.002, 1e-7, 5e-5}, {"grain", 1450.0, 1.0e10, 0.3, 0.3, 0.0}) +
                  plane_wall("floor", 0.0, 1.0, "grain") +
                  plane_wall("platen", top, -1.0, "grain", velocity_z(-0.1)) +
                  data_file_insert("grain", "grain.data") +
                  parallel_bond_section({1e-6, stiffness, 4e11, strength, 1e9});
  if (calibration)
    s += "[calibration]\nstarts = 2\nseed = 5\nthreads = 1\n" +
         calibration_parameter("bonds.normal_stiffness", 2e11, 2e13) +
         calibration_parameter("bonds.tensile_strength", 1e6, 2e7) +
         "[calibration.compression]\nplaten = \"platen\"\nfile = \"measured.csv\"\n";
  return s;
}

}  // namespace

TEST(GrainCalibration, CompressionCurveRisesToThePeakOfTheBaseBondsAndDrops) {
  comminute::testing::TestDir dir;
  write_grain(dir.path() / "grain.data");
  std::ofstream(dir.path() / "grain.toml") << case_text(1e12, 5e6, false);
  const CaseFile file = CaseFile::load(dir.path() / "grain.toml");
  const io::ForceDisplacement c = io::compress_grain(file, {"platen", 0.0, 1.0}, 1e-4);
  ASSERT_GT(c.force.size(), 10u);
  const auto peak = std::max_element(c.force.begin(), c.force.end());
  // the three base bonds carry the wedge's spread: each pulled with F/(3√6) (top sphere's three
  // legs at cos θ = √(2/3), their outward push F tan θ / 3 split over two bonds at 30°); the
  // tensile criterion adds the bending stress |M| R̄/I, so the peak lies below 3√6 σ̄ A
  const double area = std::numbers::pi * kR * kR;
  const double axial_only = 3 * std::sqrt(6.0) * 5e6 * area;
  RecordProperty("peak_force", std::to_string(*peak));
  EXPECT_LT(*peak, axial_only);
  EXPECT_GT(*peak, 0.3 * axial_only);  // same order: the base bonds do fail by the wedge
  // after the peak the force drops: the base bonds have failed
  EXPECT_LT(c.force.back(), 0.5 * *peak);
}

TEST(GrainCalibration, FitRecoversTheBondStiffnessAndStrength) {
  comminute::testing::TestDir dir;
  write_grain(dir.path() / "grain.data");
  const double kn = 1e12, sigma = 5e6;  // the "true" parameters
  {
    std::ofstream(dir.path() / "truth.toml") << case_text(kn, sigma, false);
    const CaseFile truth = CaseFile::load(dir.path() / "truth.toml");
    const io::ForceDisplacement c = io::compress_grain(truth, {"platen", 0.0, 1.0}, 1e-4);
    const auto peak = std::max_element(c.force.begin(), c.force.end());
    const double at_peak = c.displacement[static_cast<std::size_t>(peak - c.force.begin())];
    // a testing machine's record: 60 points to 1.3 × the peak's displacement (the rise, the peak
    // and the drop), and the peak itself (it records far more often than that)
    std::ofstream m(dir.path() / "measured.csv");
    m << "displacement [m],force [N]\n";
    for (int k = 1; k <= 60; ++k) {
      const double x = 1.3 * at_peak * k / 60;
      const double prev = 1.3 * at_peak * (k - 1) / 60;
      if (prev < at_peak && at_peak < x) m << fmt::format("{:.15g},{:.15g}\n", at_peak, *peak);
      m << fmt::format("{:.15g},{:.15g}\n", x, io::force_at(c, x));
    }
  }
  // the case's own values are off by 3× and 2×
  std::ofstream(dir.path() / "fit.toml") << case_text(3e12, 1e7, true);
  const CaseFile file = CaseFile::load(dir.path() / "fit.toml");
  const io::GrainCalibrationCase cc = io::read_grain_calibration(file);
  file.reject_unknown();
  comminute::testing::expect_used_keys_documented(
      file, comminute::testing::read_source_file("docs/case-file.md"));
  const auto r = calibrate::multistart(cc.space, cc.objective, cc.options);
  const auto& best = r.starts[r.best];
  RecordProperty("normal_stiffness", std::to_string(best.best[0]));
  RecordProperty("tensile_strength", std::to_string(best.best[1]));
  RecordProperty("objective", std::to_string(best.f));
  RecordProperty("evaluations", std::to_string(best.run.evaluations));
  // Tolerance 2 %: the data are the model's own, so J = 0 exactly at the truth; what limits the
  // recovery is the optimiser's stop (x_tolerance 1e-4 of the log range ≈ 0.05 %) and the peak
  // being the force at a whole step: the peak term is a staircase in σ̄ whose steps are one
  // step's platen travel (10 nm) of the ~25 um to the peak, 0.04 % each. Either parameter 2 %
  // off raises J far above the best found (checked below).
  EXPECT_NEAR(best.best[0], kn, 0.02 * kn);
  EXPECT_NEAR(best.best[1], sigma, 0.02 * sigma);
  EXPECT_LT(best.f, 0.1 * cc.objective({1.02 * kn, sigma}));
  EXPECT_LT(best.f, 0.1 * cc.objective({kn, 1.02 * sigma}));
}

TEST(GrainCalibration, BadCompressionInputIsRefused) {
  comminute::testing::TestDir dir;
  write_grain(dir.path() / "grain.data");
  std::ofstream(dir.path() / "measured.csv") << "displacement [m],force [N]\n0,0\n1e-5,3\n";
  auto refused = [&](const std::string& text, const std::string& key) {
    std::ofstream(dir.path() / "bad.toml") << text;
    const CaseFile file = CaseFile::load(dir.path() / "bad.toml");
    try {
      io::read_grain_calibration(file);
      ADD_FAILURE() << "accepted; expected a refusal naming " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  const std::string good = case_text(1e12, 5e6, true);
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  refused(replaced("platen = \"platen\"", "platen = \"lid\""), "calibration.compression.platen");
  refused(replaced("velocity = [0.0, 0.0, -0.1]", ""), "calibration.compression.platen");
  refused(replaced("end_time = 0.002", "end_time = 1e-5"), "simulation.end_time");
  refused(replaced("key = \"bonds.tensile_strength\"", "key = \"bonds.law\""),
          "calibration.parameter");
  std::ofstream(dir.path() / "measured.csv") << "displacement [m],force [N]\n0,0\n0,3\n";
  refused(good, "calibration.compression.file");
}
