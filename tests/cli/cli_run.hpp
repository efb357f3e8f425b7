// Runs the built `ocean` binary with arguments and captures its exit code, stdout and stderr.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace ocean_test {

struct CliRun {
  int exit_code = -1;
  std::string out, err;
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

/// A fresh, empty scratch directory "<temp>/<name><pid>", removed at the end of the test.
struct ScratchDir {
  std::filesystem::path path;
  explicit ScratchDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() / (name + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() { std::filesystem::remove_all(path); }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
};

/// The bad-input contract: exit 2, nothing on stdout, one line on stderr that mentions `says`.
inline void expect_usage_error(const std::string& args, const std::string& says) {
  const CliRun r = run_cli(args);
  EXPECT_EQ(r.exit_code, 2) << args;
  EXPECT_TRUE(r.out.empty()) << args << " printed: " << r.out;
  EXPECT_NE(r.err.find(says), std::string::npos) << args << " said: " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << " said: " << r.err;
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
