// The tool's last line of defence (apps/ocean/main.cpp) and its bounds on input: standard output
// that cannot be written fails the run, running out of memory ends as one line and exit 1 (never
// an abort), presets too large are refused before they are read whole, and an output path that
// is not a regular file is refused, not replaced.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using ocean_test::CliRun;
using ocean_test::line_count;
using ocean_test::run_cli;
using ocean_test::run_cli_after;
using ocean_test::ScratchDir;

// Every command that prints on standard output, with small settings.
TEST(CliBounds, AFullStandardOutputFailsEveryCommandThatPrints) {
  const ocean_test::VulkanChildren vulkan;  // info and validate list the Vulkan devices
  for (const char* args : {
           "spectrum --omega 0.5,1 --json",
           "spectrum --omega 0.5,1",
           "dispersion --k 0.1,1 --json",
           "dispersion --k 0.1,1",
           "spreading --theta 0,0.5 --json",
           "spreading --theta 0,0.5",
           "stats --resolution 16 --seeds 1 --json",
           "stats --resolution 16 --seeds 1",
           "info --json",
           "info",
           "validate --json",
           "validate",
           "lod --camera 0,30,0 --target 100,0,100 --json",
           "lod --camera 0,30,0 --target 100,0,100",
           "bench --json --resolution 16 --cascades 1 --threads 1 --min-time 0",
           "bench --resolution 16 --cascades 1 --threads 1 --min-time 0",
           "--help",
           "spectrum --help",
       }) {
    const CliRun r = run_cli(std::string(args) + " >/dev/full");
    EXPECT_EQ(r.exit_code, 1) << args;
    // The last line (a progress bar may come before it on standard error), and the only error.
    EXPECT_TRUE(
        r.err.ends_with("ocean: error: cannot write standard output: No space left on device\n"))
        << args << " said: " << r.err;
    EXPECT_EQ(r.err.find("ocean: error:"), r.err.rfind("ocean: error:")) << r.err;
  }
  // The same commands print as before where there is room.
  const CliRun fine = run_cli("spectrum --omega 0.5,1 --json");
  EXPECT_EQ(fine.exit_code, 0) << fine.err;
  EXPECT_FALSE(fine.out.empty());
}

// A failed command keeps its own message and code; the output failure adds nothing.
TEST(CliBounds, AFailedCommandReportsOnlyItsOwnError) {
  const CliRun r = run_cli("spectrum --omega x >/dev/full");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "ocean: error: --omega = 'x' is not a number\n");
}

TEST(CliBounds, OutOfMemoryIsOneLineAndExitOne) {
  if (ocean_test::kAddressSanitizer) GTEST_SKIP() << "ulimit -v cannot be used under ASan";
  // Statistics over 8 cascades of 2048² need several GiB; 1 GB of address space cannot hold
  // them, and nothing below main() catches the std::bad_alloc.
  const CliRun r =
      run_cli_after("ulimit -v 1000000; ",
                    "stats --resolution 2048 --cascades 1000,500,250,120,60,30,15,8 --seeds 1");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err, "ocean: error: out of memory: running ocean stats\n");
  EXPECT_TRUE(r.out.empty());
}

TEST(CliBounds, PresetsAreReadOnlyUpToTheirBound) {
  // Under a limit of 2 GB too, so that reading without a bound fails quickly rather than
  // filling the machine's memory.
  const std::string limit = ocean_test::kAddressSanitizer ? "" : "ulimit -v 2000000; ";
  const ScratchDir dir("ocean_cli_preset_");
  const CliRun r =
      run_cli_after(limit, "bake --preset /dev/zero --out " + (dir.path / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err,
            "ocean: error: preset '/dev/zero' is larger than 1048576 bytes (1 MiB), the most a "
            "preset may hold\n");
  EXPECT_FALSE(fs::exists(dir.path / "out"));
}

TEST(CliBounds, APlotOntoAFifoIsRefusedAndTheFifoStays) {
  const ScratchDir dir("ocean_cli_fifo_");
  const fs::path fifo = dir.path / "sea.png";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const CliRun r = run_cli("spectrum --plot " + fifo.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "ocean: error: cannot write '" + fifo.string() +
                       "': it is a FIFO, not a regular file\n");
  EXPECT_EQ(line_count(r.err), 1);
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 1);
}

}  // namespace
