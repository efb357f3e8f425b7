// `ocean bake` into a folder as a transaction, tried on a real child process: SIGINT, SIGTERM or
// SIGHUP mid-bake leaves no temporary and a manifest saying "complete": false; a second bake into a
// busy folder fails at once naming the first one's pid; an old manifest is gone before the first
// new file; a killed bake blocks nothing; bad paths fail before the first frame; a failed start
// leaves no folder; a full disk (a file size limit, and a 2 MiB tmpfs where one can be mounted)
// gives one line and a folder the manifest describes.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "cli/cli_run.hpp"

namespace {

using ocean_test::line_count;

namespace fs = std::filesystem;
using Json = nlohmann::json;

using ocean_test::listing;
using ocean_test::ScratchDir;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// An `ocean bake` child started with fork/exec, stdout to /dev/null and stderr to a file;
// killed and reaped by the destructor if the test did not wait for it.
class Child {
 public:
  /// SIGINT, SIGTERM and SIGHUP start with their default actions (as in a terminal's foreground
  /// job), or SIGINT ignored (as in a shell's background job) if `ignore_sigint`, SIGHUP ignored
  /// (as under nohup) if `ignore_sighup`.
  Child(const std::vector<std::string>& args, fs::path err_file,
        rlim_t file_size_limit = RLIM_INFINITY, bool ignore_sigint = false,
        bool ignore_sighup = false)
      : err_file_(std::move(err_file)) {
    std::vector<std::string> words = {OCEAN_CLI_PATH, "bake"};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    pid_ = ::fork();
    if (pid_ == 0) {
      sigset_t none;
      sigemptyset(&none);
      ::sigprocmask(SIG_SETMASK, &none, nullptr);
      std::signal(SIGINT, ignore_sigint ? SIG_IGN : SIG_DFL);
      std::signal(SIGTERM, SIG_DFL);
      std::signal(SIGHUP, ignore_sighup ? SIG_IGN : SIG_DFL);
      if (file_size_limit != RLIM_INFINITY) {
        const rlimit limit{file_size_limit, file_size_limit};
        if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(126);
      }
      const int err = ::open(err_file_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int null = ::open("/dev/null", O_WRONLY);
      if (err < 0 || null < 0 || ::dup2(err, 2) < 0 || ::dup2(null, 1) < 0) ::_exit(126);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  ~Child() {
    if (pid_ > 0 && !reaped_) {
      ::kill(pid_, SIGKILL);
      (void)wait();
    }
  }

  pid_t pid() const { return pid_; }
  bool running() {
    if (reaped_) return false;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) != pid_) return true;
    reaped_ = true;
    status_ = status;
    return false;
  }
  /// The raw wait status.
  int wait() {
    while (!reaped_) {
      int status = 0;
      const pid_t r = ::waitpid(pid_, &status, 0);
      if (r == pid_) {
        reaped_ = true;
        status_ = status;
      } else if (r < 0 && errno != EINTR) {
        reaped_ = true;
      }
    }
    return status_;
  }
  std::string err() const { return read_text(err_file_); }

 private:
  fs::path err_file_;
  pid_t pid_ = -1;
  bool reaped_ = false;
  int status_ = -1;
};

// Waits (polling, no timing asserted) until `file` exists while `child` runs; false if the
// child ended first or nothing came within two minutes.
bool wait_for_file(Child& child, const fs::path& file) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  while (std::chrono::steady_clock::now() < deadline) {
    if (fs::exists(file)) return true;
    if (!child.running()) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

// A bake long enough to be still running when it is stopped: 10^6 frames, one small cascade.
std::vector<std::string> long_bake(const fs::path& out) {
  return {"--resolution", "16", "--cascades", "50", "--frames", "1000000", "--out", out.string()};
}

// A stopped bake's folder: no temporary, no lock, and a manifest saying "complete": false that
// lists exactly the frame files present, every frame whole. Returns the manifest.
Json expect_incomplete_and_consistent(const fs::path& dir) {
  for (const std::string& name : listing(dir)) {
    EXPECT_EQ(name.find(".tmp-"), std::string::npos) << "temporary left: " << name;
    EXPECT_NE(name, ".ocean-bake.lock") << "lock file left";
  }
  EXPECT_TRUE(fs::is_regular_file(dir / "manifest.json")) << "no manifest";
  if (!fs::is_regular_file(dir / "manifest.json")) return {{"frames", Json::array()}};
  const Json m = Json::parse(read_text(dir / "manifest.json"));
  EXPECT_EQ(m.value("complete", true), false);
  EXPECT_EQ(m.value("frames_written", -1), static_cast<long long>(m["frames"].size()));
  std::set<std::string> listed;
  std::size_t files_per_frame = 0;
  for (const Json& frame : m["frames"]) {
    if (files_per_frame == 0) files_per_frame = frame["files"].size();
    EXPECT_EQ(frame["files"].size(), files_per_frame);
    for (const Json& f : frame["files"]) listed.insert(f.get<std::string>());
  }
  for (const std::string& name : listed) EXPECT_TRUE(fs::exists(dir / name)) << name;
  for (const std::string& name : listing(dir)) {
    if (name != "manifest.json") {
      EXPECT_TRUE(listed.count(name)) << "not in the manifest: " << name;
    }
  }
  return m;
}

TEST(BakeTransaction, SigintOrSigtermMidBakeLeavesNoTemporaryAndAnIncompleteManifest) {
  for (const int signal : {SIGINT, SIGTERM}) {
    ScratchDir dir("bake_signal_");
    const fs::path out = dir.path / "out";
    Child bake(long_bake(out), dir.path / "err");
    // Frame 1 begun: frame 0 is whole.
    ASSERT_TRUE(wait_for_file(bake, out / "displacement_c0_f00001.npy")) << bake.err();
    ASSERT_EQ(::kill(bake.pid(), signal), 0);
    const int status = bake.wait();
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
    const std::string err = bake.err();
    const std::string name = signal == SIGINT ? "SIGINT" : "SIGTERM";
    EXPECT_EQ(err.rfind("ocean: error: bake interrupted: " + name, 0), 0u) << err;
    EXPECT_EQ(line_count(err), 1) << err;
    const Json m = expect_incomplete_and_consistent(out);
    EXPECT_GE(m["frames"].size(), 1u);
    EXPECT_EQ(m["frame_count"], 1000000);
  }
}

// The terminal closing (SIGHUP: a logout, a lost ssh connection) stops a bake as Ctrl-C does:
// between two files, with the incomplete manifest, and exit 128 + 1.
TEST(BakeTransaction, SighupMidBakeStopsItAsSigintDoes) {
  ScratchDir dir("bake_sighup_");
  const fs::path out = dir.path / "out";
  Child bake(long_bake(out), dir.path / "err");
  ASSERT_TRUE(wait_for_file(bake, out / "displacement_c0_f00001.npy")) << bake.err();
  ASSERT_EQ(::kill(bake.pid(), SIGHUP), 0);
  const int status = bake.wait();
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGHUP);
  const std::string err = bake.err();
  EXPECT_EQ(err.rfind("ocean: error: bake interrupted: SIGHUP; bake cancelled after ", 0), 0u)
      << err;
  EXPECT_EQ(line_count(err), 1) << err;
  const Json m = expect_incomplete_and_consistent(out);
  EXPECT_GE(m["frames"].size(), 1u);
}

// The set of signals on the line `field` ("SigIgn": ignored, "SigCgt": caught by a handler) of
// /proc/<pid>/status, bit n-1 for signal n.
unsigned long long signal_set(pid_t pid, const std::string& field) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind(field + ":", 0) == 0)
      return std::stoull(line.substr(field.size() + 1), nullptr, 16);
  }
  return 0;
}

