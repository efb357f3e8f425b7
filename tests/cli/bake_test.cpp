// `ocean bake`: files agree with the simulator bit for bit, loops have T·fps frames, every
// format reads back, the contact sheet has its tiles and labels, and bad input leaves nothing
// behind.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/cli_run.hpp"
#include "ocean/backends.hpp"
#include "support/exr_reader.hpp"
#include "support/npy_reader.hpp"
#include "support/png_reader.hpp"

namespace {

using ocean_test::line_count;

namespace fs = std::filesystem;

int bake_run(const std::string& args, std::string* err = nullptr) {
  const ocean_test::CliRun r = ocean_test::run_cli("bake " + args);
  if (err != nullptr) *err = r.err;
  return r.exit_code;
}

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / (name + std::to_string(::getpid()))) {
    fs::remove_all(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

TEST(Bake, NpyMatchesTheSimulatorBitForBit) {
  TempDir dir("bake_npy_");
  const std::string flags =
      "--wind-speed 12 --fetch 40000 --resolution 32 --cascades 200,47 --seed 3 --choppiness 0.7";
  ASSERT_EQ(bake_run(flags + " --out " + dir.path.string() + " --frames 2 --fps 10 --time 1.5"), 0);
  ocean::SimulationConfig c;
  c.sea.wind_sea.spectrum = {
      .model = ocean::SpectrumModel::jonswap, .wind_speed_mps = 12, .fetch_m = 4e4};
  c.resolution = 32;
  c.cascade_patch_sizes_m = {200, 47};
  c.seed = 3;
  c.choppiness = 0.7;
  auto sim = ocean::make_simulator(c).value();
  sim->step(1.5);
  sim->step(1.6);  // frame 1 at 1.5 + 1/10 s, foam accumulated over 0.1 s
  for (int k = 0; k < 2; ++k) {
    const auto& expected = sim->frame().cascades[static_cast<std::size_t>(k)];
    const std::string stem = "c" + std::to_string(k) + "_f00001";
    const auto d = ocean::io::read_npy(dir.path / ("displacement_" + stem + ".npy"));
    ASSERT_TRUE(d.ok()) << d.status().message();
    EXPECT_EQ(d.value().shape, (std::vector<std::size_t>{32, 32, 3}));
    EXPECT_EQ(std::memcmp(d.value().data.data(), expected.displacement.data(),
                          expected.displacement.size() * 4),
              0);
    const auto foam = ocean::io::read_npy(dir.path / ("foam_" + stem + ".npy")).value();
    EXPECT_TRUE(
        std::equal(foam.data.begin(), foam.data.end(), expected.foam.begin(), expected.foam.end()));
    const auto mip5 = ocean::io::read_npy(dir.path / ("nfs_" + stem + "_mip5.npy")).value();
    EXPECT_EQ(mip5.shape, (std::vector<std::size_t>{1, 1, 4}));
  }
  std::ifstream manifest(dir.path / "manifest.json");
  const auto m = nlohmann::json::parse(manifest);
  EXPECT_EQ(m["frames"].size(), 2u);
  EXPECT_DOUBLE_EQ(m["frames"][1]["time_s"].get<double>(), 1.6);
  EXPECT_EQ(m["config"]["cascades_m"].size(), 2u);
}

TEST(Bake, LoopWritesOnePeriodAndEveryFormatReadsBack) {
  TempDir dir("bake_loop_");
  ASSERT_EQ(
      bake_run("--resolution 16 --cascades 50 --loop-period 6 --loop --fps 1 --format png --format exr "
          "--out " +
          dir.path.string()),
      0);
  std::ifstream manifest(dir.path / "manifest.json");
  EXPECT_EQ(nlohmann::json::parse(manifest)["frames"].size(), 6u);
  const auto png = ocean::io::read_png(dir.path / "nfs_c0_f00005_mip1.png");
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.value().width, 8);
  EXPECT_EQ(png.value().channels, 4);
  const auto height = ocean::io::read_png(dir.path / "height_c0_f00000.png").value();
  EXPECT_EQ(height.bit_depth, 16);
  const auto exr = ocean::io::read_exr(dir.path / "maps_c0_f00003.exr");
  ASSERT_TRUE(exr.ok());
  EXPECT_EQ(exr.value().channel_names.size(), 5u);
  EXPECT_TRUE(ocean::io::read_exr(dir.path / "displacement_c0_f00002.exr").ok());
}

TEST(Bake, ContactSheetShowsEachCascadesMapsUnderLabels) {
  TempDir dir("bake_sheet_");
  const fs::path sheet = dir.path / "sheet.png";
  ASSERT_EQ(bake_run("--resolution 64 --cascades 100,30 --out " + (dir.path / "maps").string() +
                " --contact-sheet " + sheet.string()),
            0);
  const auto png = ocean::io::read_png(sheet);
  ASSERT_TRUE(png.ok()) << png.status().message();
  const auto& im = png.value();
  // Four 300 px tiles a row with 16 px margins; a 54 px title band; per cascade a 26 px label
  // band, the tile and a margin.
  EXPECT_EQ(im.width, 16 + 4 * (300 + 16));
  EXPECT_EQ(im.height, 54 + 2 * (26 + 300 + 16));
  ASSERT_EQ(im.channels, 3);
  const auto dark_in_rows = [&](int y0, int y1) {
    int n = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = 0; x < im.width; ++x) {
        const std::size_t i = (static_cast<std::size_t>(y) * im.width + x) * 3;
        n += im.samples[i] < 100 && im.samples[i + 1] < 100 && im.samples[i + 2] < 100;
      }
    }
    return n;
  };
  EXPECT_GT(dark_in_rows(0, 54), 200);   // the title
  EXPECT_GT(dark_in_rows(54, 80), 200);  // the first row's labels
  // An unwritable sheet: exit 1 with one line, nothing left at that path.
  std::string err;
  const fs::path missing = dir.path / "missing" / "sheet.png";
  EXPECT_EQ(bake_run("--resolution 16 --cascades 50 --out " + (dir.path / "maps2").string() +
                    " --contact-sheet " + missing.string(),
                &err),
            1);
  EXPECT_NE(err.find("cannot write"), std::string::npos) << err;
  EXPECT_EQ(line_count(err), 1) << err;
  EXPECT_FALSE(fs::exists(missing.parent_path()));
  EXPECT_FALSE(fs::exists(dir.path / "maps2"));  // checked before the first frame
}

