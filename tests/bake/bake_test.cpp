// ocean::bake without the command-line tool: the files agree with the simulator bit for bit, the
// manifest lists them and says whether the bake completed, the callback sees every frame and can
// stop the bake, a cancellation stops it between files, a failed write leaves no half frame, a
// failed or cancelled start leaves everything as it was, the folder lock, and bad parameters
// write nothing.
#include "ocean/bake.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "ocean/backends.hpp"
#include "ocean/waves.hpp"
#include "support/npy_reader.hpp"
#include "support/png_reader.hpp"
#include "support/temp_dir.hpp"

namespace {

namespace fs = std::filesystem;

using ocean_test::TempDir;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

nlohmann::json read_manifest(const fs::path& dir) {
  std::ifstream in(dir / "manifest.json");
  return nlohmann::json::parse(in, nullptr, false);
}

std::size_t entries_with(const fs::path& dir, const std::string& part) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    n += e.path().filename().string().find(part) != std::string::npos;
  return n;
}

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

  const nlohmann::json manifest = read_manifest(dir.path);
  EXPECT_EQ(manifest["generator"], "ocean bake");
  EXPECT_EQ(manifest["complete"], true);
  EXPECT_EQ(manifest["frame_count"], 2);
  EXPECT_EQ(manifest["frames_written"], 2);
  EXPECT_FALSE(manifest.contains("stopped"));
  EXPECT_EQ(entries_with(dir.path, ".ocean-bake.lock"), 0u);
  EXPECT_EQ(manifest["backend"], "cpu");
  EXPECT_EQ(manifest["formats"], nlohmann::json({"npy", "png"}));
  ASSERT_EQ(manifest["frames"].size(), 2u);
  for (const auto& name : manifest["frames"][1]["files"]) {
    EXPECT_TRUE(fs::exists(dir.path / name.get<std::string>())) << name;
  }
  EXPECT_DOUBLE_EQ(manifest["height_png_range_m"].get<double>(),
                   ocean::bake::height_png_range_m(ocean::SimulationPlan::make(c).value()));
}

// With a local layer the bake writes the composited local surface (Frame::local, M.7.9) of each
// frame: read back, it is bit for bit that of a simulator carrying the same layer stepped through
// the same times (the foam accumulated over the frames before), and the wake does foam.
TEST(BakeLibrary, WritesTheCompositedLocalSurface) {
  TempDir dir("bake_lib_local_");
  ocean::SimulationConfig c = small_config();
  c.foam.source = ocean::FoamSource::ramp;  // foam where the wake folds the surface
  ocean::waves::LayerParams lp;
  lp.area = {.origin_m = {-40.0, -40.0}, .size_m = 80.0, .resolution = 32};
  lp.wakes.push_back({.x_m = 20.0,
                      .heading_deg = 180.0,
                      .speed_mps = 4.0,
                      .hull_length_m = 10.0,
                      .peak_height_m = 1.5});
  auto made = ocean::waves::LocalLayer::make(lp);
  ASSERT_TRUE(made.ok()) << made.status().message();
  const std::shared_ptr<const ocean::waves::LocalLayer> layer = std::move(made).value();
  ASSERT_TRUE(ocean::bake::bake(c, "cpu",
                                {.output_dir = dir.path,
                                 .frame_count = 3,
                                 .fps = 10,
                                 .start_time_s = 1.0,
                                 .local_layer = layer})
                  .ok());
  auto sim = ocean::make_simulator(c).value();
  sim->set_local_layer(layer);
  for (const double t : {1.0, 1.1, 1.2}) sim->step(t);
  const ocean::LocalSurfaceFrame& expected = sim->frame().local;
  const std::size_t cells = 32 * 32;
  const struct {
    const char* name;
    const std::vector<float>& values;
    std::size_t per_cell;
  } files[] = {{"local_displacement_f00002.npy", expected.displacement, 3},
               {"local_normal_f00002.npy", expected.normal, 3},
               {"local_jacobian_f00002.npy", expected.jacobian, 1},
               {"local_foam_f00002.npy", expected.foam, 1}};
  for (const auto& f : files) {
    const auto read = ocean::io::read_npy(dir.path / f.name);
    ASSERT_TRUE(read.ok()) << read.status().message();
    ASSERT_EQ(read.value().data.size(), f.per_cell * cells) << f.name;
    EXPECT_EQ(read.value().shape[0], 32u);
    EXPECT_EQ(std::memcmp(read.value().data.data(), f.values.data(), f.values.size() * 4), 0)
        << f.name;
  }
  float most_foam = 0.0f;
  for (const float v : expected.foam) most_foam = std::max(most_foam, v);
  EXPECT_GT(most_foam, 0.5f);  // the wake folds the sum somewhere
  const nlohmann::json manifest = read_manifest(dir.path);
  for (const auto& f : files) {
    const auto& names = manifest["frames"][2]["files"];
    EXPECT_NE(std::find(names.begin(), names.end(), f.name), names.end()) << f.name;
  }
}