bool in_set(unsigned long long set, int signal) { return ((set >> (signal - 1)) & 1u) != 0; }

// A shell starts background jobs with SIGINT ignored, so that Ctrl-C reaches only the foreground
// job: the bake keeps it ignored, and still handles SIGTERM.
TEST(BakeTransaction, ASigintIgnoredByTheParentStaysIgnored) {
  ScratchDir dir("bake_sigign_");
  const fs::path out = dir.path / "out";
  Child bake(long_bake(out), dir.path / "err", RLIM_INFINITY, true);
  ASSERT_TRUE(wait_for_file(bake, out / "displacement_c0_f00001.npy")) << bake.err();
  EXPECT_TRUE(in_set(signal_set(bake.pid(), "SigIgn"), SIGINT));
  EXPECT_FALSE(in_set(signal_set(bake.pid(), "SigCgt"), SIGINT));
  EXPECT_TRUE(in_set(signal_set(bake.pid(), "SigCgt"), SIGTERM));
  ASSERT_EQ(::kill(bake.pid(), SIGTERM), 0);
  const int status = bake.wait();
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << bake.err();
  expect_incomplete_and_consistent(out);
}

// `nohup ocean bake ... &` outlives the terminal: a SIGHUP its parent ignores stays ignored, and
// the bake still stops on SIGTERM.
TEST(BakeTransaction, ASighupIgnoredByTheParentStaysIgnored) {
  ScratchDir dir("bake_sighupign_");
  const fs::path out = dir.path / "out";
  Child bake(long_bake(out), dir.path / "err", RLIM_INFINITY, false, true);
  ASSERT_TRUE(wait_for_file(bake, out / "displacement_c0_f00001.npy")) << bake.err();
  EXPECT_TRUE(in_set(signal_set(bake.pid(), "SigIgn"), SIGHUP));
  EXPECT_FALSE(in_set(signal_set(bake.pid(), "SigCgt"), SIGHUP));
  EXPECT_TRUE(in_set(signal_set(bake.pid(), "SigCgt"), SIGINT));
  ASSERT_EQ(::kill(bake.pid(), SIGHUP), 0);
  ASSERT_EQ(::kill(bake.pid(), SIGTERM), 0);
  const int status = bake.wait();
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << bake.err();
  expect_incomplete_and_consistent(out);
}

