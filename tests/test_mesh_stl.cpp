// STL import: ASCII and binary read the same mesh; every malformed file is refused naming the
// triangle (and the line for ASCII).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "mesh_fixture.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

std::string refusal(const std::string& bytes) {
  try {
    validate_mesh(weld(parse_stl(bytes)));
  } catch (const StlError& e) {
    return e.what();
  }
  return "accepted";
}

std::string ascii(const IndexedMesh& m) {
  const TestDir dir;
  write_ascii_stl(dir / "m.stl", m);
  std::ifstream f(dir / "m.stl");
  return std::string(std::istreambuf_iterator<char>(f), {});
}

}  // namespace

TEST(MeshStl, AsciiAndBinaryGiveTheSameWeldedMesh) {
  const IndexedMesh m = tiled_square(3, 0.25);  // 16 vertices, 18 triangles
  const TestDir dir;
  write_ascii_stl(dir / "a.stl", m);
  std::ofstream(dir / "b.stl", std::ios::binary) << binary_stl(m);
  const IndexedMesh a = read_stl(dir / "a.stl"), b = read_stl(dir / "b.stl");
  ASSERT_EQ(a.vertices.size(), 16u);  // corners shared by up to six triangles are welded
  ASSERT_EQ(b.vertices.size(), 16u);
  ASSERT_EQ(a.triangles, b.triangles);  // both number vertices in first-seen order
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Vec3& want = m.vertices[m.triangles[t][k]];
      EXPECT_EQ(a.vertices[a.triangles[t][k]], want);  // exact: 17 digits round-trip
      EXPECT_EQ(b.vertices[b.triangles[t][k]], want);  // exact: multiples of 1/4 are floats
    }
}

TEST(MeshStl, MalformedFilesNameTheTriangle) {
  IndexedMesh m = tiled_square(2, 1.0);  // 8 triangles
  const std::string good = binary_stl(m);
  // binary, cut in the middle of triangle 5
  EXPECT_NE(refusal(good.substr(0, 84 + 50 * 5 + 20)).find("triangle 5 is incomplete"),
            std::string::npos);
  // ASCII, cut after the third facet
  const std::string text = ascii(m);
  std::size_t cut = 0;
  for (int k = 0; k < 3; ++k) cut = text.find("endfacet", cut) + 8;
  EXPECT_NE(refusal(text.substr(0, cut)).find("triangle 2: file ends before 'endsolid'"),
            std::string::npos);
  // a NaN and an infinite coordinate
  IndexedMesh bad = m;
  bad.vertices.push_back({std::numeric_limits<double>::quiet_NaN(), 0, 0});
  bad.triangles[4][1] = static_cast<std::uint32_t>(bad.vertices.size() - 1);
  EXPECT_NE(refusal(ascii(bad)).find("triangle 4: vertex (nan, 0, 0) is not finite"),
            std::string::npos)
      << refusal(ascii(bad));
  bad.vertices.back().x = std::numeric_limits<double>::infinity();
  EXPECT_NE(refusal(binary_stl(bad)).find("triangle 4: vertex (inf, 0, 0) is not finite"),
            std::string::npos);
  // zero area: a triangle with two equal corners, and one with collinear corners
  bad = m;
  bad.triangles[6][2] = bad.triangles[6][1];
  EXPECT_NE(refusal(ascii(bad)).find("triangle 6: zero area"), std::string::npos);
  bad = m;
  bad.vertices.push_back({0.5, 0, 0});  // on the edge (0,0,0)-(1,0,0)
  bad.triangles.push_back({0, 1, static_cast<std::uint32_t>(bad.vertices.size() - 1)});
  EXPECT_NE(refusal(binary_stl(bad)).find("triangle 8: zero area"), std::string::npos);
  // inconsistent orientation: triangle 1 flipped runs along its diagonal like triangle 0
  bad = m;
  std::swap(bad.triangles[1][1], bad.triangles[1][2]);
  EXPECT_NE(refusal(ascii(bad)).find("triangle 1: inconsistently oriented"), std::string::npos);
  // non-manifold: a fin on the diagonal of cell (0, 0), shared by three triangles
  bad = m;
  bad.vertices.push_back({0.5, 0.5, 1});
  bad.triangles.push_back({2 + 2 + 0, 0, static_cast<std::uint32_t>(bad.vertices.size() - 1)});
  EXPECT_NE(refusal(binary_stl(bad)).find("triangle 8: non-manifold edge"), std::string::npos)
      << refusal(binary_stl(bad));
  // finite coordinates whose edges overflow
  bad = m;
  bad.vertices[8] = {1e308, -1e308, 0};
  EXPECT_NE(refusal(ascii(bad)).find("coordinates too large"), std::string::npos);
  // neither form
  EXPECT_NE(refusal("hello").find("not an STL file"), std::string::npos);
  EXPECT_EQ(refusal(good), "accepted");
}

TEST(MeshStl, FileErrorsCarryTheFileAndLine) {
  const TestDir dir;
  IndexedMesh bad = tiled_square(1, 1.0);
  bad.vertices.push_back({std::numeric_limits<double>::quiet_NaN(), 0, 0});
  bad.triangles[1][2] = 4;
  write_ascii_stl(dir / "nan.stl", bad);
  try {
    read_stl(dir / "nan.stl");
    FAIL() << "accepted";
  } catch (const StlError& e) {
    // line 1 "solid", 7 lines per facet: triangle 1's third vertex is on line 1 + 7 + 5 = 13
    EXPECT_NE(std::string(e.what()).find("nan.stl:13: triangle 1: vertex (nan"), std::string::npos)
        << e.what();
  }
}
