// A scratch folder for a test: tests/support, shared by the test executables.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace ocean_test {

/// <temp>/<name><pid>, removed (with all it holds) when made and when the object goes; not
/// created, so that a test can check what creates it.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() / (name + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

}  // namespace ocean_test
