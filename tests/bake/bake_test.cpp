// ocean::bake without the command-line tool: the files agree with the simulator bit for bit, the
// manifest lists them, the callback sees every frame and can stop the bake, and bad parameters
// write nothing.
#include "ocean/bake.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "ocean/backends.hpp"
#include "support/npy_reader.hpp"
#include "support/png_reader.hpp"

namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / (name + std::to_string(::getpid()))) {
    fs::remove_all(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

ocean::SimulationConfig small_config() {
  ocean::SimulationConfig c;
  c.resolution = 32;
  c.cascade_patch_sizes_m = {200, 47};
  c.seed = 5;
  return c;
}

TEST(BakeLibrary, FilesMatchTheSimulatorAndTheManifestListsThem) {
  TempDir dir("bake_lib_");
  const ocean::SimulationConfig c = small_config();
  long long calls = 0;
  const ocean::Status s = ocean::bake::bake(
      c, "cpu",
      {.output_dir = dir.path,
       .formats = {.npy = true, .png = true},
       .frame_count = 2,
       .fps = 10,
       .start_time_s = 0.5},
      [&](const ocean::bake::FrameDone& done) {
        EXPECT_EQ(done.index, calls);
        EXPECT_EQ(done.frame_count, 2);
        EXPECT_DOUBLE_EQ(done.time_s, 0.5 + 0.1 * static_cast<double>(done.index));
        EXPECT_NE(done.frame, nullptr);
        ++calls;
        return ocean::Status::ok_status();
      });
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(calls, 2);

  auto sim = ocean::make_simulator(c).value();
  sim->step(0.5);
  sim->step(0.6);
  const ocean::CascadeFrame& expected = sim->frame().cascades[1];
  const auto d = ocean::io::read_npy(dir.path / "displacement_c1_f00001.npy");
  ASSERT_TRUE(d.ok()) << d.status().message();
  ASSERT_EQ(d.value().data.size(), expected.displacement.size());
  EXPECT_EQ(std::memcmp(d.value().data.data(), expected.displacement.data(),
                        expected.displacement.size() * sizeof(float)),
            0);
  const auto png = ocean::io::read_png(dir.path / "height_c0_f00000.png");
  ASSERT_TRUE(png.ok()) << png.status().message();
  EXPECT_EQ(png.value().bit_depth, 16);

  std::ifstream in(dir.path / "manifest.json");
  const nlohmann::json manifest = nlohmann::json::parse(in);
  EXPECT_EQ(manifest["generator"], "ocean bake");
  EXPECT_EQ(manifest["backend"], "cpu");
  EXPECT_EQ(manifest["formats"], nlohmann::json({"npy", "png"}));
  ASSERT_EQ(manifest["frames"].size(), 2u);
  for (const auto& name : manifest["frames"][1]["files"]) {
    EXPECT_TRUE(fs::exists(dir.path / name.get<std::string>())) << name;
  }
  EXPECT_DOUBLE_EQ(manifest["height_png_range_m"].get<double>(),
                   ocean::bake::height_png_range_m(c));
}

TEST(BakeLibrary, SimulatorOverloadRecordsItsBackend) {
  TempDir dir("bake_lib_sim_");
  auto sim = ocean::make_simulator(small_config()).value();
  ASSERT_TRUE(ocean::bake::bake(*sim, {.output_dir = dir.path}).ok());
  EXPECT_TRUE(fs::exists(dir.path / "displacement_c0_f00000.npy"));
  std::ifstream in(dir.path / "manifest.json");
  EXPECT_EQ(nlohmann::json::parse(in)["backend"], std::string(sim->backend().name()));
}

TEST(BakeLibrary, CallbackErrorStopsTheBakeWithoutAManifest) {
  TempDir dir("bake_lib_stop_");
  const ocean::Status s = ocean::bake::bake(
      small_config(), "cpu", {.output_dir = dir.path, .frame_count = 3},
      [](const ocean::bake::FrameDone& done) {
        return done.index == 1 ? ocean::io_error("stop here") : ocean::Status::ok_status();
      });
  EXPECT_EQ(s.message(), "stop here");
  EXPECT_TRUE(fs::exists(dir.path / "foam_c0_f00001.npy"));
  EXPECT_FALSE(fs::exists(dir.path / "foam_c0_f00002.npy"));
  EXPECT_FALSE(fs::exists(dir.path / "manifest.json"));
}

TEST(BakeLibrary, BadParametersWriteNothing) {
  TempDir dir("bake_lib_bad_");
  const ocean::SimulationConfig c = small_config();
  const auto code = [&](const ocean::bake::BakeParams& p) {
    return ocean::bake::bake(c, "cpu", p).code();
  };
  using ocean::ErrorCode;
  EXPECT_EQ(code({}), ErrorCode::invalid_argument);
  EXPECT_EQ(code({.output_dir = dir.path, .formats = {.npy = false}}), ErrorCode::invalid_argument);
  EXPECT_EQ(code({.output_dir = dir.path, .frame_count = 0}), ErrorCode::invalid_argument);
  EXPECT_EQ(code({.output_dir = dir.path, .frame_count = ocean::bake::kMaxFrames + 1}),
            ErrorCode::invalid_argument);
  EXPECT_EQ(code({.output_dir = dir.path, .fps = 0}), ErrorCode::invalid_argument);
  EXPECT_EQ(code({.output_dir = dir.path, .start_time_s = std::nan("")}),
            ErrorCode::invalid_argument);
  EXPECT_FALSE(fs::exists(dir.path));
}

TEST(BakeLibrary, LoopFrameCountIsPeriodTimesFps) {
  ocean::SimulationConfig c = small_config();
  c.loop_period_s = 0;
  EXPECT_EQ(ocean::bake::loop_frame_count(c, 30), 0);
  c.loop_period_s = 2.5;
  EXPECT_EQ(ocean::bake::loop_frame_count(c, 30), 75);
}

}  // namespace