TEST(BakeLibrary, SimulatorOverloadRecordsItsBackend) {
  TempDir dir("bake_lib_sim_");
  auto sim = ocean::make_simulator(small_config()).value();
  ASSERT_TRUE(ocean::bake::bake(*sim, {.output_dir = dir.path}).ok());
  EXPECT_TRUE(fs::exists(dir.path / "displacement_c0_f00000.npy"));
  std::ifstream in(dir.path / "manifest.json");
  EXPECT_EQ(nlohmann::json::parse(in)["backend"], std::string(sim->backend().name()));
}

TEST(BakeLibrary, CallbackErrorStopsTheBakeWithAnIncompleteManifest) {
  TempDir dir("bake_lib_stop_");
  const ocean::Status s = ocean::bake::bake(
      small_config(), "cpu", {.output_dir = dir.path, .frame_count = 3},
      [](const ocean::bake::FrameDone& done) {
        return done.index == 1 ? ocean::io_error("stop here") : ocean::Status::ok_status();
      });
  EXPECT_EQ(s.message(), "stop here");
  EXPECT_TRUE(fs::exists(dir.path / "foam_c0_f00001.npy"));
  EXPECT_FALSE(fs::exists(dir.path / "foam_c0_f00002.npy"));
  const nlohmann::json m = read_manifest(dir.path);
  EXPECT_EQ(m["complete"], false);
  EXPECT_EQ(m["frames_written"], 2);
  EXPECT_EQ(m["frames"].size(), 2u);
  EXPECT_EQ(m["stopped"], "stop here");
  EXPECT_EQ(entries_with(dir.path, ".tmp-"), 0u);
  EXPECT_FALSE(fs::exists(dir.path / ocean::bake::kLockFileName));
}

