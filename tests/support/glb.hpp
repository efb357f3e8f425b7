// A glTF 2.0 binary (.glb) written byte by byte, for tests: the format of the glTF 2.0
// specification §4.4 (12-byte header, a JSON chunk, a BIN chunk), and a unit cube in it.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace ocean_test {

inline void put32(std::string& s, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

// A .glb of `json` and `bin` (each padded to 4 bytes, JSON with spaces, BIN with zeros).
inline std::filesystem::path write_glb(const std::filesystem::path& path, std::string json,
                                       std::string bin) {
  while (json.size() % 4 != 0) json.push_back(' ');
  while (bin.size() % 4 != 0) bin.push_back('\0');
  std::string out = "glTF";
  put32(out, 2);
  put32(out, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  put32(out, static_cast<std::uint32_t>(json.size()));
  out += "JSON";
  out += json;
  put32(out, static_cast<std::uint32_t>(bin.size()));
  out += std::string("BIN\0", 4);
  out += bin;
  std::ofstream(path, std::ios::binary) << out;
  return path;
}

// A unit cube centred on its origin: 8 float positions, 36 uint16 indices (outward).
inline std::string cube_bin() {
  std::string bin;
  const auto put_float = [&](float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    put32(bin, u);
  };
  for (int i = 0; i < 8; ++i)
    for (int axis = 0; axis < 3; ++axis) put_float((i >> axis) & 1 ? 0.5f : -0.5f);
  const std::uint16_t faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},
                                      {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},
                                      {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for (const auto& f : faces)
    for (std::uint16_t i : f) {
      bin.push_back(static_cast<char>(i & 0xff));
      bin.push_back(static_cast<char>(i >> 8));
    }
  return bin;  // 96 + 72 bytes
}

inline std::string cube_json(const std::string& position_count = "8",
                             const std::string& nodes = R"([{"mesh": 0, "translation": [0, 2, 0],
                                                      "scale": [2, 2, 2]}])") {
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": )" +
         nodes + R"(,
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
    "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1.0],
                                           "metallicFactor": 0.5, "roughnessFactor": 0.3}}],
    "buffers": [{"byteLength": 168}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96},
                    {"buffer": 0, "byteOffset": 96, "byteLength": 72}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
         position_count + R"(, "type": "VEC3",
                   "min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]},
                  {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"}]})";
}

}  // namespace ocean_test