TEST(BakeTransaction, ASecondBakeIntoABusyFolderFailsAtOnceNamingTheFirst) {
  ScratchDir dir("bake_lock_");
  const fs::path out = dir.path / "out";
  Child first(long_bake(out), dir.path / "err");
  ASSERT_TRUE(wait_for_file(first, out / "displacement_c0_f00000.npy")) << first.err();
  const ocean_test::CliRun second =
      ocean_test::run_cli("bake --resolution 16 --cascades 50 --seed 2 --out " + out.string());
  EXPECT_EQ(second.exit_code, 1);
  EXPECT_NE(second.err.find("process " + std::to_string(first.pid())), std::string::npos)
      << second.err;
  EXPECT_EQ(line_count(second.err), 1) << second.err;
  ASSERT_EQ(::kill(first.pid(), SIGINT), 0);
  const int status = first.wait();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 130) << first.err();
  // Nothing of the second one's is in the folder: the manifest is the first's.
  const Json m = expect_incomplete_and_consistent(out);
  EXPECT_EQ(m["config"]["seed"], 1);
  // The lock went with the first bake: the next one runs.
  EXPECT_EQ(
      ocean_test::run_cli("bake --resolution 16 --cascades 50 --out " + out.string()).exit_code, 0);
}

TEST(BakeTransaction, AKilledBakeInvalidatedTheOldManifestAndBlocksNothing) {
  ScratchDir dir("bake_killed_");
  const fs::path out = dir.path / "out";
  const std::string small = "bake --resolution 16 --cascades 50 --out " + out.string();
  ASSERT_EQ(ocean_test::run_cli(small + " --seed 1 --frames 2").exit_code, 0);
  ASSERT_TRUE(fs::exists(out / "manifest.json"));
  const fs::path first_file = out / "displacement_c0_f00000.npy";
  struct stat old_file {};
  ASSERT_EQ(::stat(first_file.c_str(), &old_file), 0);

  // A new bake (seed 2) replaces frame 0 by renaming a new file over it: from that moment on
  // the seed-1 manifest must be gone. SIGKILL cannot be caught: what is left is what a crash
  // leaves.
  std::vector<std::string> args = long_bake(out);
  args.insert(args.end(), {"--seed", "2"});
  Child killed(args, dir.path / "err");
  bool replaced = false;
  while (!replaced && killed.running()) {
    struct stat now {};
    replaced = ::stat(first_file.c_str(), &now) == 0 && now.st_ino != old_file.st_ino;
    if (!replaced) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_TRUE(replaced) << killed.err();
  EXPECT_FALSE(fs::exists(out / "manifest.json")) << "an old manifest next to new frames";
  ASSERT_EQ(::kill(killed.pid(), SIGKILL), 0);
  killed.wait();
  EXPECT_FALSE(fs::exists(out / "manifest.json"));

  // Temporaries of dead bakes are swept by the next bake; a live process's are not touched.
  const fs::path dead = out / (".foam_c0_f00009.npy.tmp-" + std::to_string(killed.pid()) + "-3");
  const fs::path live = out / (".foam_c0_f00009.npy.tmp-" + std::to_string(::getpid()) + "-3");
  std::ofstream(dead) << "partial";
  std::ofstream(live) << "being written";
  const ocean_test::CliRun next = ocean_test::run_cli(small + " --seed 3");
  EXPECT_EQ(next.exit_code, 0) << next.err;
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_FALSE(fs::exists(out / ".ocean-bake.lock"));
  const Json m = Json::parse(read_text(out / "manifest.json"));
  EXPECT_EQ(m["complete"], true);
  EXPECT_EQ(m["frames_written"], 1);
  EXPECT_EQ(m["config"]["seed"], 3);
}

TEST(BakeTransaction, BadOutputPathsFailBeforeTheFirstFrame) {
  ScratchDir dir("bake_paths_");
  const fs::path fifo = dir.path / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const fs::path old_bake = dir.path / "old";
  ASSERT_EQ(ocean_test::run_cli("bake --resolution 16 --cascades 50 --out " + old_bake.string())
                .exit_code,
            0);
  const std::string old_manifest = read_text(old_bake / "manifest.json");
  struct Case {
    fs::path out, sheet;
    const char* says;
  };
  const Case cases[] = {
      {dir.path / "new" / "maps", dir.path / "missing" / "sheet.png", "No such file or directory"},
      {dir.path / "new" / "maps", dir.path, "is a directory"},
      {dir.path / "new" / "maps", fifo, "not a regular file"},
      {old_bake, dir.path / "missing" / "sheet.png", "No such file or directory"},
      {fifo / "maps", dir.path / "sheet.png", "not a directory"},
  };
  for (const Case& c : cases) {
    const ocean_test::CliRun r =
        ocean_test::run_cli("bake --resolution 16 --cascades 50 --frames 1000000 --out " +
                            c.out.string() + " --contact-sheet " + c.sheet.string());
    EXPECT_EQ(r.exit_code, 1) << c.sheet;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir.path / "new")) << c.sheet << ": a folder left by a failed start";
    EXPECT_TRUE(fs::is_fifo(fifo));
    // An old bake in the folder is untouched by a start that failed.
    EXPECT_EQ(read_text(old_bake / "manifest.json"), old_manifest);
    EXPECT_FALSE(fs::exists(old_bake / "displacement_c0_f00001.npy"));
  }
}

