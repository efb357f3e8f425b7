// The OpenEXR header walk of read_exr (see exr_header.hpp).
//
// This work is based on: [OpenEXR File Layout] (docs/references.md): the magic number, a
// version word whose bit 12 marks a multi-part file, then per part a list of attributes
// "name\0type\0", an int32 size (little-endian) and the value, ended by an empty name; a
// multi-part file ends its list of headers with an empty header. Which types OpenEXR 3.1 reads by
// their declared size and which by their content follows its Header::readFrom and the
// attributes' readValueFrom.
#include "exr_header.hpp"

#include <array>
#include <cstdint>
#include <optional>

#include "ocean/core.hpp"

namespace ocean::io {
namespace {

// Known types OpenEXR reads as a fixed number of bytes whatever the declared size says.
struct FixedType {
  std::string_view name;
  std::int32_t size;
};
constexpr std::array<FixedType, 24> kFixedTypes{{
    {"box2i", 16},      {"box2f", 16},
    {"compression", 1}, {"lineOrder", 1},
    {"envmap", 1},      {"deepImageState", 1},
    {"float", 4},       {"int", 4},
    {"double", 8},      {"rational", 8},
    {"timecode", 8},    {"v2i", 8},
    {"v2f", 8},         {"v2d", 16},
    {"v3i", 12},        {"v3f", 12},
    {"v3d", 24},        {"m33f", 36},
    {"m33d", 72},       {"m44f", 64},
    {"m44d", 128},      {"chromaticities", 32},
    {"keycode", 28},    {"tiledesc", 9},
}};
// OpenEXR reads names of at most 255 bytes.
constexpr std::size_t kMaxName = 255;
// A channel list entry after its name: pixel type, pLinear, 3 reserved bytes, x and y sampling.
constexpr std::size_t kChannelFields = 16;

class Walk {
 public:
  explicit Walk(std::string_view bytes) : bytes_(bytes) {}

  ExrHeaderInfo check() {
    if (bytes_.size() < 8 || bytes_.substr(0, 4) != std::string_view("\x76\x2f\x31\x01", 4)) {
      info_.problem = "not an OpenEXR file (wrong magic)";
      return info_;
    }
    const bool multi_part = (int32_at(4) & 0x1000) != 0;
    pos_ = 8;
    do {
      info_.problem = header();
      first_part_ = false;
    } while (info_.problem.empty() && multi_part && pos_ < bytes_.size() && bytes_[pos_] != '\0');
    return info_;
  }

 private:
  // One part's attributes, up to and including the empty name that ends them.
  std::string header() {
    while (true) {
      const std::optional<std::string_view> name = text();
      if (!name) return "truncated header";
      if (name->empty()) return {};
      const std::optional<std::string_view> type = text();
      if (!type || bytes_.size() - pos_ < 4) return "truncated header";
      const std::int32_t size = int32_at(pos_);
      pos_ += 4;
      const std::string what = "header attribute '" + excerpt(*name) + "'";
      if (size < 0 || static_cast<std::size_t>(size) > bytes_.size() - pos_)
        return what + " declares " + std::to_string(size) + " bytes, more than the file holds";
      if (std::string p = value(what, *type, size); !p.empty()) return p;
      if (first_part_) note(*name, *type);
      pos_ += static_cast<std::size_t>(size);
    }
  }

  // Keeps the first part's image size from its attribute at the cursor (size already checked).
  void note(std::string_view name, std::string_view type) {
    if (name == "dataWindow" && type == "box2i") {
      info_.width = std::int64_t{int32_at(pos_ + 8)} - int32_at(pos_) + 1;
      info_.height = std::int64_t{int32_at(pos_ + 12)} - int32_at(pos_ + 4) + 1;
    } else if (name == "tiles" && type == "tiledesc") {  // uint32 x size, y size, mode byte
      info_.tile_width = static_cast<std::uint32_t>(int32_at(pos_));
      info_.tile_height = static_cast<std::uint32_t>(int32_at(pos_ + 4));
    } else if (name == "channels" && type == "chlist") {
      info_.channels = 0;
      for (std::size_t at = pos_; bytes_[at] != '\0';
           at = bytes_.find('\0', at) + 1 + kChannelFields)
        ++info_.channels;
    }
  }

  // Whether OpenEXR reads the value as exactly `size` bytes.
  std::string value(const std::string& what, std::string_view type, std::int32_t size) const {
    const auto wrong_size = [&](std::int32_t expected) {
      return what + " of type '" + excerpt(type) + "' declares " + std::to_string(size) +
             " bytes, not " + std::to_string(expected);
    };
    for (const FixedType& fixed : kFixedTypes) {
      if (type == fixed.name) return size == fixed.size ? std::string() : wrong_size(fixed.size);
    }
    if (type == "floatvector" && size % 4 != 0) return wrong_size(size - size % 4);
    if (type == "chlist") {
      const std::int32_t used = channel_list_size(static_cast<std::size_t>(size));
      if (used != size) return wrong_size(used);
    }
    // string, stringvector, preview, idmanifest (whose contents OpenEXR checks against the size),
    // floatvector, or a type OpenEXR keeps opaque: read as exactly size bytes.
    return {};
  }

  // The bytes a channel list at the cursor takes as OpenEXR reads it (entries up to an empty
  // name), or -1 when it does not end within `size` bytes.
  [[nodiscard]] std::int32_t channel_list_size(std::size_t size) const {
    const std::string_view list = bytes_.substr(pos_, size);
    std::size_t at = 0;
    while (at < list.size()) {
      const std::size_t end = list.find('\0', at);
      if (end == std::string_view::npos || end - at > kMaxName) return -1;
      if (end == at) return static_cast<std::int32_t>(end + 1);
      at = end + 1 + kChannelFields;
    }
    return -1;
  }

  // A NUL-terminated name at the cursor of at most kMaxName bytes, the cursor moved past it.
  std::optional<std::string_view> text() {
    const std::size_t end = bytes_.find('\0', pos_);
    if (end == std::string_view::npos || end - pos_ > kMaxName) return std::nullopt;
    const std::string_view s = bytes_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return s;
  }

  [[nodiscard]] std::int32_t int32_at(std::size_t at) const {
    std::uint32_t u = 0;
    for (std::size_t i = 0; i < 4; ++i)
      u |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes_[at + i])) << (8 * i);
    return static_cast<std::int32_t>(u);
  }

  std::string_view bytes_;
  std::size_t pos_ = 0;
  bool first_part_ = true;
  ExrHeaderInfo info_;
};

}  // namespace

ExrHeaderInfo check_exr_header(std::string_view bytes) { return Walk(bytes).check(); }

}  // namespace ocean::io
