// Fuzz target: the library's height map reader (ocean::waves::load_height_map), which takes the
// .npy, PNG and OpenEXR files a user names for waveforms and the seabed. Byte 0 picks the
// extension the file is given; the rest is the file. A map it accepts is 1..kMaxHeightMapSide
// samples a side with rows × cols finite values; anything else is a one-line error, never a
// crash, a leak or an allocation the file does not pay for.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <system_error>

#include "expect.hpp"
#include "memory_file.hpp"
#include "ocean/waves.hpp"

namespace {

// A directory of this process's own for the named links to the in-memory file, removed at exit.
struct LinkDir {
  std::filesystem::path path = std::filesystem::temp_directory_path() /
                               ("ocean-fuzz-height-map-" + std::to_string(::getpid()));
  LinkDir() { std::filesystem::create_directories(path); }
  ~LinkDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  LinkDir(const LinkDir&) = delete;
  LinkDir& operator=(const LinkDir&) = delete;
};

const std::filesystem::path& link_dir() {
  static const LinkDir dir;
  return dir.path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const char* const kExtensions[] = {".npy", ".png", ".exr"};
  const ocean::fuzz::MemoryFile file(data + 1, size - 1);
  const std::filesystem::path link = link_dir() / (std::string("map") + kExtensions[data[0] % 3]);
  std::error_code ec;
  std::filesystem::remove(link, ec);
  std::filesystem::create_symlink(file.path(), link);
  const auto map = ocean::waves::load_height_map(link);
  using ocean::fuzz::expect;
  if (!map.ok()) {
    expect(map.status().message().find('\n') == std::string::npos, "height map: two-line error");
    return 0;
  }
  const ocean::waves::HeightMap& m = map.value();
  expect(m.rows >= 1 && m.cols >= 1 && m.rows <= ocean::waves::kMaxHeightMapSide &&
             m.cols <= ocean::waves::kMaxHeightMapSide,
         "height map: side outside 1..kMaxHeightMapSide");
  expect(m.values.size() == static_cast<std::size_t>(m.rows) * static_cast<std::size_t>(m.cols),
         "height map: values != rows*cols");
  for (float v : m.values) expect(std::isfinite(v), "height map: a non-finite value accepted");
  return 0;
}
