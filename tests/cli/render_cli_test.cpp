// `ocean render` from the command line: PNG and EXR output of the right size and content, image
// sequences, the statistics as JSON, and bad input (unknown preset, zero-size image, unwritable
// output, unknown extension, MP4 without ffmpeg, no Vulkan device): one line, non-zero exit,
// nothing written. Skips the rendering cases where no Vulkan device exists (fails them with
// OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/cli_run.hpp"
#include "ocean/vk.hpp"
#include "support/exr_reader.hpp"
#include "support/png_reader.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean_test::line_count;

namespace fs = std::filesystem;

bool have_vulkan() { return ocean::vk::list_devices().ok(); }

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ocean_render_cli_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir / name;
}

const std::string kRenderSmall =
    " --width 80 --height 45 --quality low --resolution 64 --warmup 0 --validation";

TEST(RenderCli, WritesAPngOfTheRequestedSize) {
  if (!have_vulkan()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const fs::path out = scratch("a.png");
  const ocean_test::CliRun r =
      ocean_test::run_cli("render --out " + out.string() + kRenderSmall + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["patches"].get<int>(), 0);
  EXPECT_LE(j["draw_calls"].get<int>(), 19);
  auto png = ocean::io::read_png(out);
  ASSERT_TRUE(png.ok()) << png.status().message();
  EXPECT_EQ(png.value().width, 80);
  EXPECT_EQ(png.value().height, 45);
  EXPECT_EQ(png.value().channels, 3);
  // Sky on top brighter in blue than the dark water at the bottom.
  const auto& px = png.value().samples;
  const auto blue = [&](int x, int y) {
    return px[static_cast<std::size_t>((y * 80 + x) * 3 + 2)];
  };
  EXPECT_GT(blue(5, 2), blue(5, 43));
}

// The lagoon of `--shallows lagoon` straight down from 700 m (docs/rendering.md R.24, R.64): its
// 400 m map ends in 300 m of water, so its deep water looks as the open sea does there. The same
// sea is drawn with and without the lagoon; the mean colour of four patches inside the map's
// corners (180 m from both axes) and of four across the middle of its sides (the map's edge at
// 200 m through their middle) is each channel within 3 % of the open sea's at the same pixels.
// The patches lie symmetrically about the nadir, so the picture's orientation does not matter.
TEST(RenderCli, TheLagoonsDeepWaterHasTheOpenSeasColour) {
  if (!have_vulkan()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const auto shoot = [](const std::string& name, const std::string& flags) {
    const fs::path out = scratch(name);
    const ocean_test::CliRun r = ocean_test::run_cli(
        "render --out " + out.string() +
        " --width 160 --height 160 --quality low --resolution 64 --warmup 0 --preset moderate "
        "--camera 0,700,1 --target 0,0,0 --fov 60" +
        flags);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    auto png = ocean::io::read_png(out);
    EXPECT_TRUE(png.ok()) << png.status().message();
    return png.ok() ? std::move(png).value().samples : std::vector<std::uint16_t>{};
  };
  const std::vector<std::uint16_t> lagoon = shoot("lagoon_colour.png", " --shallows lagoon");
  const std::vector<std::uint16_t> sea = shoot("sea_colour.png", "");
  ASSERT_EQ(lagoon.size(), 160u * 160u * 3u);
  ASSERT_EQ(sea.size(), lagoon.size());
  const double per_m = 80.0 / (700.0 * std::tan(30.0 * 3.14159265358979 / 180.0));  // px per m
  // Mean of channel ch over four 7×7 patches centred on the world offsets (±x, ±z).
  const auto patches = [&](const std::vector<std::uint16_t>& px, double x, double z, int ch) {
    double sum = 0.0;
    for (const auto& [ox, oz] : {std::pair{x, z}, {-x, z}, {x, -z}, {-x, -z}}) {
      const int cx = static_cast<int>(std::lround(80.0 + ox * per_m - 0.5));
      const int cy = static_cast<int>(std::lround(80.0 + oz * per_m - 0.5));
      for (int y = cy - 3; y <= cy + 3; ++y)
        for (int x0 = cx - 3; x0 <= cx + 3; ++x0)
          sum += px[static_cast<std::size_t>((y * 160 + x0) * 3 + ch)];
    }
    return sum / 196.0;
  };
  for (int ch = 0; ch < 3; ++ch) {
    const double corners = patches(lagoon, 180.0, 180.0, ch);
    const double corners_sea = patches(sea, 180.0, 180.0, ch);
    const double edges = (patches(lagoon, 200.0, 0.0, ch) + patches(lagoon, 0.0, 200.0, ch)) / 2;
    const double edges_sea = (patches(sea, 200.0, 0.0, ch) + patches(sea, 0.0, 200.0, ch)) / 2;
    std::printf(
        "channel %d: lagoon's deep corners %.2f, open sea %.2f; across the map's edge "
        "%.2f, open sea %.2f (sRGB levels)\n",
        ch, corners, corners_sea, edges, edges_sea);
    EXPECT_NEAR(corners, corners_sea, 0.03 * corners_sea) << "channel " << ch;
    EXPECT_NEAR(edges, edges_sea, 0.03 * edges_sea) << "channel " << ch;
  }
}

// The summed samples of `b` over those of `a`: their brightness ratio.
double brightness_ratio(const ocean::io::PngImage& a, const ocean::io::PngImage& b) {
  double sa = 0.0, sb = 0.0;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    sa += a.samples[i];
    sb += b.samples[i];
  }
  return sb / sa;
}

// --supersample N draws N times larger and writes the requested size, averaged in linear light
// (R.60): a different picture from the plain one, of the same mean brightness within 2 %.
TEST(RenderCli, SupersampleWritesTheRequestedSize) {
  if (!have_vulkan()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const fs::path plain = scratch("plain.png"), super = scratch("super.png");
  const ocean_test::CliRun a = ocean_test::run_cli("render --out " + plain.string() + kRenderSmall);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const ocean_test::CliRun b = ocean_test::run_cli("render --out " + super.string() + kRenderSmall +
                                                   " --supersample 2 --json");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(nlohmann::json::parse(b.out)["supersample"].get<int>(), 2);
  auto p = ocean::io::read_png(plain);
  auto q = ocean::io::read_png(super);
  ASSERT_TRUE(p.ok() && q.ok());
  EXPECT_EQ(q.value().width, 80);
  EXPECT_EQ(q.value().height, 45);
  EXPECT_NE(p.value().samples, q.value().samples);
  EXPECT_NEAR(brightness_ratio(p.value(), q.value()), 1.0, 0.02);
}

// --taa (R.61): a sequence of two frames, the first the mean of 16 jittered draws, each of the
// requested size, different from the plain picture, of the same mean brightness within 2 %, with
// the validation layer silent.
TEST(RenderCli, TaaWritesASequenceOfTheRequestedSize) {
  if (!have_vulkan()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const fs::path plain = scratch("taa_plain.png"), taa = scratch("taa_%d.png");
  const ocean_test::CliRun a = ocean_test::run_cli("render --out " + plain.string() + kRenderSmall);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const ocean_test::CliRun b =
      ocean_test::run_cli("render --out " + taa.string() + kRenderSmall + " --taa --frames 2");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  auto p = ocean::io::read_png(plain);
  ASSERT_TRUE(p.ok());
  for (const char* name : {"taa_0.png", "taa_1.png"}) {
    auto q = ocean::io::read_png(scratch(name));
    ASSERT_TRUE(q.ok()) << name;
    EXPECT_EQ(q.value().width, 80);
    EXPECT_EQ(q.value().height, 45);
    EXPECT_NE(p.value().samples, q.value().samples);
    EXPECT_NEAR(brightness_ratio(p.value(), q.value()), 1.0, 0.02) << name;
  }
}

// A preset's far_field_range (docs/rendering.md R.13) is the picture's unless --far-field-range
// says otherwise: with [0, 1] the whole sea beyond a metre is the far field and the picture
// changes; the flag with the default range gives back the default picture bit for bit.
TEST(RenderCli, PresetFarFieldRangeAppliesUnlessTheFlagOverrides) {
  if (!have_vulkan()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const std::string small = " --width 64 --height 36 --quality low --resolution 32 --warmup 0";
  const auto render = [&](const std::string& name, const std::string& extra) {
    const fs::path out = scratch(name);
    const ocean_test::CliRun r =
        ocean_test::run_cli("render --out " + out.string() + small + extra);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    auto png = ocean::io::read_png(out);
    EXPECT_TRUE(png.ok());
    return png.ok() ? png.value().samples : decltype(png.value().samples){};
  };
  const auto plain = render("ff_plain.png", "");
  const auto preset = render("ff_preset.png", " --set 'far_field_range=[0,1]'");
  const auto flag =
      render("ff_flag.png", " --set 'far_field_range=[0,1]' --far-field-range 1000,2500");
  ASSERT_FALSE(plain.empty());
  EXPECT_NE(plain, preset);
  EXPECT_EQ(plain, flag);
}

TEST(RenderCli, WritesLinearHdrExrAndSequences) {
  if (!have_vulkan()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const fs::path exr = scratch("b.exr");
  ocean_test::CliRun r = ocean_test::run_cli("render --out " + exr.string() + kRenderSmall);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto image = ocean::io::read_exr(exr);
  ASSERT_TRUE(image.ok()) << image.status().message();
  EXPECT_EQ(image.value().width, 80);
  ASSERT_EQ(image.value().channel_names.size(), 3u);  // B, G, R
  float max_value = 0.0f;
  for (const auto& plane : image.value().planes)
    for (float v : plane) {
      ASSERT_TRUE(std::isfinite(v));
      max_value = std::max(max_value, v);
    }
  EXPECT_GT(max_value, 0.0f);

  const fs::path seq = scratch("seq.png");
  r = ocean_test::run_cli("render --out " + seq.string() + kRenderSmall + " --frames 3 --fps 10");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (int f = 0; f < 3; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "seq_%05d.png", f);
    EXPECT_TRUE(fs::exists(seq.parent_path() / name)) << name;
  }
  EXPECT_FALSE(fs::exists(seq));
}

TEST(RenderCli, BadInputSaysWhatIsWrong) {
  ocean_test::expect_usage_error("render --preset hurricane", "hurricane");
  ocean_test::expect_usage_error("render --width 0", "--width");
  ocean_test::expect_usage_error("render --height -5", "--height");
  ocean_test::expect_usage_error("render --out picture.jpg", ".png, .exr or .mp4");
  ocean_test::expect_usage_error("render --camera 0,-3000,0", "at most 1000 m below the sea");
  ocean_test::expect_usage_error("render --camera 1,2", "--camera");
  ocean_test::expect_usage_error("render --quality extreme", "--quality");
  ocean_test::expect_usage_error("render --view xray", "--view");
  ocean_test::expect_usage_error("render --frames 1.5", "--frames");
  ocean_test::expect_usage_error("render --exposure nan", "--exposure");
  ocean_test::expect_usage_error("render --supersample 5", "--supersample");
  ocean_test::expect_usage_error("render --supersample 1.5", "--supersample");
  ocean_test::expect_usage_error("render --supersample 4 --width 8192", "at most 16384 a side");
  ocean_test::expect_usage_error("render --supersample 2 --motion-vectors m.png", "--supersample");
  ocean_test::expect_usage_error("render --supersample 2 --contact-sheet s.png", "--supersample");
  ocean_test::expect_usage_error("render --taa --supersample 2", "one anti-aliasing");
  ocean_test::expect_usage_error("render --taa --sphere", "--taa: not with --sphere");
  ocean_test::expect_usage_error("render --taa --mesh tessellation", "--taa: not with --mesh");
  ocean_test::expect_usage_error("render --taa --backend vulkan", "--taa: not with --backend");
  ocean_test::expect_usage_error("render --taa --contact-sheet s.png", "no --taa");
  ocean_test::expect_usage_error("render --taa --motion-vectors m.png", "give --frames 2 or more");
  // The far field's range (docs/rendering.md R.13): two finite distances, DMIN below DMAX.
  ocean_test::expect_usage_error("render --far-field-range 2000,1000", "DMIN must be below DMAX");
  ocean_test::expect_usage_error("render --far-field-range 500,500", "DMIN must be below DMAX");
  ocean_test::expect_usage_error("render --far-field-range -5,100", "--far-field-range");
  ocean_test::expect_usage_error("render --far-field-range nan,100", "--far-field-range");
  ocean_test::expect_usage_error("render --far-field-range 100", "two distances DMIN,DMAX");
  // The water's scattering (R.54, R.66): 0..10 1/m, from the flag or a preset.
  ocean_test::expect_usage_error("render --scattering -0.1", "--scattering");
  ocean_test::expect_usage_error("render --scattering 11", "--scattering");
  ocean_test::expect_usage_error("render --scattering nan", "--scattering");
  ocean_test::expect_usage_error("render --set underwater.scattering_per_m=12",
                                 "underwater.scattering_per_m");
  // The far field's noise map (R.13b): 0 (none) or 128..4096 texels, a window within 1e6 m.
  ocean_test::expect_usage_error("render --far-noise-resolution 100", "[128, 4096]");
  ocean_test::expect_usage_error("render --far-noise-resolution -1", "--far-noise-resolution");
  ocean_test::expect_usage_error("render --far-noise-resolution 2.5", "--far-noise-resolution");
  ocean_test::expect_usage_error("render --far-noise-resolution 512 --far-field-range 1000,500000",
                                 "exceeds the simulation's 1e6 m");
  // ... and in a preset ("far_field_range"), refused before anything runs, by render and view.
  ocean_test::expect_usage_error("render --set 'far_field_range=[2000,1000]'",
                                 "far_field_range: [2000, 1000] must be finite distances with 0 "
                                 "<= DMIN < DMAX");
  ocean_test::expect_usage_error("render --set 'far_field_range=[5]'", "far_field_range: expected");
  ocean_test::expect_usage_error("view --set 'far_field_range=[-1,10]'", "far_field_range:");
  // The local layer's flags (docs/waves.md), as ocean bake and ocean query read them.
  ocean_test::expect_usage_error("render --kelvin-wake 0,0,0,6,40", "--local-area");
  ocean_test::expect_usage_error("render --kelvin-wake 0,0,0,nan,40 --local-area -100,-100,200",
                                 "--kelvin-wake");
  ocean_test::expect_usage_error("render --calm", "--local-area");
  ocean_test::expect_usage_error("render --bathymetry depth.npy,0,0", "--bathymetry");
  ocean_test::expect_usage_error(
      "render --calm --local-area -100,-100,200 --bathymetry x.npy,0,0,1", "--calm");
  // The planet's radius (R.15): positive, a number, at least a kilometre; inf is a flat sea.
  ocean_test::expect_usage_error("render --planet-radius 0", "--planet-radius = 0 is out of range");
  ocean_test::expect_usage_error("render --planet-radius -6371000", "--planet-radius");
  ocean_test::expect_usage_error("render --planet-radius nan", "--planet-radius");
  ocean_test::expect_usage_error("render --planet-radius 500", "a radius >= 1000 m");
  ocean_test::expect_usage_error("render --planet-radius earth", "--planet-radius");
  // The environment map (R.17): readable, OpenEXR (HDR), RGB, twice as wide as high.
  ocean_test::expect_usage_error("render --environment /nonexistent/sky.exr",
                                 "--environment: cannot read '/nonexistent/sky.exr'");
  const ocean_test::ScratchDir dir("ocean_render_environment");
  const std::vector<std::uint8_t> grey(8 * 4 * 3, 128);
  ASSERT_TRUE(ocean::io::write_png8(dir.path / "sky.png", 8, 4, 3, grey.data()).ok());
  ocean_test::expect_usage_error("render --environment " + (dir.path / "sky.png").string(),
                                 "not an OpenEXR file");
}

// A wake drawn into the picture (docs/rendering.md R.19): the same render with and without it
// differ, and only the wake's flags changed.
TEST(RenderCli, KelvinWakeChangesThePicture) {
  if (!have_vulkan()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const std::string view =
      " --width 96 --height 96 --quality low --resolution 64 --warmup 0"
      " --camera -60,120,1 --target -60,0,0 --validation";
  const fs::path plain = scratch("plain.png"), wake = scratch("wake.png");
  ocean_test::CliRun r = ocean_test::run_cli("render --out " + plain.string() + view);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = ocean_test::run_cli("render --out " + wake.string() + view +
                          " --kelvin-wake -120,0,0,6,30 --local-area -150,-75,150"
                          " --local-resolution 256");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto a = ocean::io::read_png(plain), b = ocean::io::read_png(wake);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a.value().samples.size(), b.value().samples.size());
  double diff = 0.0;
  for (std::size_t i = 0; i < a.value().samples.size(); ++i)
    diff += std::abs(int(a.value().samples[i]) - int(b.value().samples[i]));
  EXPECT_GT(diff / static_cast<double>(a.value().samples.size()), 0.1);  // 0.44 measured
}

// --calm draws the layer alone: with no wake in its area the picture is a flat mirror, the same
// in every frame, and a wake makes it differ.
TEST(RenderCli, CalmDrawsOnlyTheLayer) {
  if (!have_vulkan()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const std::string view =
      " --width 64 --height 64 --quality low --warmup 0 --calm"
      " --camera -60,120,1 --target -60,0,0 --validation"
      " --local-area -150,-75,150 --local-resolution 128";
  const fs::path a = scratch("calm_a.png"), b = scratch("calm_b.png"), w = scratch("calm_w.png");
  ASSERT_EQ(ocean_test::run_cli("render --time 1 --out " + a.string() + view).exit_code, 0);
  ASSERT_EQ(ocean_test::run_cli("render --time 9 --out " + b.string() + view).exit_code, 0);
  const ocean_test::CliRun r = ocean_test::run_cli("render --time 9 --out " + w.string() + view +
                                                   " --kelvin-wake -120,0,0,6,30");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto pa = ocean::io::read_png(a), pb = ocean::io::read_png(b), pw = ocean::io::read_png(w);
  ASSERT_TRUE(pa.ok() && pb.ok() && pw.ok());
  EXPECT_EQ(pa.value().samples, pb.value().samples);  // no sea moves under a calm
  EXPECT_NE(pb.value().samples, pw.value().samples);
}

TEST(RenderCli, UnwritableOutputFailsBeforeRendering) {
  const ocean_test::CliRun r = ocean_test::run_cli("render --out /nonexistent/dir/x.png");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("cannot write '/nonexistent/dir/x.png'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists("/nonexistent/dir/x.png"));
}

TEST(RenderCli, Mp4NeedsFfmpegOrIsWritten) {
  const fs::path out = scratch("c.mp4");
  const bool ffmpeg = std::system("command -v ffmpeg >/dev/null 2>&1") == 0;
  const ocean_test::CliRun r =
      ocean_test::run_cli("render --out " + out.string() + kRenderSmall + " --frames 2");
  if (!ffmpeg) {
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("ffmpeg"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  } else if (have_vulkan()) {
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_GT(fs::file_size(out), 0u);
  }
}

TEST(RenderCli, NoVulkanDeviceIsOneLine) {
  const fs::path out = scratch("none.png");
  // Point the loader at no driver at all.
  const std::string env = "VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json ";
  const std::string cmd = env + OCEAN_CLI_PATH + std::string(" render --out ") + out.string() +
                          " --width 8 --height 8 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string text;
  char buf[512];
  while (std::fgets(buf, sizeof buf, pipe) != nullptr) text += buf;
  const int status = pclose(pipe);
  EXPECT_EQ(WEXITSTATUS(status), 1) << text;
  EXPECT_NE(text.find("Vulkan"), std::string::npos) << text;
  EXPECT_EQ(line_count(text), 1) << text;
  EXPECT_FALSE(fs::exists(out));
}

// The tessellated mesh (docs/rendering.md R.40–R.42): sky above, water below; where the device
// lacks tessellation shaders, one line and no file. An unknown mesh is a usage error.
TEST(RenderCli, TessellatedMeshRendersOrIsRefusedInOneLine) {
  ocean_test::expect_usage_error("render --mesh triangles", "quadtree or tessellation");
  if (!have_vulkan()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const fs::path out = scratch("tessellated.png");
  const ocean_test::CliRun r = ocean_test::run_cli("render --mesh tessellation --out " +
                                                   out.string() + kRenderSmall + " --json");
  if (r.exit_code != 0) {
    EXPECT_NE(r.err.find("lacks tessellation shaders"), std::string::npos) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
    return;
  }
  EXPECT_GT(nlohmann::json::parse(r.out)["patches"].get<int>(), 0);
  auto png = ocean::io::read_png(out);
  ASSERT_TRUE(png.ok()) << png.status().message();
  const auto& px = png.value().samples;
  const auto blue = [&](int x, int y) {
    return px[static_cast<std::size_t>((y * 80 + x) * 3 + 2)];
  };
  EXPECT_GT(blue(5, 2), blue(5, 43));
}

}  // namespace
