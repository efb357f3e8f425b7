// Runs the built `ocean` binary with arguments and captures its exit code, stdout and stderr:
// run_cli through the shell (arguments as one command line), run_cli_argv with an argument
// vector and no shell (any bytes in an argument, a working directory, extra environment).
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "support/temp_dir.hpp"

namespace ocean_test {

struct CliRun {
  int exit_code = -1;
  std::string out, err;
};

/// While it lives, the `ocean` processes a test starts run without LeakSanitizer's check at exit
/// (ASAN_OPTIONS gains detect_leaks=0; the test process's own setting is read at its start and
/// stays). For commands that open a Vulkan instance (`info`, `validate`, `bench --overlap`):
/// Mesa's lavapipe keeps one-time allocations that LeakSanitizer cannot name once the loader has
/// unloaded the driver, the policy of ocean_add_vulkan_test (tests/CMakeLists.txt) for the
/// tests that open one themselves. Address and undefined-behaviour checks stay on.
class VulkanChildren {
 public:
  VulkanChildren() {
    const char* old = std::getenv("ASAN_OPTIONS");
    had_ = old != nullptr;
    if (had_) old_ = old;
    ::setenv("ASAN_OPTIONS", (had_ && !old_.empty() ? old_ + ":" : "").append("detect_leaks=0").c_str(),
             1);
  }
  ~VulkanChildren() {
    if (had_) {
      ::setenv("ASAN_OPTIONS", old_.c_str(), 1);
    } else {
      ::unsetenv("ASAN_OPTIONS");
    }
  }
  VulkanChildren(const VulkanChildren&) = delete;
  VulkanChildren& operator=(const VulkanChildren&) = delete;

 private:
  bool had_ = false;
  std::string old_;
};

/// Runs `ocean <args>` through the shell (so `args` may redirect standard output), after
/// `shell_prefix` (e.g. "ulimit -v 2000000; ").
inline CliRun run_cli_after(const std::string& shell_prefix, const std::string& args) {
  const std::filesystem::path err_file =
      std::filesystem::temp_directory_path() / ("ocean_cli_stderr_" + std::to_string(::getpid()));
  const std::string command =
      shell_prefix + std::string(OCEAN_CLI_PATH) + " " + args + " 2>" + err_file.string();
  CliRun r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    r.out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_file);
  r.err.assign(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
  std::filesystem::remove(err_file);
  return r;
}

inline CliRun run_cli(const std::string& args) { return run_cli_after("", args); }

/// A fresh, empty directory in the temporary directory, named `name` and this process's id;
/// removed with all it holds when the object goes.
struct ScratchDir : TempDir {
  explicit ScratchDir(const std::string& name) : TempDir(name) {
    std::filesystem::create_directories(path);
  }
};

/// The names of the entries of `dir` (not recursive).
inline std::set<std::string> listing(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const std::filesystem::directory_entry& e : std::filesystem::directory_iterator(dir))
    names.insert(e.path().filename().string());
  return names;
}

inline std::string read_whole_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Runs `program args...` with no shell: each argument reaches it byte for byte. A program
/// without a slash is looked up in PATH. `cwd`, when not empty, is its working directory; `env`
/// entries ("NAME=value") are added to (or replace those of) this process's environment.
inline CliRun run_program(const std::string& program, const std::vector<std::string>& args,
                          const std::filesystem::path& cwd = {},
                          const std::vector<std::string>& env = {}) {
  const std::filesystem::path base =
      std::filesystem::temp_directory_path() / ("ocean_cli_argv_" + std::to_string(::getpid()));
  const std::string out_file = base.string() + ".out", err_file = base.string() + ".err";
  // Everything the child needs is built before fork: after it only async-signal-safe calls.
  std::vector<std::string> argv_text{program};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_text = env;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry(*e);
    const std::string name = entry.substr(0, entry.find('=') + 1);
    const bool replaced = std::any_of(env.begin(), env.end(), [&](const std::string& mine) {
      return mine.compare(0, name.size(), name) == 0;
    });
    if (!replaced) env_text.push_back(entry);
  }
  std::vector<char*> envp;
  for (std::string& e : env_text) envp.push_back(e.data());
  envp.push_back(nullptr);
  CliRun r;
  const pid_t pid = ::fork();
  if (pid < 0) return r;
  if (pid == 0) {
    const int out = ::open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
    if (!cwd.empty() && ::chdir(cwd.c_str()) != 0) ::_exit(126);
    ::execvpe(argv[0], argv.data(), envp.data());
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_whole_file(out_file);
  r.err = read_whole_file(err_file);
  std::filesystem::remove(out_file);
  std::filesystem::remove(err_file);
  return r;
}

/// Runs the built `ocean` with an argument vector and no shell (see run_program).
inline CliRun run_cli_argv(const std::vector<std::string>& args,
                           const std::filesystem::path& cwd = {},
                           const std::vector<std::string>& env = {}) {
  return run_program(OCEAN_CLI_PATH, args, cwd, env);
}

/// The number of lines (newline characters) in `text`: an error message is exactly one.
inline long line_count(const std::string& text) {
  return static_cast<long>(std::count(text.begin(), text.end(), '\n'));
}

/// The bad-input contract: exit 2, nothing on stdout, one line on stderr that mentions `says`.
inline void expect_usage_error(const std::string& args, const std::string& says) {
  const CliRun r = run_cli(args);
  EXPECT_EQ(r.exit_code, 2) << args;
  EXPECT_TRUE(r.out.empty()) << args << " printed: " << r.out;
  EXPECT_NE(r.err.find(says), std::string::npos) << args << " said: " << r.err;
  EXPECT_EQ(line_count(r.err), 1) << args << " said: " << r.err;
}

/// Address-space limits (`ulimit -v`) cannot be used under AddressSanitizer, which reserves
/// terabytes of shadow memory: tests that need one skip there.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

}  // namespace ocean_test
