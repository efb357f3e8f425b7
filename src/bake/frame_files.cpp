// src/bake/frame_files.cpp — one cascade's maps as .npy, OpenEXR and PNG files, and its packed
// normal/foam/smoothness mip chain, one image per level.
#include "frame_files.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>

#include "ocean/io.hpp"

namespace ocean::bake::detail {

Status write_cascade_files(const CascadeFrame& c, const std::string& stem,
                           const std::filesystem::path& dir, const Formats& formats,
                           double height_range_m, const std::atomic<bool>* cancel,
                           std::vector<std::string>& names) {
  const int n = c.resolution;
  const auto un = static_cast<std::size_t>(n);
  const auto texels = un * un;
  // One file, through `write(path)`, unless the bake was cancelled; named once written, so that
  // `names` holds exactly the files on disk.
  const auto put = [&](const std::string& name, const auto& write) -> Status {
    if (cancel != nullptr && cancel->load(std::memory_order_relaxed))
      return {ErrorCode::cancelled, "cancelled"};
    Status s = write(dir / name);
    if (s.ok()) names.push_back(name);
    return s;
  };
  const auto npy = [&](const std::string& name, const float* data,
                       std::span<const std::size_t> shape) {
    return put(name, [&](const std::filesystem::path& p) { return io::write_npy(p, data, shape); });
  };
  const auto exr = [&](const std::string& name, int size, std::span<const io::ExrChannel> channels,
                       io::ExrPixelType type) {
    return put(name, [&](const std::filesystem::path& p) {
      return io::write_exr(p, size, size, channels, type);
    });
  };
  if (formats.npy) {
    const std::size_t vec3[] = {un, un, 3}, scalar[] = {un, un};
    if (Status s = npy("displacement_" + stem + ".npy", c.displacement.data(), vec3); !s.ok())
      return s;
    if (Status s = npy("normal_" + stem + ".npy", c.normal.data(), vec3); !s.ok()) return s;
    if (Status s = npy("jacobian_" + stem + ".npy", c.jacobian.data(), scalar); !s.ok()) return s;
    if (Status s = npy("foam_" + stem + ".npy", c.foam.data(), scalar); !s.ok()) return s;
  }
  if (formats.exr) {
    std::vector<float> planes(6 * texels);
    for (std::size_t i = 0; i < texels; ++i) {
      for (std::size_t k = 0; k < 3; ++k) {
        planes[k * texels + i] = c.displacement[3 * i + k];
        planes[(3 + k) * texels + i] = c.normal[3 * i + k];
      }
    }
    const io::ExrChannel displacement[] = {
        {"R", planes.data()}, {"G", planes.data() + texels}, {"B", planes.data() + 2 * texels}};
    if (Status s = exr("displacement_" + stem + ".exr", n, displacement, io::ExrPixelType::float32);
        !s.ok()) {
      return s;
    }
    const io::ExrChannel maps[] = {{"normal.X", planes.data() + 3 * texels},
                                   {"normal.Y", planes.data() + 4 * texels},
                                   {"normal.Z", planes.data() + 5 * texels},
                                   {"jacobian", c.jacobian.data()},
                                   {"foam", c.foam.data()}};
    if (Status s = exr("maps_" + stem + ".exr", n, maps, io::ExrPixelType::half); !s.ok()) return s;
  }
  // The packed normal/foam/smoothness chain, one image per mip level.
  const int levels = std::countr_zero(static_cast<unsigned>(n));
  for (int level = 0; level <= levels; ++level) {
    const int size = n >> level;
    const auto count = static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
    const std::uint32_t* packed = c.packed_mips.data() + mip_offset(n, level);
    const std::string name = "nfs_" + stem + "_mip" + std::to_string(level);
    std::vector<std::uint8_t> rgba(4 * count);
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t k = 0; k < 4; ++k)
        rgba[4 * i + k] = static_cast<std::uint8_t>(packed[i] >> (8 * k));
    }
    if (formats.png) {
      if (Status s = put(name + ".png",
                         [&](const std::filesystem::path& p) {
                           return io::write_png8(p, size, size, 4, rgba.data());
                         });
          !s.ok())
        return s;
    }
    if (formats.exr || formats.npy) {
      std::vector<float> values(4 * count);
      for (std::size_t i = 0; i < 4 * count; ++i) values[i] = rgba[i] / 255.0f;
      if (formats.npy) {
        const std::size_t shape[] = {static_cast<std::size_t>(size), static_cast<std::size_t>(size),
                                     4};
        if (Status s = npy(name + ".npy", values.data(), shape); !s.ok()) return s;
      }
      if (formats.exr) {
        std::vector<float> planar(4 * count);
        for (std::size_t i = 0; i < count; ++i) {
          for (std::size_t k = 0; k < 4; ++k) planar[k * count + i] = values[4 * i + k];
        }
        const io::ExrChannel ch[] = {{"R", planar.data()},
                                     {"G", planar.data() + count},
                                     {"B", planar.data() + 2 * count},
                                     {"A", planar.data() + 3 * count}};
        if (Status s = exr(name + ".exr", size, ch, io::ExrPixelType::half); !s.ok()) return s;
      }
    }
  }
  if (formats.png) {
    std::vector<std::uint16_t> height(texels);
    for (std::size_t i = 0; i < texels; ++i) {
      const double t = 0.5 + 0.5 * c.displacement[3 * i + 1] / height_range_m;
      height[i] = static_cast<std::uint16_t>(std::lround(std::clamp(t, 0.0, 1.0) * 65535.0));
    }
    if (Status s = put("height_" + stem + ".png",
                       [&](const std::filesystem::path& p) {
                         return io::write_png16_gray(p, n, n, height.data());
                       });
        !s.ok())
      return s;
  }
  return {};
}

}  // namespace ocean::bake::detail
