#include "comminute/geometry/stl_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

namespace comminute {

StlError::StlError(long triangle, long line, const std::string& message)
    : Error(message), triangle_(triangle), line_(line) {}

namespace {

std::string where(long triangle) {
  return triangle < 0 ? std::string() : fmt::format("triangle {}: ", triangle);
}

void check_finite(const Vec3& v, long triangle, long line) {
  if (!is_finite(v))
    throw StlError(
        triangle, line,
        fmt::format("{}vertex ({}, {}, {}) is not finite", where(triangle), v.x, v.y, v.z));
}

std::vector<Vec3> parse_binary(const std::string& b) {
  std::uint32_t n = 0;
  std::memcpy(&n, b.data() + 80, 4);
  std::vector<Vec3> corners;
  corners.reserve(3 * static_cast<std::size_t>(n));
  for (std::uint32_t t = 0; t < n; ++t) {
    const char* rec = b.data() + 84 + 50 * static_cast<std::size_t>(t);
    for (int k = 0; k < 3; ++k) {
      float f[3];
      std::memcpy(f, rec + 12 + 12 * k, 12);
      const Vec3 v{f[0], f[1], f[2]};
      check_finite(v, t, 0);
      corners.push_back(v);
    }
  }
  return corners;
}

std::vector<Vec3> parse_ascii(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  long line_no = 0, triangle = -1;
  int in_facet = -1;  // vertices read in the open facet, -1 outside a facet
  bool ended = false;
  std::vector<Vec3> corners;
  auto fail = [&](const std::string& m) { throw StlError(triangle, line_no, where(triangle) + m); };
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream ls(line);
    std::string word;
    if (!(ls >> word)) continue;
    if (word == "solid") {
      if (line_no != 1 && triangle >= 0) fail("a second 'solid' inside the file");
      continue;
    }
    if (word == "endsolid") {
      if (in_facet >= 0) fail("'endsolid' inside a facet");
      ended = true;
      break;
    }
    if (word == "facet") {
      if (in_facet >= 0) fail("'facet' before the previous facet ended");
      ++triangle;
      in_facet = 0;
    } else if (word == "vertex") {
      if (in_facet < 0 || in_facet >= 3) fail("'vertex' outside a facet or a fourth vertex");
      // strtod accepts nan and inf, so they are read and then refused with their triangle
      std::string s[3];
      if (!(ls >> s[0] >> s[1] >> s[2])) fail("a vertex needs three coordinates");
      double c[3];
      for (int k = 0; k < 3; ++k) {
        char* end = nullptr;
        c[k] = std::strtod(s[k].c_str(), &end);
        if (end == s[k].c_str() || *end != '\0') fail(fmt::format("'{}' is not a number", s[k]));
      }
      const Vec3 v{c[0], c[1], c[2]};
      check_finite(v, triangle, line_no);
      corners.push_back(v);
      ++in_facet;
    } else if (word == "endfacet") {
      if (in_facet != 3) fail(fmt::format("facet ends after {} vertices, not 3", in_facet));
      in_facet = -1;
    } else if (word != "outer" && word != "endloop") {
      fail(fmt::format("unexpected '{}'", word));
    }
  }
  if (!ended)
    throw StlError(triangle, line_no, where(triangle) + "file ends before 'endsolid' (truncated)");
  if (corners.empty()) throw StlError(-1, line_no, "no triangles");
  return corners;
}

}  // namespace

std::vector<Vec3> parse_stl(const std::string& bytes) {
  if (bytes.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50 * static_cast<std::uint64_t>(n)) {
      if (n == 0) throw StlError(-1, 0, "binary STL with no triangles");
      return parse_binary(bytes);
    }
  }
  if (bytes.compare(0, 5, "solid") == 0) return parse_ascii(bytes);
  if (bytes.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data() + 80, 4);
    const std::uint64_t whole = bytes.size() < 84 ? 0 : (bytes.size() - 84) / 50;
    throw StlError(static_cast<long>(std::min<std::uint64_t>(whole, n)), 0,
                   fmt::format("binary STL truncated: the header counts {} triangles ({} bytes) "
                               "but the file has {} bytes; triangle {} is incomplete",
                               n, 84 + 50 * static_cast<std::uint64_t>(n), bytes.size(), whole));
  }
  throw StlError(-1, 0,
                 fmt::format("not an STL file ({} bytes: shorter than a binary header and not "
                             "starting with 'solid')",
                             bytes.size()));
}

IndexedMesh weld(const std::vector<Vec3>& corners) {
  IndexedMesh m;
  std::map<std::tuple<double, double, double>, std::uint32_t> index;
  m.triangles.resize(corners.size() / 3);
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const Vec3& v = corners[c];
    auto [it, fresh] = index.emplace(std::make_tuple(v.x, v.y, v.z),
                                     static_cast<std::uint32_t>(m.vertices.size()));
    if (fresh) m.vertices.push_back(v);
    m.triangles[c / 3][c % 3] = it->second;
  }
  return m;
}

void validate_mesh(const IndexedMesh& m) {
  // directed edge (a, b) -> first triangle running along it
  std::map<std::pair<std::uint32_t, std::uint32_t>, long> directed;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<long>> undirected;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    const Vec3 &a = m.vertices[tri[0]], &b = m.vertices[tri[1]], &c = m.vertices[tri[2]];
    const double longest = std::max({norm2(b - a), norm2(c - b), norm2(a - c)});
    const double area2 = norm(cross(b - a, c - a));  // twice the area
    if (!std::isfinite(longest) || !std::isfinite(area2))
      throw StlError(
          static_cast<long>(t), 0,
          fmt::format("triangle {}: coordinates too large (its edges or area overflow)", t));
    if (!(area2 > 2e-12 * longest))
      throw StlError(static_cast<long>(t), 0,
                     fmt::format("triangle {}: zero area (corners ({}, {}, {}), ({}, {}, {}), ({}, "
                                 "{}, {}))",
                                 t, a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z));
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = tri[k], v = tri[(k + 1) % 3];
      auto& users = undirected[std::minmax(u, v)];
      users.push_back(static_cast<long>(t));
      if (users.size() > 2)
        throw StlError(
            static_cast<long>(t), 0,
            fmt::format("triangle {}: non-manifold edge ({}, {}, {})-({}, {}, {}), "
                        "shared with triangles {} and {}",
                        t, m.vertices[u].x, m.vertices[u].y, m.vertices[u].z, m.vertices[v].x,
                        m.vertices[v].y, m.vertices[v].z, users[0], users[1]));
      auto [it, fresh] = directed.emplace(std::make_pair(u, v), static_cast<long>(t));
      if (!fresh)
        throw StlError(static_cast<long>(t), 0,
                       fmt::format("triangle {}: inconsistently oriented: it runs along its edge "
                                   "({}, {}, {})-({}, {}, {}) in the same direction as triangle {}",
                                   t, m.vertices[u].x, m.vertices[u].y, m.vertices[u].z,
                                   m.vertices[v].x, m.vertices[v].y, m.vertices[v].z, it->second));
    }
  }
}

IndexedMesh read_stl(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw StlError(-1, 0, fmt::format("{}: cannot be opened", file.string()));
  std::ostringstream s;
  s << in.rdbuf();
  try {
    IndexedMesh m = weld(parse_stl(s.str()));
    validate_mesh(m);
    return m;
  } catch (const StlError& e) {
    const std::string at =
        e.line() > 0 ? fmt::format("{}:{}", file.string(), e.line()) : file.string();
    throw StlError(e.triangle(), e.line(), fmt::format("{}: {}", at, e.what()));
  }
}

}  // namespace comminute
