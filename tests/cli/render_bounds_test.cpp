// `ocean render` refuses, before allocating anything, a picture the machine cannot hold, and an
// output that is not a regular file: one line naming the size or the path and the limit,
// nothing written. The memory limit is set with `ulimit -v` (not under ASan, which cannot run
// with one).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_run.hpp"
#include "ocean/vk.hpp"

namespace {

using ocean_test::line_count;

namespace fs = std::filesystem;
using ocean_test::CliRun;
using ocean_test::run_cli;
using ocean_test::run_cli_after;
using ocean_test::ScratchDir;

void expect_one_line(const CliRun& r, int exit_code, const std::string& says) {
  EXPECT_EQ(r.exit_code, exit_code) << r.err;
  EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// The tool's own buffers: a 16384² PNG holds 8 (read-back) + 7 (PNG) bytes a pixel, 3.75 GiB,
// more than a 3 GB address space; found before the Vulkan device is even opened.
TEST(RenderBounds, APictureLargerThanMemoryIsRefusedFirst) {
  if (ocean_test::kAddressSanitizer) GTEST_SKIP() << "ulimit -v cannot be used under ASan";
  const ScratchDir dir("ocean_render_bounds_");
  const fs::path out = dir.path / "huge.png";
  const CliRun r = run_cli_after("ulimit -v 3000000; ",
                                 "render --out " + out.string() + " --width 16384 --height 16384");
  expect_one_line(r, 2,
                  "ocean: error: --width 16384 --height 16384: rendering a PNG needs 3.8 GiB of "
                  "memory, more than the ");
  expect_one_line(r, 2, " the address-space limit (ulimit -v) leaves\n");
  EXPECT_TRUE(fs::is_empty(dir.path));
  // An EXR holds more a pixel (8 + 34 bytes): 3000² of it, 360 MiB, in 300 MB.
  const CliRun exr =
      run_cli_after("ulimit -v 300000; ", "render --out " + (dir.path / "a.exr").string() +
                                              " --width 3000 --height 3000");
  expect_one_line(exr, 2, "--width 3000 --height 3000: rendering an EXR needs 360 MiB of memory");
  EXPECT_TRUE(fs::is_empty(dir.path));
}

// The renderer's targets on a CPU device are host memory too: 16 bytes a pixel and the 8 of the
// read-back buffer, 6 GiB at 16384², which passes the tool's check (3.75 GiB) under a 5.5 GB
// limit but not the renderer's: refused either against the device's heap (lavapipe's is 2 GiB)
// or against what the limit leaves, before any target is allocated.
TEST(RenderBounds, TheRenderersTargetsAreCheckedBeforeTheyAreAllocated) {
  if (ocean_test::kAddressSanitizer) GTEST_SKIP() << "ulimit -v cannot be used under ASan";
  const auto devices = ocean::vk::list_devices();
  if (!devices.ok() || devices.value().size() != 1 || devices.value()[0].type != "cpu")
    GTEST_SKIP() << "the test needs one device, a CPU one, whose memory is host memory";
  const ScratchDir dir("ocean_render_bounds_");
  const CliRun r = run_cli_after("ulimit -v 5500000; ",
                                 "render --out " + (dir.path / "big.png").string() +
                                     " --width 16384 --height 16384 --resolution 16 --warmup 0");
  expect_one_line(r, 2, "ocean: error: image size 16384x16384 ");
  const bool heap = r.err.find(
                        " needs 6.0 GiB of device memory for its targets and read-back "
                        "buffer, more than the ") != std::string::npos;
  const bool host = r.err.find(" needs 6.0 GiB of memory, more than the ") != std::string::npos;
  EXPECT_TRUE(heap || host) << r.err;
  EXPECT_TRUE(fs::is_empty(dir.path));
}

TEST(RenderBounds, AnOutputThatIsNotARegularFileIsRefusedBeforeRendering) {
  const ScratchDir dir("ocean_render_bounds_");
  const fs::path fifo = dir.path / "frame.png";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const CliRun r = run_cli("render --out " + fifo.string() + " --width 8 --height 8");
  expect_one_line(r, 1, "cannot write '" + fifo.string() + "': it is a FIFO, not a regular file");
  EXPECT_TRUE(fs::is_fifo(fifo));
}

// --environment is read whole under the reader's limit: /dev/zero and a FIFO with no writer are
// one usage line at once, naming the file and the limit, before any device is opened. (Under an
// address-space and a time limit, so that a reader without a bound fails rather than fills the
// machine's memory or waits for ever.)
TEST(RenderBounds, AnEnvironmentMapThatIsNotARegularFileIsRefusedAtOnce) {
  const ScratchDir dir("ocean_render_bounds_");
  const fs::path fifo = dir.path / "sky.exr";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string limit = ocean_test::kAddressSanitizer ? "" : "ulimit -v 2000000; ";
  for (const auto& [path, kind] :
       {std::pair<std::string, std::string>{"/dev/zero", "a character device"},
        {fifo.string(), "a FIFO"}}) {
    const CliRun r =
        run_cli_after(limit + "timeout 60 ",
                      "render --environment " + path + " --out " + (dir.path / "a.png").string());
    expect_one_line(r, 2,
                    "ocean: error: --environment: cannot read '" + path + "': it is " + kind +
                        ", not a regular file; an OpenEXR file is read whole, at most 2147483648 "
                        "bytes (2 GiB)\n");
  }
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(ocean_test::listing(dir.path), std::set<std::string>{"sky.exr"});
}

// An MP4 is one file whatever the frame count: a FIFO or a link to a device under its name is
// refused before anything is rendered or ffmpeg started, and stays as it was.
TEST(RenderBounds, AnMp4OntoAFifoOrADeviceIsRefusedBeforeRendering) {
  for (const char* frames : {"1", "2"}) {
    const ScratchDir dir("ocean_render_bounds_");
    const fs::path fifo = dir.path / "video.mp4";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const CliRun r = ocean_test::run_cli_argv(
        {"render", "--out", fifo.string(), "--frames", frames, "--width", "8", "--height", "8"});
    expect_one_line(
        r, 1,
        "ocean: error: cannot write '" + fifo.string() + "': it is a FIFO, not a regular file\n");
    EXPECT_TRUE(fs::is_fifo(fifo)) << frames;
    EXPECT_EQ(ocean_test::listing(dir.path), std::set<std::string>{"video.mp4"}) << frames;

    const fs::path link = dir.path / "null.mp4";
    fs::create_symlink("/dev/null", link);
    const CliRun d = ocean_test::run_cli_argv(
        {"render", "--out", link.string(), "--frames", frames, "--width", "8", "--height", "8"});
    expect_one_line(d, 1,
                    "ocean: error: cannot write '" + link.string() +
                        "': it links to a character device, not a regular file\n");
    EXPECT_TRUE(fs::is_symlink(link)) << frames;
    EXPECT_EQ(ocean_test::listing(dir.path), (std::set<std::string>{"video.mp4", "null.mp4"}));
  }
}

// A FIFO made under the MP4's name while ffmpeg encodes (by a stand-in ffmpeg that writes its
// output and then makes it) is not replaced: the name is checked again before the rename, as the
// library's atomic writes do, and the temporary is removed.
TEST(RenderBounds, AnMp4OutputThatBecomesAFifoWhileEncodingIsNotReplaced) {
  if (!ocean::vk::list_devices().ok()) GTEST_SKIP() << "no Vulkan device";
  const ScratchDir dir("ocean_render_bounds_");
  const fs::path bin = dir.path / "bin";
  fs::create_directory(bin);
  // The last argument is "file:<temporary>".
  std::ofstream(bin / "ffmpeg") << "#!/bin/sh\ncat >/dev/null\nfor a; do last=$a; done\n"
                                   "echo video > \"${last#file:}\"\nmkfifo \"$FIFO_AT\"\n";
  fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
  const fs::path out = dir.path / "v.mp4";
  const CliRun r = ocean_test::run_cli_argv(
      {"render", "--out", out.string(), "--frames", "2", "--width", "16", "--height", "16",
       "--quality", "low", "--resolution", "16", "--cascades", "60", "--warmup", "0"},
      {}, {"PATH=" + bin.string() + ":/usr/bin:/bin", "FIFO_AT=" + out.string()});
  expect_one_line(
      r, 1,
      "ocean: error: cannot write '" + out.string() + "': it is a FIFO, not a regular file\n");
  EXPECT_TRUE(fs::is_fifo(out));
  EXPECT_EQ(ocean_test::listing(dir.path), (std::set<std::string>{"bin", "v.mp4"}));
}

}  // namespace
