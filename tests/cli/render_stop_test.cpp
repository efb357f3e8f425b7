// `ocean render --float` over a long simulated span: the objects are integrated from t = 0 to the
// picture's time, so --time has a stated bound with --float (refused beyond it with one usage
// line), a long span shows its progress, and SIGINT, SIGTERM or SIGHUP stop it cleanly: exit
// 128 + the signal, one line, nothing written. Tried on a real child process.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/cli_run.hpp"
#include "ocean/vk.hpp"

namespace {

namespace fs = std::filesystem;

// The flags of a small, quick picture; the sea is the moderate preset's unless more are given.
const std::vector<std::string> kStopSmall = {"--width",   "16",  "--height", "16",
                                             "--quality", "low", "--warmup", "0"};

// Bodies integrated to --time 1e6 would take days: refused at once, naming the flag and the
// bound, with or without a frame sequence that would end beyond it.
TEST(RenderStop, FloatingBeyondTheBoundIsAUsageError) {
  const ocean_test::ScratchDir dir("ocean_render_stop_");
  const std::string out = (dir.path / "a.png").string();
  for (const auto& [args, message] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--time", "1e6"},
            "--time = 1e+06 is out of range with --float: must be at most 600 s (the objects "
            "are integrated from t = 0 in 1/60 s steps)"},
           {{"--time", "599", "--frames", "61", "--fps", "30"},
            "--time 599 with --frames 61 at --fps 30 ends at 601 s, out of range with --float: "
            "must be at most 600 s (the objects are integrated from t = 0 in 1/60 s steps)"}}) {
    std::vector<std::string> words = {"30", OCEAN_CLI_PATH, "render",    "--out",
                                      out,  "--object",     "box,0,0,0", "--float"};
    words.insert(words.end(), args.begin(), args.end());
    words.insert(words.end(), kStopSmall.begin(), kStopSmall.end());
    const ocean_test::CliRun r = ocean_test::run_program("timeout", words);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(r.err, "ocean: error: " + message + "\n");
  }
  EXPECT_TRUE(fs::is_empty(dir.path));
}

// A span of a minute or more shows its progress: a bar on a terminal, one summary line in a log.
TEST(RenderStop, ALongFloatingSpanShowsItsProgress) {
  if (!ocean::vk::list_devices().ok()) GTEST_SKIP() << "no Vulkan device";
  const ocean_test::ScratchDir dir("ocean_render_stop_");
  std::vector<std::string> args = {"render",   "--out",      (dir.path / "a.png").string(),
                                   "--object", "box,0,0,0",  "--float",
                                   "--time",   "60",         "--resolution",
                                   "16",       "--cascades", "60"};
  args.insert(args.end(), kStopSmall.begin(), kStopSmall.end());
  const ocean_test::CliRun r = ocean_test::run_cli_argv(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.rfind("floating bodies (1/60 s steps): 3600/3600 done in ", 0), 0u) << r.err;
  EXPECT_EQ(ocean_test::line_count(r.err), 1) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir.path / "a.png"));
}

// The CPU time `pid` has used, in clock ticks (/proc/<pid>/stat: utime + stime).
long long render_stop_cpu_ticks(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  const std::size_t close = text.rfind(')');  // the command name may hold spaces
  if (close == std::string::npos) return 0;
  std::istringstream fields(text.substr(close + 2));
  std::string field;
  long long utime = 0, stime = 0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {  // fields 3.. after the name
    if (i == 14) utime = std::stoll(field);
    if (i == 15) stime = std::stoll(field);
  }
  return utime + stime;
}

TEST(RenderStop, ASignalStopsALongFloatingSpanAndWritesNothing) {
  if (!ocean::vk::list_devices().ok()) GTEST_SKIP() << "no Vulkan device";
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    const ocean_test::ScratchDir dir("ocean_render_stop_");
    const fs::path out = dir.path / "pictures";
    fs::create_directory(out);
    const fs::path err_file = dir.path / "err";
    // The bound's span of the moderate sea: minutes of work, stopped long before its end.
    std::vector<std::string> words = {
        OCEAN_CLI_PATH, "render", "--out", (out / "a.png").string(), "--object", "box,0,0,0",
        "--float",      "--time", "600"};
    words.insert(words.end(), kStopSmall.begin(), kStopSmall.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      sigset_t none;
      sigemptyset(&none);
      ::sigprocmask(SIG_SETMASK, &none, nullptr);
      for (const int s : {SIGINT, SIGTERM, SIGHUP}) std::signal(s, SIG_DFL);
      const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int null = ::open("/dev/null", O_WRONLY);
      if (err < 0 || null < 0 || ::dup2(err, 2) < 0 || ::dup2(null, 1) < 0) ::_exit(126);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    // Half a second of CPU time: past the start, into the integration (no timing is asserted:
    // wherever the signal lands, the render stops the same way).
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    int status = 0;
    bool ended = false;
    while (std::chrono::steady_clock::now() < deadline && !ended &&
           render_stop_cpu_ticks(pid) < ::sysconf(_SC_CLK_TCK) / 2) {
      ended = ::waitpid(pid, &status, WNOHANG) == pid;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (!ended) {
      ASSERT_EQ(::kill(pid, signal), 0);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
    }
    const std::string err = ocean_test::read_whole_file(err_file);
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << ": " << err;
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal) << err;
    const std::string name = signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "SIGHUP";
    EXPECT_EQ(err, "ocean: error: render interrupted: " + name + "; nothing written\n");
    EXPECT_TRUE(fs::is_empty(out)) << name;
  }
}

}  // namespace
