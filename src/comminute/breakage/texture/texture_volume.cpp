#include "comminute/breakage/texture/texture_volume.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "comminute/core/error.hpp"

namespace comminute::breakage::texture {

TextureVolume::TextureVolume(std::size_t nx, std::size_t ny, std::size_t nz, double voxel_size,
                             std::vector<std::uint8_t> labels, std::vector<Phase> phases)
    : nx_(nx),
      ny_(ny),
      nz_(nz),
      voxel_(voxel_size),
      labels_(std::move(labels)),
      phases_(std::move(phases)) {
  if (nx_ == 0 || ny_ == 0 || nz_ == 0 || labels_.size() != nx_ * ny_ * nz_)
    throw Error("texture volume: labels do not match the size");
  if (!(voxel_ > 0)) throw Error("texture volume: voxel size must be > 0");
  if (phases_.empty() || phases_.size() > 255) throw Error("texture volume: 1 to 255 phases");
  for (std::uint8_t l : labels_)
    if (l >= phases_.size())
      throw Error("texture volume: label " + std::to_string(l) + " but only " +
                  std::to_string(phases_.size()) + " phases");
}

Vec3 TextureVolume::extent() const {
  return {voxel_ * static_cast<double>(nx_), voxel_ * static_cast<double>(ny_),
          voxel_ * static_cast<double>(nz_)};
}

namespace {
std::size_t wrap(double x, double voxel, std::size_t n) {
  const double c = std::floor(x / voxel);
  const double m = c - std::floor(c / static_cast<double>(n)) * static_cast<double>(n);
  const auto i = static_cast<std::size_t>(m);
  return i < n ? i : n - 1;  // m may round up to n for tiny negative x
}
}  // namespace

std::uint8_t TextureVolume::at(const Vec3& x) const {
  return label(wrap(x.x, voxel_, nx_), wrap(x.y, voxel_, ny_), wrap(x.z, voxel_, nz_));
}

std::vector<double> TextureVolume::fractions() const {
  std::vector<double> f(phases_.size(), 0.0);
  for (std::uint8_t l : labels_) f[l] += 1;
  for (double& v : f) v /= static_cast<double>(labels_.size());
  return f;
}

TextureVolume read_raw_texture(const std::string& path, std::vector<Phase> phases) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("texture image '" + path + "': cannot open");
  auto bad = [&](const std::string& why) { return Error("texture image '" + path + "': " + why); };
  std::string line;
  if (!std::getline(in, line) || line != "comminute-texture 1")
    throw bad("first line must be 'comminute-texture 1'");
  std::size_t n[3] = {0, 0, 0};
  double voxel = 0;
  bool ended = false;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string key;
    ls >> key;
    if (key == "end_header") {
      ended = true;
      break;
    }
    if (key == "size") {
      if (!(ls >> n[0] >> n[1] >> n[2])) throw bad("'size' needs three integers");
    } else if (key == "voxel_size") {
      if (!(ls >> voxel) || !(voxel > 0)) throw bad("'voxel_size' needs a number > 0 (m)");
    } else if (!key.empty()) {
      throw bad("unknown header key '" + key + "'");
    }
  }
  if (!ended) throw bad("no 'end_header' line");
  if (n[0] == 0 || n[1] == 0 || n[2] == 0) throw bad("'size' missing or zero");
  if (!(voxel > 0)) throw bad("'voxel_size' missing");
  std::vector<std::uint8_t> labels(n[0] * n[1] * n[2]);
  in.read(reinterpret_cast<char*>(labels.data()), static_cast<std::streamsize>(labels.size()));
  if (static_cast<std::size_t>(in.gcount()) != labels.size())
    throw bad("expected " + std::to_string(labels.size()) + " voxel bytes, found " +
              std::to_string(in.gcount()));
  if (in.peek() != std::char_traits<char>::eof()) throw bad("bytes after the last voxel");
  for (std::uint8_t l : labels)
    if (l >= phases.size())
      throw bad("voxel label " + std::to_string(l) + " but only " + std::to_string(phases.size()) +
                " phases are defined");
  return TextureVolume(n[0], n[1], n[2], voxel, std::move(labels), std::move(phases));
}

void write_raw_texture(const std::string& path, const TextureVolume& v) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error("texture image '" + path + "': cannot write");
  out << "comminute-texture 1\nsize " << v.nx() << ' ' << v.ny() << ' ' << v.nz() << '\n';
  out.precision(17);
  out << "voxel_size " << v.voxel_size() << "\nend_header\n";
  for (std::size_t k = 0; k < v.nz(); ++k)
    for (std::size_t j = 0; j < v.ny(); ++j)
      for (std::size_t i = 0; i < v.nx(); ++i) out.put(static_cast<char>(v.label(i, j, k)));
}

}  // namespace comminute::breakage::texture
