// The exact error line of every number and name flag of the ocean tool: the messages the typed
// options (apps/ocean/options.hpp) and the enum name tables write, each as the tool has always
// written it.
#include <gtest/gtest.h>

#include <string>

#include "cli_run.hpp"

namespace {

struct Case {
  const char* args;
  const char* message;  // after "ocean: error: "
};

void expect_messages(std::initializer_list<Case> cases) {
  for (const Case& c : cases) {
    const ocean_test::CliRun r = ocean_test::run_cli(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_EQ(r.err, std::string("ocean: error: ") + c.message + "\n") << c.args;
  }
}

TEST(CliMessages, SpectrumDispersionSpreading) {
  expect_messages({
      {"spectrum --omega 1,x", "--omega = 'x' is not a number"},
      {"spectrum --omega 1,", "--omega = '' is not a number"},
      {"spectrum --omega 1,-1", "--omega = -1 is out of range: must be >= 0 and finite"},
      {"spectrum --hs nan --tp 8 --omega 1", "--hs = nan is out of range: must be a finite number"},
      {"spectrum --gamma x --omega 1", "--gamma = 'x' is not a number"},  // not "----gamma"
      {"spectrum --gamma 0.5 --omega 1", "--gamma = 0.5 is out of range: must be in [1, 20]"},
      {"spectrum --depth-factor x --omega 1",
       "--depth-factor = 'x' is unknown: must be exact or thompson-vincent"},
      {"spectrum --fetch-law x --omega 1",
       "--fetch-law = 'x' is unknown: must be hasselmann or cube-root"},
      {"spectrum --normalization x --omega 1",
       "--normalization = 'x' is unknown: must be dnv or exact"},
      {"spectrum --model foo --omega 1",
       "--model: model = 'foo' is unknown: must be one of pierson-moskowitz, jonswap, tma, "
       "phillips"},
      {"dispersion --k 1,-2", "--k = -2 is out of range: must be >= 0 and finite"},
      {"dispersion --omega inf", "--omega = inf is out of range: must be >= 0 and finite"},
      {"dispersion --depth x --k 1", "--depth = 'x' is not a number"},
      {"spreading --omega-ratio 0 --theta 0",
       "--omega-ratio = 0 is out of range: must be > 0 and finite"},
      {"spreading --wind-speed 200 --fetch 1e5 --theta 0",
       "--wind-speed = 200 is out of range: must be in [0.001, 100]"},
      {"spreading --wind-speed 10 --fetch x --theta 0", "--fetch = 'x' is not a number"},
      {"spreading --wind-speed 10 --fetch 0.5 --theta 0",
       "--fetch = 0.5 is out of range: must be in [1, 1e+08]"},
      {"spreading --theta 0,inf", "--theta = inf is out of range: must be a finite number"},
      {"spreading --alpha x --theta 0", "--alpha = 'x' is not a number"},
      {"spreading --model nope --theta 0",
       "--model: spreading model = 'nope' is unknown: must be one of power-cosine, cos2s, "
       "mitsuyasu, hasselmann, donelan-banner"},
  });
}

TEST(CliMessages, SimulationAndStatsFlags) {
  expect_messages({
      {"stats --resolution 100.5",
       "--resolution = 100.5 is out of range: must be a power of two in [16, 2048]"},
      {"stats --resolution 100",
       "resolution = 100 is out of range: must be a power of two in [16, 2048]"},
      {"stats --seed -1", "--seed = -1 is out of range: must be an integer >= 0"},
      {"stats --seed 1.5", "--seed = 1.5 is out of range: must be an integer >= 0"},
      {"stats --cascades 100,x", "--cascades = 'x' is not a number"},
      {"stats --choppiness nan", "--choppiness = nan is out of range: must be a finite number"},
      {"stats --normals x",
       "--normals: normals = 'x' is unknown: must be one of central-difference, analytic, sobel"},
      {"stats --seeds 0", "--seeds = 0 is out of range: must be an integer in [1, 100000]"},
      {"stats --seeds 2.5", "--seeds = 2.5 is out of range: must be an integer in [1, 100000]"},
      {"stats --time inf", "--time = inf is out of range: must be a finite number"},
      {"stats --patch-size 0", "--patch-size = 0 is out of range: must be in [0.01, 1e+06]"},
  });
}

// Names read from presets (src/preset) through --set.
TEST(CliMessages, PresetNames) {
  expect_messages({
      {"stats --set sea.wind_sea.fetch_law=x",
       "sea.wind_sea.fetch_law: expected \"hasselmann\" or \"cube-root\", got a string"},
      {"stats --set sea.wind_sea.normalization=x",
       "sea.wind_sea.normalization: expected \"dnv\" or \"exact\", got a string"},
      {"stats --set sea.wind_sea.depth_factor=x",
       "sea.wind_sea.depth_factor: expected \"exact\" or \"thompson-vincent\", got a string"},
      {"stats --set blue_channel=x", "blue_channel = 'x' is unknown: must be foam or jacobian"},
      {"stats --set normals=x",
       "normals = 'x' is unknown: must be one of central-difference, analytic, sobel"},
      {"stats --set sea.wind_sea.model=x",
       "sea.wind_sea.model: model = 'x' is unknown: must be one of pierson-moskowitz, jonswap, "
       "tma, phillips"},
      {"stats --set sea.wind_sea.spreading.model=x",
       "sea.wind_sea.spreading.model: spreading model = 'x' is unknown: must be one of "
       "power-cosine, cos2s, mitsuyasu, hasselmann, donelan-banner"},
  });
}

TEST(CliMessages, BakeFlags) {
  const std::string out = " --out " + testing::TempDir() + "ocean_messages_bake";
  const std::string fps = "bake --fps 0" + out, time = "bake --time inf" + out,
                    zero = "bake --frames 0" + out, half = "bake --frames 1.5" + out;
  expect_messages({
      {fps.c_str(), "--fps = 0 is out of range: must be in [0.001, 10000]"},
      {time.c_str(), "--time = inf is out of range: must be a finite number"},
      {zero.c_str(), "--frames = 0 is out of range: must be an integer in [1, 1000000]"},
      {half.c_str(), "--frames = 1.5 is out of range: must be an integer in [1, 1000000]"},
  });
}

TEST(CliMessages, BenchFlags) {
  expect_messages({
      {"bench --resolution 100", "--resolution = 100 is not a power of two"},
      {"bench --resolution 4096",
       "--resolution = '4096' is out of range: must be an integer in [16, 2048]"},
      {"bench --cascades 1.5", "--cascades = '1.5' is out of range: must be an integer in [1, 4]"},
      {"bench --threads 0",
       "--threads = '0' is out of range: must be an integer in [1, 256] or 'all'"},
      {"bench --threads nan", "--threads = nan is out of range: must be a finite number"},
      {"bench --threads 1,,2", "--threads = '' is not a number"},
      {"bench --cascades ''", "--cascades is empty: give a value or leave the flag out"},
      {"bench --min-time -1", "--min-time = -1 is out of range: must be in [0, 60] s"},
      {"bench --frame-interval 5000",
       "--frame-interval = 5000 is out of range: must be in [0, 1000] ms"},
  });
}

TEST(CliMessages, LodFlags) {
  expect_messages({
      {"lod --camera 0,10,0 --target 1,0,0 --ocean-size 100",
       "--ocean-size = 100 is out of range: must be in [256, 8192]"},
      {"lod --camera 0,10,0 --target 1,0,0 --fov 0",
       "--fov = 0 is out of range: must be in [1, 170]"},
      {"lod --camera 0,10,0 --target 1,0,0 --aspect 30",
       "--aspect = 30 is out of range: must be in [0.05, 20]"},
      {"lod --camera 0,10,0 --target 1,0,0 --center 1",
       "--center = 1 must be two finite numbers X,Z"},
      {"lod --camera 0,10,0 --target 1,0,0 --center 1,x", "--center = 'x' is not a number"},
      {"lod --camera 1,2 --target 0,0,0", "--camera = 1,2 must be three numbers X,Y,Z"},
      {"lod --camera inf,2,3 --target 0,0,0",
       "--camera = inf is out of range: must be a finite number"},
      {"lod --camera 0,10,0 --target 1,0,0 --preset extreme",
       "--preset = extreme is not a preset: must be low, medium, high or ultra"},
  });
}

#ifdef OCEAN_HAS_VULKAN
TEST(CliMessages, RenderFlags) {
  expect_messages({
      {"render --width -3 --out y.png", "--width = -3 is out of range: must be in [1, 16384]"},
      {"render --width 10.5", "--width and --height must be whole numbers of pixels"},
      {"render --fov 200", "--fov = 200 is out of range: must be in [1, 170]"},
      {"render --frames 0", "--frames = 0 is out of range: must be in [1, 1e+06]"},
      {"render --frames 2.5", "--frames = 2.5 must be a whole number"},
      {"render --fps 0", "--fps = 0 is out of range: must be in [0.001, 1000]"},
      {"render --warmup 700", "--warmup = 700 is out of range: must be in [0, 600]"},
      {"render --time -1", "--time = -1 is out of range: must be in [0, 1e+09]"},
      {"render --sun-elevation 95", "--sun-elevation = 95 is out of range: must be in [-10, 90]"},
      {"render --sun-azimuth 400", "--sun-azimuth = 400 is out of range: must be in [-360, 360]"},
      {"render --exposure 0", "--exposure = 0 is out of range: must be in [0.001, 1000]"},
      {"render --ocean-size 100", "--ocean-size = 100 is out of range: must be in [256, 8192]"},
      {"render --sky foggy", "--sky = foggy is not a sky: must be clear, hazy, overcast or sunset"},
      {"render --quality x", "--quality = x is not a quality: must be low, medium, high or ultra"},
      {"render --view x", "--view = x is not a view: must be shaded, lod, wireframe or normals"},
  });
}
#endif

#ifdef OCEAN_HAS_VIEW
TEST(CliMessages, ViewFlags) {
  expect_messages({
      {"view --frames -1", "--frames = -1 is out of range: must be in [0, 1e+09]"},
      {"view --frames 2.5", "--frames = 2.5 must be a whole number"},
      {"view --width 10", "--width = 10 is out of range: must be in [64, 16384]"},
  });
}
#endif

}  // namespace
