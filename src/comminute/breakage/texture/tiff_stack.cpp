#include "comminute/breakage/texture/tiff_stack.hpp"

#include <cstdint>
#include <fstream>
#include <iterator>

#include "comminute/core/error.hpp"

namespace comminute::breakage::texture {

namespace {

class TiffFile {
 public:
  explicit TiffFile(const std::string& path) : path_(path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail("cannot open");
    bytes_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (bytes_.size() < 8) fail("too short for a TIFF header");
    if (bytes_[0] == 'I' && bytes_[1] == 'I')
      big_ = false;
    else if (bytes_[0] == 'M' && bytes_[1] == 'M')
      big_ = true;
    else
      fail("not a TIFF file (no II/MM byte order mark)");
    if (u16(2) != 42) fail("not a classic TIFF file (magic number is not 42)");
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw Error("texture image '" + path_ + "': " + why);
  }
  std::uint32_t u8(std::size_t at) const {
    if (at >= bytes_.size()) fail("offset beyond the end of the file");
    return static_cast<unsigned char>(bytes_[at]);
  }
  std::uint32_t u16(std::size_t at) const {
    return big_ ? (u8(at) << 8) | u8(at + 1) : u8(at) | (u8(at + 1) << 8);
  }
  std::uint32_t u32(std::size_t at) const {
    return big_ ? (u16(at) << 16) | u16(at + 2) : u16(at) | (u16(at + 2) << 16);
  }
  // Values of an IFD entry of type SHORT (3) or LONG (4).
  std::vector<std::uint32_t> values(std::size_t entry) const {
    const std::uint32_t type = u16(entry + 2), count = u32(entry + 4);
    if (type != 3 && type != 4) fail("tag " + std::to_string(u16(entry)) + " is not SHORT or LONG");
    const std::size_t size = type == 3 ? 2 : 4;
    if (count > bytes_.size()) fail("tag count beyond the file");
    const std::size_t at = count * size <= 4 ? entry + 8 : u32(entry + 8);
    std::vector<std::uint32_t> v;
    for (std::size_t k = 0; k < count; ++k)
      v.push_back(size == 2 ? u16(at + 2 * k) : u32(at + 4 * k));
    return v;
  }
  std::size_t size() const { return bytes_.size(); }

 private:
  std::string path_;
  std::string bytes_;
  bool big_ = false;
};

}  // namespace

TextureVolume read_tiff_texture(const std::string& path, double voxel_size,
                                std::vector<Phase> phases) {
  const TiffFile f(path);
  std::size_t nx = 0, ny = 0, pages = 0;
  std::vector<std::uint8_t> labels;
  std::uint32_t ifd = f.u32(4);
  while (ifd != 0) {
    if (++pages > 65536) f.fail("more than 65536 pages (or a loop of pages)");
    const std::uint32_t entries = f.u16(ifd);
    std::uint32_t width = 0, length = 0, bits = 1, compression = 1, samples = 1, rows = 0;
    std::vector<std::uint32_t> offsets, counts;
    for (std::uint32_t e = 0; e < entries; ++e) {
      const std::size_t at = ifd + 2 + 12 * static_cast<std::size_t>(e);
      const std::uint32_t tag = f.u16(at);
      if (tag == 256) width = f.values(at).at(0);
      if (tag == 257) length = f.values(at).at(0);
      if (tag == 258) bits = f.values(at).at(0);
      if (tag == 259) compression = f.values(at).at(0);
      if (tag == 273) offsets = f.values(at);
      if (tag == 277) samples = f.values(at).at(0);
      if (tag == 278) rows = f.values(at).at(0);
      if (tag == 279) counts = f.values(at);
      if (tag == 322) f.fail("tiled pages are not read (save the stack in strips)");
    }
    const std::string page = "page " + std::to_string(pages) + ": ";
    if (width == 0 || length == 0) f.fail(page + "no ImageWidth/ImageLength");
    if (bits != 8 || samples != 1) f.fail(page + "only 8-bit single-channel images are read");
    if (compression != 1) f.fail(page + "compressed (only uncompressed TIFF is read)");
    if (pages == 1) {
      nx = width;
      ny = length;
    } else if (width != nx || length != ny) {
      f.fail(page + "size differs from the first page's");
    }
    if (rows == 0 || rows > length) rows = length;
    const std::size_t strips = (length + rows - 1) / rows;
    if (offsets.size() != strips || counts.size() != strips)
      f.fail(page + "strip offsets/byte counts do not match the rows per strip");
    std::size_t read = 0;
    for (std::size_t s = 0; s < strips; ++s) {
      const std::size_t rows_here = std::min<std::size_t>(rows, length - s * rows);
      if (counts[s] != rows_here * width) f.fail(page + "a strip has the wrong byte count");
      if (static_cast<std::size_t>(offsets[s]) + counts[s] > f.size())
        f.fail(page + "a strip lies beyond the end of the file");
      for (std::size_t b = 0; b < counts[s]; ++b)
        labels.push_back(static_cast<std::uint8_t>(f.u8(offsets[s] + b)));
      read += counts[s];
    }
    if (read != static_cast<std::size_t>(width) * length) f.fail(page + "pixel count mismatch");
    ifd = f.u32(ifd + 2 + 12 * static_cast<std::size_t>(entries));
  }
  for (std::uint8_t l : labels)
    if (l >= phases.size())
      f.fail("pixel value " + std::to_string(l) + " but only " + std::to_string(phases.size()) +
             " phases are defined");
  return TextureVolume(nx, ny, pages, voxel_size, std::move(labels), std::move(phases));
}

}  // namespace comminute::breakage::texture