TEST(BakeLibrary, CancellationStopsBeforeTheNextFile) {
  TempDir dir("bake_lib_cancel_");
  std::atomic<bool> cancel{false};
  const ocean::Status s = ocean::bake::bake(
      small_config(), "cpu", {.output_dir = dir.path, .frame_count = 5, .cancel = &cancel},
      [&](const ocean::bake::FrameDone& done) {
        if (done.index == 1) cancel = true;
        return ocean::Status::ok_status();
      });
  EXPECT_EQ(s.code(), ocean::ErrorCode::cancelled);
  EXPECT_NE(s.message().find("cancelled after 2 of 5 frames"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("\"complete\": false"), std::string::npos) << s.message();
  EXPECT_TRUE(fs::exists(dir.path / "foam_c1_f00001.npy"));
  EXPECT_FALSE(fs::exists(dir.path / "displacement_c0_f00002.npy"));
  const nlohmann::json m = read_manifest(dir.path);
  EXPECT_EQ(m["complete"], false);
  EXPECT_EQ(m["frame_count"], 5);
  EXPECT_EQ(m["frames_written"], 2);
  EXPECT_EQ(m["stopped"], "cancelled");
  EXPECT_EQ(entries_with(dir.path, ".tmp-"), 0u);
  EXPECT_FALSE(fs::exists(dir.path / ocean::bake::kLockFileName));
}

TEST(BakeLibrary, AFailedWriteRemovesTheUnfinishedFrame) {
  TempDir dir("bake_lib_fail_");
  // A folder where frame 1's third file goes: its rename fails after two files of frame 1.
  fs::create_directories(dir.path / "jacobian_c0_f00001.npy" / "x");
  const ocean::Status s =
      ocean::bake::bake(small_config(), "cpu", {.output_dir = dir.path, .frame_count = 3});
  EXPECT_EQ(s.code(), ocean::ErrorCode::io_error);
  EXPECT_NE(s.message().find("jacobian_c0_f00001.npy"), std::string::npos) << s.message();
  EXPECT_FALSE(fs::exists(dir.path / "displacement_c0_f00001.npy"));
  EXPECT_FALSE(fs::exists(dir.path / "normal_c0_f00001.npy"));
  EXPECT_TRUE(fs::exists(dir.path / "nfs_c1_f00000_mip5.npy"));
  const nlohmann::json m = read_manifest(dir.path);
  EXPECT_EQ(m["complete"], false);
  EXPECT_EQ(m["frames_written"], 1);
  EXPECT_EQ(m["stopped"], s.message());
  EXPECT_EQ(entries_with(dir.path, ".tmp-"), 0u);
}

TEST(BakeLibrary, AStartThatFailsOrIsCancelledLeavesEverythingAsItWas) {
  TempDir dir("bake_lib_start_");
  const ocean::SimulationConfig c = small_config();
  const fs::path old = dir.path / "old";
  ASSERT_TRUE(ocean::bake::bake(c, "cpu", {.output_dir = old}).ok());
  const std::string old_manifest = read_text(old / "manifest.json");
  std::atomic<bool> cancel{true};
  const fs::path fresh = dir.path / "a" / "b";
  EXPECT_EQ(ocean::bake::bake(c, "cpu", {.output_dir = fresh, .cancel = &cancel}).code(),
            ocean::ErrorCode::cancelled);
  EXPECT_EQ(ocean::bake::bake(c, "cpu", {.output_dir = old, .cancel = &cancel}).code(),
            ocean::ErrorCode::cancelled);
  EXPECT_EQ(ocean::bake::bake(c, "no-such-backend", {.output_dir = fresh}).code(),
            ocean::ErrorCode::invalid_argument);
  const ocean::Status sheet =
      ocean::bake::bake(c, "cpu", {.output_dir = fresh, .other_outputs = {dir.path}});
  EXPECT_NE(sheet.message().find("is a directory"), std::string::npos) << sheet.message();
  EXPECT_FALSE(fs::exists(dir.path / "a"));
  EXPECT_EQ(read_text(old / "manifest.json"), old_manifest);
  EXPECT_FALSE(fs::exists(old / ocean::bake::kLockFileName));
  // A folder named manifest.json cannot be removed: the start fails before any frame file.
  fs::create_directories(dir.path / "m" / "manifest.json" / "x");
  const ocean::Status m = ocean::bake::bake(c, "cpu", {.output_dir = dir.path / "m"});
  EXPECT_NE(m.message().find("cannot remove the old manifest"), std::string::npos) << m.message();
  EXPECT_FALSE(fs::exists(dir.path / "m" / "displacement_c0_f00000.npy"));
}

TEST(BakeLibrary, ALockedFolderFailsAtOnceNamingTheHolderAndAStaleLockDoesNot) {
  TempDir dir("bake_lib_lock_");
  fs::create_directories(dir.path);
  const fs::path lock = dir.path / ocean::bake::kLockFileName;
  const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const std::string pid = std::to_string(::getpid());
  ASSERT_EQ(::write(fd, pid.data(), pid.size()), static_cast<ssize_t>(pid.size()));
  const ocean::Status busy = ocean::bake::bake(small_config(), "cpu", {.output_dir = dir.path});
  EXPECT_EQ(busy.code(), ocean::ErrorCode::io_error);
  EXPECT_NE(busy.message().find("is being baked by process " + pid), std::string::npos)
      << busy.message();
  EXPECT_FALSE(fs::exists(dir.path / "displacement_c0_f00000.npy"));
  // Unlocked, as the kernel leaves it when its holder dies: it blocks nothing and is removed.
  ASSERT_EQ(::close(fd), 0);
  const ocean::Status s = ocean::bake::bake(small_config(), "cpu", {.output_dir = dir.path});
  EXPECT_TRUE(s.ok()) << s.message();
  EXPECT_FALSE(fs::exists(lock));
  EXPECT_EQ(read_manifest(dir.path)["complete"], true);
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
