// `ocean render --out NAME` reads the name as data: quotes, $(...), spaces, a newline, bytes
// that are not UTF-8 and %% name exactly the files written (the directory holds them and nothing
// else); other printf conversions and a second frame-number field are refused with one line and
// nothing written. The MP4 path starts ffmpeg with no shell: the video is written under its name,
// and a missing or failing ffmpeg is one line with nothing left behind.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "cli/cli_run.hpp"
#include "ocean/vk.hpp"

namespace {

using ocean_test::line_count;

namespace fs = std::filesystem;

bool names_have_vulkan() { return ocean::vk::list_devices().ok(); }

// `ocean render` of a small picture (64x48 unless told) in `dir`, with `more` flags.
ocean_test::CliRun render_in(const fs::path& dir, const std::vector<std::string>& more,
                             const std::vector<std::string>& env = {}, int width = 64,
                             int height = 48) {
  std::vector<std::string> args = {"render", "--width", std::to_string(width), "--height",
                                   std::to_string(height)};
  args.insert(args.end(),
              {"--quality", "low", "--resolution", "16", "--cascades", "60", "--warmup", "0"});
  args.insert(args.end(), more.begin(), more.end());
  return ocean_test::run_cli_argv(args, dir, env);
}

struct Written {
  std::string out, frames;
  std::set<std::string> files;
};

TEST(RenderNames, NamesAreWrittenExactly) {
  if (!names_have_vulkan()) GTEST_SKIP() << "no Vulkan device";
  for (const Written& c : std::vector<Written>{
           {"it's.png", "2", {"it's_00000.png", "it's_00001.png"}},
           {"say \"hi\".png", "1", {"say \"hi\".png"}},
           {"$(touch injected) `touch b`;.png",
            "2",
            {"$(touch injected) `touch b`;_00000.png", "$(touch injected) `touch b`;_00001.png"}},
           {"with space %03d.png", "2", {"with space 000.png", "with space 001.png"}},
           {"100%% %d.png", "2", {"100% 0.png", "100% 1.png"}},
           {"%%s%%n.png", "1", {"%s%n.png"}},
           {"new\nline.png", "1", {"new\nline.png"}},
           {"\xff\xfe.png", "2", {"\xff\xfe_00000.png", "\xff\xfe_00001.png"}},
           {"f_%05d.exr", "3", {"f_00000.exr", "f_00001.exr", "f_00002.exr"}},
       }) {
    ocean_test::ScratchDir dir("ocean_render_names_ok_");
    const ocean_test::CliRun r = render_in(dir.path, {"--out", c.out, "--frames", c.frames});
    EXPECT_EQ(r.exit_code, 0) << c.out << ": " << r.err;
    EXPECT_EQ(ocean_test::listing(dir.path), c.files) << c.out;
  }
}

TEST(RenderNames, ConversionsAndTwoFieldsAreRefusedWithOneLine) {
  for (const std::string name :
       {"a%s.png", "a%n.png", "a%n%n%n%n.png", "a%05d%05d.png", "a%5d.png", "a%x.png", "a%019d.png",
        "50%.png", "\xff%s.png", "a%d.mp4", "a%s.mp4"}) {
    for (const char* frames : {"1", "3"}) {
      ocean_test::ScratchDir dir("ocean_render_names_bad_");
      const ocean_test::CliRun r = render_in(dir.path, {"--out", name, "--frames", frames});
      EXPECT_EQ(r.exit_code, 2) << name;
      EXPECT_TRUE(r.out.empty()) << name << " printed: " << r.out;
      EXPECT_EQ(r.err.rfind("ocean: error: --out = '", 0), 0u) << name << " said: " << r.err;
      EXPECT_EQ(line_count(r.err), 1) << name << " said: " << r.err;
      EXPECT_TRUE(ocean_test::listing(dir.path).empty()) << name;
    }
  }
}

bool ffmpeg_installed() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

// An ISO BMFF file (MP4) opens with a box whose type, at byte 4, is "ftyp".
bool starts_with_ftyp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  char head[8] = {};
  in.read(head, sizeof head);
  return in && std::string(head + 4, 4) == "ftyp";
}

TEST(RenderNames, Mp4IsWrittenUnderItsNameThroughFfmpegWithNoShell) {
  if (!names_have_vulkan()) GTEST_SKIP() << "no Vulkan device";
  if (!ffmpeg_installed()) GTEST_SKIP() << "ffmpeg is not installed (./dev installs it)";
  ocean_test::ScratchDir dir("ocean_render_names_mp4_");
  const std::string name = "it's $(touch injected) \"q\" `touch b`; a:b 100%%.mp4";
  const std::string file = "it's $(touch injected) \"q\" `touch b`; a:b 100%.mp4";
  const ocean_test::CliRun r = render_in(dir.path, {"--out", name, "--frames", "3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(ocean_test::listing(dir.path), (std::set<std::string>{file}));
  EXPECT_TRUE(starts_with_ftyp(dir.path / file));
  if (std::system("command -v ffprobe >/dev/null 2>&1") == 0) {
    const ocean_test::CliRun probe = ocean_test::run_program(
        "ffprobe",
        {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
         "stream=nb_read_frames,width,height", "-of", "csv=p=0", "file:" + file},
        dir.path);
    EXPECT_EQ(probe.exit_code, 0) << probe.err;
    EXPECT_EQ(probe.out, "64,48,3\n") << probe.err;
  }
}

TEST(RenderNames, Mp4WithoutFfmpegIsOneLineAndWritesNothing) {
  ocean_test::ScratchDir dir("ocean_render_names_noffmpeg_");
  fs::create_directory(dir.path / "empty");
  const ocean_test::CliRun r = render_in(dir.path, {"--out", "v.mp4", "--frames", "2"},
                                         {"PATH=" + (dir.path / "empty").string()});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("ffmpeg"), std::string::npos) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_EQ(ocean_test::listing(dir.path), (std::set<std::string>{"empty"}));
}

// A stand-in ffmpeg in `bin`: a shell script with `body`.
void fake_ffmpeg(const fs::path& bin, const std::string& body) {
  fs::create_directory(bin);
  std::ofstream(bin / "ffmpeg") << "#!/bin/sh\n" << body << "\n";
  fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
}

TEST(RenderNames, FailingFfmpegIsOneLineAndLeavesNothing) {
  if (!names_have_vulkan()) GTEST_SKIP() << "no Vulkan device";
  // It exits at once, unread: the tool's writes meet a closed pipe (EPIPE, not SIGPIPE: a frame of
  // 160x120 RGBA is more than a pipe holds). Then one that reads everything and fails.
  for (const std::string body :
       {"echo 'fake: no such encoder' >&2; echo 'fake: giving up' >&2; exit 3",
        "cat >/dev/null; echo 'fake: cannot write' >&2; exit 4", "cat >/dev/null; exit 0"}) {
    ocean_test::ScratchDir dir("ocean_render_names_badffmpeg_");
    const fs::path bin = dir.path / "bin";
    fake_ffmpeg(bin, body);
    const ocean_test::CliRun r = render_in(dir.path, {"--out", "v.mp4", "--frames", "3"},
                                           {"PATH=" + bin.string() + ":/usr/bin:/bin"}, 160, 120);
    EXPECT_EQ(r.exit_code, 1) << body << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << body;
    EXPECT_EQ(r.err.rfind("ocean: error: cannot write 'v.mp4': ffmpeg", 0), 0u) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << body << ": " << r.err;
    EXPECT_EQ(ocean_test::listing(dir.path), (std::set<std::string>{"bin"})) << body;
  }
}

}  // namespace