TEST(Bake, PresetAndOverrides) {
  TempDir dir("bake_preset_");
  fs::create_directories(dir.path);
  const fs::path preset = dir.path / "p.json";
  std::ofstream(preset)
      << R"({"resolution": 16, "cascades_m": [40.0], "sea": {"wind_sea": {"wind_speed_mps": 7}}})";
  ASSERT_EQ(bake_run("--preset " + preset.string() +
                " --set choppiness=0.5 --set normals=analytic --out " + (dir.path / "o").string()),
            0);
  std::ifstream manifest(dir.path / "o" / "manifest.json");
  const auto m = nlohmann::json::parse(manifest);
  EXPECT_EQ(m["config"]["resolution"], 16);
  EXPECT_EQ(m["config"]["choppiness"], 0.5);
  EXPECT_EQ(m["config"]["normals"], "analytic");
  EXPECT_EQ(m["config"]["sea"]["wind_sea"]["wind_speed_mps"], 7.0);
}

TEST(Bake, BadInputFailsCleanly) {
  TempDir dir("bake_bad_");
  fs::create_directories(dir.path);
  const fs::path bad_key = dir.path / "bad_key.json", bad_type = dir.path / "bad_type.json",
                 bad_json = dir.path / "bad.json";
  std::ofstream(bad_key) << R"({"sea": {"wind_sea": {"windspeed": 7}}})";
  std::ofstream(bad_type) << R"({"resolution": "big"})";
  std::ofstream(bad_json) << R"({"resolution": )";
  const fs::path out = dir.path / "out";
  struct Case {
    std::string args;
    int code;
    const char* says;
  };
  const Case cases[] = {
      {"--out " + out.string() + " --format tiff", 2, "--format"},
      {"--out " + out.string() + " --frames 0", 2, "--frames"},
      {"--out " + out.string() + " --frames 2 --loop", 2, "not both"},
      {"--out " + out.string() + " --loop --loop-period 0", 2, "--loop"},
      {"--out " + out.string() + " --resolution 100", 2, "resolution"},
      {"--out " + out.string() + " --fps 0", 2, "--fps"},
      {"--out " + out.string() + " --time nan", 2, "--time"},
      {"--out " + out.string() + " --preset " + bad_key.string(), 2,
       "sea.wind_sea.windspeed: unknown key"},
      {"--out " + out.string() + " --preset " + bad_type.string(), 2,
       "resolution: expected an integer"},
      {"--out " + out.string() + " --preset " + bad_json.string(), 2, "not valid JSON"},
      {"--out " + out.string() + " --preset " + (dir.path / "missing.json").string(), 1,
       "cannot read preset"},
      {"--out " + out.string() + " --set nokey", 2, "key=value"},
      {"--out " + out.string() + " --backend cuda", 1, "CUDA"},  // built without, or no device
      {"--out " + (bad_key / "sub").string(), 1, "cannot"},
      {"", 2, "--out"},
  };
  for (const Case& c : cases) {
    std::string err;
    EXPECT_EQ(bake_run(c.args, &err), c.code) << c.args << ": " << err;
    EXPECT_NE(err.find(c.says), std::string::npos) << c.args << " said: " << err;
    EXPECT_FALSE(fs::exists(out)) << c.args;  // nothing written, not even a folder
  }
}

}  // namespace