TEST(BakeTransaction, AFailedStartLeavesNoFolder) {
  ScratchDir dir("bake_start_");
  const ocean_test::CliRun r = ocean_test::run_cli("bake --backend no-such-backend --out " +
                                                   (dir.path / "a" / "b").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir.path / "a"));
}

// A file size limit of 8 KiB: the files of a 16² frame (4224 bytes at most) and the manifest fit,
// the contact sheet written after frame 0 (about 18 kB) does not, so its write fails with EFBIG
// and SIGXFSZ (which by default kills the process and leaves the temporary behind).
TEST(BakeTransaction, AFileSizeLimitFailsWithOneLineAndNoTemporary) {
  ScratchDir dir("bake_fsize_");
  const fs::path out = dir.path / "out", sheet = dir.path / "sheet.png";
  Child bake({"--resolution", "16", "--cascades", "50", "--frames", "3", "--out", out.string(),
              "--contact-sheet", sheet.string()},
             dir.path / "err", 8 * 1024);
  const int status = bake.wait();
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 1);
  const std::string err = bake.err();
  EXPECT_EQ(err.rfind("ocean: error: cannot write '" + sheet.string() + "'", 0), 0u) << err;
  EXPECT_NE(err.find("File too large"), std::string::npos) << err;
  EXPECT_EQ(line_count(err), 1) << err;
  EXPECT_EQ(listing(dir.path), (std::set<std::string>{"err", "out"}));
  const Json m = expect_incomplete_and_consistent(out);
  EXPECT_EQ(m["frames"].size(), 1u);
}

// A real full disk: a 2 MiB tmpfs mounted in a private mount namespace (so it never shows
// outside this test), needing root. The folder is copied out before the namespace ends.
TEST(BakeTransaction, AFullDiskFailsWithOneLineAndAConsistentFolder) {
  if (::geteuid() != 0) {
    GTEST_SKIP() << "not root, so no tmpfs can be mounted; AFileSizeLimitFailsWithOneLineAndNo"
                    "Temporary covers a failing write";
  }
  ScratchDir dir("bake_full_");
  const fs::path mnt = dir.path / "mnt", copy = dir.path / "copy", script = dir.path / "full.sh";
  fs::create_directories(mnt);
  std::ofstream(script) << "mount -t tmpfs -o size=2m tmpfs \"$1\" || { echo 'mount failed'; exit "
                           "0; }\n"
                           "\"$2\" bake --resolution 64 --cascades 50 --frames 100 --out "
                           "\"$1/out\" 2>\"$3/err\"\n"
                           "echo \"exit $?\"\n"
                           "cp -a \"$1/out\" \"$3/copy\"\n";
  const std::string command = "unshare --mount --propagation private sh " + script.string() + " " +
                              mnt.string() + " " + OCEAN_CLI_PATH + " " + dir.path.string() +
                              " 2>&1";
  std::string said;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) said += buffer;
    ::pclose(pipe);
  }
  if (said.rfind("exit ", 0) != 0) {
    GTEST_SKIP() << "no tmpfs could be mounted (" << said
                 << "); AFileSizeLimitFailsWithOneLineAndNoTemporary covers a failing write";
  }
  EXPECT_EQ(said, "exit 1\n");
  const std::string err = read_text(dir.path / "err");
  EXPECT_NE(err.find("No space left on device"), std::string::npos) << err;
  EXPECT_EQ(line_count(err), 1) << err;
  const Json m = expect_incomplete_and_consistent(copy);
  EXPECT_GE(m["frames"].size(), 1u);
  EXPECT_LT(m["frames"].size(), 100u);
}

}  // namespace
