// Meshes as data and glTF 2.0 files: a cube written here byte by byte as a .glb (the format of
// the glTF 2.0 specification §4.4: 12-byte header, a JSON chunk, a BIN chunk) is read with its
// node's transform and material; hostile files — garbage, accessors beyond their buffer, a
// node cycle, a missing file — are one error, never a crash. Mesh validation, flat shading and
// the model matrix of a pose.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "ocean/bodies.hpp"
#include "ocean/objects.hpp"
#include "support/glb.hpp"

namespace {

namespace fs = std::filesystem;
using ocean::render::Mesh;
using ocean_test::cube_bin;
using ocean_test::cube_json;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ocean_gltf_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir / name;
}

TEST(Gltf, ReadsACubeWithItsTransformAndMaterial) {
  const auto meshes =
      ocean::render::load_gltf(ocean_test::write_glb(scratch("cube.glb"), cube_json(), cube_bin()));
  ASSERT_TRUE(meshes.ok()) << meshes.status().message();
  ASSERT_EQ(meshes.value().size(), 1u);
  const Mesh& m = meshes.value()[0];
  EXPECT_TRUE(ocean::render::validate(m).ok());
  EXPECT_EQ(m.indices.size(), 36u);
  // Scaled by 2 and moved up by 2: y in [1, 3], x and z in [-1, 1]; flat normals of the faces.
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_NEAR(std::abs(m.positions[i][0]), 1.0f, 1e-6f);
    EXPECT_NEAR(std::abs(m.positions[i][1] - 2.0f), 1.0f, 1e-6f);
    const auto& n = m.normals[i];
    EXPECT_NEAR(std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]), 1.0f, 1e-6f);
  }
  // Outward: every normal points away from the cube's centre (0, 2, 0).
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const auto& p = m.positions[m.indices[t]];
    const auto& n = m.normals[m.indices[t]];
    EXPECT_GT(n[0] * p[0] + n[1] * (p[1] - 2.0f) + n[2] * p[2], 0.0f);
  }
  EXPECT_NEAR(m.material.base_colour[1], 0.4, 1e-12);
  EXPECT_NEAR(m.material.metallic, 0.5, 1e-12);
  EXPECT_NEAR(m.material.roughness, 0.3, 1e-12);
}

TEST(Gltf, RefusesHostileFilesWithOneMessage) {
  const auto expect_invalid = [](const fs::path& path, const std::string& words) {
    const auto r = ocean::render::load_gltf(path);
    ASSERT_FALSE(r.ok()) << path;
    EXPECT_EQ(r.status().code(), ocean::ErrorCode::invalid_argument) << r.status().message();
    EXPECT_NE(r.status().message().find("cannot read '"), std::string::npos);
    EXPECT_NE(r.status().message().find(words), std::string::npos) << r.status().message();
    EXPECT_EQ(r.status().message().find('\n'), std::string::npos);
  };
  const fs::path garbage = scratch("garbage.glb");
  std::ofstream(garbage, std::ios::binary) << "glTF\x02\0\0\0 this is not a glTF file";
  expect_invalid(garbage, "");
  expect_invalid(ocean_test::write_glb(scratch("beyond.glb"), cube_json("900"), cube_bin()),
                 "outside its buffer");
  expect_invalid(
      ocean_test::write_glb(scratch("cycle.glb"),
                            cube_json("8", R"([{"mesh": 0, "children": [0]}])"), cube_bin()),
      "cycle");
  const auto missing = ocean::render::load_gltf(scratch("missing.glb"));
  EXPECT_EQ(missing.status().code(), ocean::ErrorCode::io_error);
}

// A .gltf whose buffer file is a FIFO nobody writes to, or a device: tinygltf would open the FIFO
// and wait for ever. Every file the loader reads goes through io::read_bounded, which refuses
// anything but a regular file before reading and stops at kMaxGltfFileBytes.
TEST(Gltf, BufferFilesThatAreNotRegularFilesAreRefused) {
  const fs::path dir = scratch("special").parent_path() / "special_buffers";
  fs::create_directories(dir);
  std::string json = cube_json();
  const std::string plain = R"("buffers": [{"byteLength": 168}])";
  ASSERT_NE(json.find(plain), std::string::npos);
  for (const char* name : {"pipe.bin", "zero.bin"}) {
    SCOPED_TRACE(name);
    const fs::path buffer = dir / name;
    fs::remove(buffer);
    if (std::string(name) == "pipe.bin") {
      ASSERT_EQ(::mkfifo(buffer.c_str(), 0600), 0);
    } else {
      fs::create_symlink("/dev/zero", buffer);
    }
    std::string text = json;
    text.replace(text.find(plain), plain.size(),
                 std::string(R"("buffers": [{"byteLength": 168, "uri": ")") + name + R"("}])");
    const fs::path gltf = dir / (std::string(name) + ".gltf");
    std::ofstream(gltf) << text;
    const auto r = ocean::render::load_gltf(gltf);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.status().message().find("not a regular file"), std::string::npos)
        << r.status().message();
    EXPECT_EQ(r.status().message().find('\n'), std::string::npos);
  }
  fs::remove_all(dir);
}

TEST(Meshes, ValidationFlatShadingAndModelMatrix) {
  Mesh m;
  EXPECT_FALSE(ocean::render::validate(m).ok());
  const auto box = ocean::bodies::box_hull({1.0, 2.0, 3.0}).value();
  m = ocean::render::flat_mesh(box.vertices, box.triangles, {});
  ASSERT_TRUE(ocean::render::validate(m).ok());
  EXPECT_EQ(m.positions.size(), 3 * box.triangles.size());
  Mesh bad = m;
  bad.indices.back() = 1u << 30;
  EXPECT_FALSE(ocean::render::validate(bad).ok());
  bad = m;
  bad.positions[0][0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(ocean::render::validate(bad).ok());
  bad = m;
  bad.material.roughness = -1.0;
  EXPECT_FALSE(ocean::render::validate(bad).ok());
  // The model matrix of a pose turns like bodies::rotate and moves by the position.
  const auto q = ocean::bodies::orientation_from_heading(40.0);
  const auto model = ocean::render::model_matrix({1.0, 2.0, 3.0}, q);
  const auto r = ocean::bodies::rotate(q, {0.3, -0.2, 0.7});
  for (int row = 0; row < 3; ++row) {
    const double v =
        model[0 + row] * 0.3 + model[4 + row] * -0.2 + model[8 + row] * 0.7 + model[12 + row];
    EXPECT_NEAR(v, r[static_cast<std::size_t>(row)] + 1.0 + row, 1e-12);
  }
}

}  // namespace
