// src/waves/height_map_file.cpp — reading pre-authored height maps: NumPy .npy (2-D float32 or
// float64, C order), grayscale PNG (8 or 16 bits, mapped to [−1, 1]) and OpenEXR (one channel,
// or Y, values as they are). Every failure is one
// line naming the file (through ocean::excerpt) and what is wrong; memory is bounded by the file
// size and kMaxHeightMapSide, so a hostile header cannot make it allocate more.
//
// libpng reports errors by longjmp: each setjmp lives in a small function whose frame holds no
// C++ object with a destructor (as in the project's PNG writer).
#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "io/png_detail.hpp"
#include "ocean/io.hpp"
#include "ocean/waves.hpp"

namespace ocean::waves {
namespace {

constexpr std::size_t kMaxNpyHeader = 65536;

Status bad(const std::filesystem::path& path, const std::string& why) {
  return invalid_argument("cannot read '" + excerpt(path.string()) + "': " + why);
}

Status check_size(const std::filesystem::path& path, std::uint64_t rows, std::uint64_t cols) {
  if (rows < 1 || cols < 1 || rows > kMaxHeightMapSide || cols > kMaxHeightMapSide) {
    return bad(path, "a height map must be 1 to " + std::to_string(kMaxHeightMapSide) +
                         " samples on each side, not " + std::to_string(rows) + "x" +
                         std::to_string(cols));
  }
  return {};
}

// The value of key `key` in a .npy header dict, up to the next ',' or '}' at depth 0.
std::string dict_value(const std::string& header, const std::string& key) {
  std::size_t at = header.find("'" + key + "'");
  if (at == std::string::npos) at = header.find("\"" + key + "\"");
  if (at == std::string::npos) return {};
  at = header.find(':', at);
  if (at == std::string::npos) return {};
  std::size_t end = at + 1;
  for (int depth = 0; end < header.size(); ++end) {
    const char c = header[end];
    depth += c == '(' ? 1 : c == ')' ? -1 : 0;
    if (depth == 0 && (c == ',' || c == '}')) break;
  }
  std::string v = header.substr(at + 1, end - at - 1);
  v.erase(0, v.find_first_not_of(' '));
  v.erase(v.find_last_not_of(' ') + 1);
  return v;
}

Result<HeightMap> read_npy(const std::filesystem::path& path, const std::string& bytes) {
  if (bytes.size() < 10 || std::memcmp(bytes.data(), "\x93NUMPY", 6) != 0)
    return bad(path, "not a NumPy .npy file");
  const auto major = static_cast<unsigned char>(bytes[6]);
  const std::size_t len_bytes = major == 1 ? 2 : 4;
  if (major < 1 || major > 3 || bytes.size() < 8 + len_bytes)
    return bad(path, "unsupported .npy version");
  std::size_t header_len = 0;
  for (std::size_t i = 0; i < len_bytes; ++i)
    header_len |= static_cast<std::size_t>(static_cast<unsigned char>(bytes[8 + i])) << (8 * i);
  const std::size_t data_at = 8 + len_bytes + header_len;
  if (header_len > kMaxNpyHeader || data_at > bytes.size())
    return bad(path, "truncated or oversized .npy header");
  const std::string header = bytes.substr(8 + len_bytes, header_len);
  const std::string descr = dict_value(header, "descr");
  const std::size_t item = descr == "'<f4'" || descr == "\"<f4\""   ? 4
                           : descr == "'<f8'" || descr == "\"<f8\"" ? 8
                                                                    : 0;
  if (item == 0) return bad(path, "dtype must be float32 or float64 ('<f4' or '<f8')");
  if (dict_value(header, "fortran_order") != "False") return bad(path, "must be in C order");
  const std::string shape = dict_value(header, "shape");
  unsigned long long rows = 0, cols = 0;
  char tail = 0;
  if (std::sscanf(shape.c_str(), "(%llu ,%llu %c", &rows, &cols, &tail) != 3 || tail != ')')
    return bad(path, "must be a 2-D array, not shape " + excerpt(shape, 40));
  if (Status s = check_size(path, rows, cols); !s.ok()) return s;
  const std::size_t count = static_cast<std::size_t>(rows * cols);
  if (bytes.size() - data_at != count * item)
    return bad(path, "data size does not match shape " + excerpt(shape, 40));
  HeightMap map{.rows = static_cast<int>(rows), .cols = static_cast<int>(cols), .values = {}};
  map.values.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    double v = 0.0;
    if (item == 4) {
      float f = 0.0f;
      std::memcpy(&f, bytes.data() + data_at + 4 * i, 4);
      v = f;
    } else {
      std::memcpy(&v, bytes.data() + data_at + 8 * i, 8);
    }
    if (!std::isfinite(v) || std::abs(v) > 1e30)
      return bad(path, "value " + std::to_string(i) + " is not a finite height");
    map.values[i] = static_cast<float>(v);
  }
  return map;
}

// The height channel of an EXR image: its only channel, else "Y" (luminance, the gray channel of
// an OpenEXR file), else refused; every value finite. Row 0 of the file is row 0 of the map.
Result<HeightMap> read_exr_map(const std::filesystem::path& path) {
  Result<io::ExrImage> image = io::read_exr(path);
  if (!image.ok()) return image.status();
  const io::ExrImage& exr = image.value();
  std::size_t channel = 0;
  if (exr.planes.size() != 1) {
    const auto y = std::find(exr.channel_names.begin(), exr.channel_names.end(), "Y");
    if (y == exr.channel_names.end())
      return bad(path, "an EXR height map needs one channel or a \"Y\" channel, not " +
                           std::to_string(exr.planes.size()) + " without \"Y\"");
    channel = static_cast<std::size_t>(y - exr.channel_names.begin());
  }
  if (Status st = check_size(path, static_cast<std::uint64_t>(exr.height),
                             static_cast<std::uint64_t>(exr.width));
      !st.ok())
    return st;
  HeightMap map{.rows = exr.height, .cols = exr.width, .values = exr.planes[channel]};
  for (std::size_t i = 0; i < map.values.size(); ++i) {
    if (!std::isfinite(map.values[i]) || std::abs(map.values[i]) > 1e30f)
      return bad(path, "value " + std::to_string(i) + " is not a finite height");
  }
  return map;
}

bool read_header(png_structp png, png_infop info) {
  if (setjmp(png_jmpbuf(png)) != 0) return false;
  png_read_info(png, info);
  return true;
}

bool read_rows(png_structp png, png_infop info, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png)) != 0) return false;
  png_set_expand_gray_1_2_4_to_8(png);
  (void)png_set_interlace_handling(png);
  png_read_update_info(png, info);
  png_read_image(png, rows);
  return true;
}

Result<HeightMap> read_png(const std::filesystem::path& path, io::detail::PngIo& io) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &io, io::detail::png_on_error,
                                           io::detail::png_on_warning);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  struct Destroy {
    png_structp* png;
    png_infop* info;
    ~Destroy() { png_destroy_read_struct(png, info, nullptr); }
  } destroy{&png, &info};
  if (info == nullptr) return bad(path, "out of memory");
  png_set_read_fn(png, &io, io::detail::png_on_read);
  png_set_user_limits(png, kMaxHeightMapSide, kMaxHeightMapSide);
  io::detail::limit_png_reader(png);
  if (std::string problem = io::detail::check_png_chunks(io.file); !problem.empty())
    return bad(path, problem);
  if (!read_header(png, info)) return bad(path, io::detail::png_reason(io));
  if (png_get_color_type(png, info) != PNG_COLOR_TYPE_GRAY)
    return bad(path, "a PNG height map must be grayscale without alpha");
  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  if (Status s = check_size(path, height, width); !s.ok()) return s;
  const int depth = png_get_bit_depth(png, info) == 16 ? 16 : 8;
  const std::size_t row_bytes =
      static_cast<std::size_t>(width) * static_cast<std::size_t>(depth / 8);
  std::vector<png_byte> bytes(row_bytes * height);
  std::vector<png_bytep> rows(height);
  for (std::size_t y = 0; y < height; ++y) rows[y] = bytes.data() + y * row_bytes;
  if (!read_rows(png, info, rows.data())) return bad(path, io::detail::png_reason(io));
  HeightMap map{.rows = static_cast<int>(height), .cols = static_cast<int>(width), .values = {}};
  map.values.resize(static_cast<std::size_t>(width) * height);
  const double top = depth == 16 ? 65535.0 : 255.0;
  for (std::size_t i = 0; i < map.values.size(); ++i) {
    const double v = depth == 16 ? ((bytes[2 * i] << 8U) | bytes[2 * i + 1]) : bytes[i];
    map.values[i] = static_cast<float>(2.0 * v / top - 1.0);
  }
  return map;
}

}  // namespace

Result<HeightMap> load_height_map(const std::filesystem::path& path) {
  try {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".npy" && ext != ".png" && ext != ".exr")
      return bad(path, "height maps must be .npy, .png or .exr files");
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return bad(path, "it is a directory");
    if (ext == ".exr") return read_exr_map(path);
    if (ext == ".png") {
      io::detail::PngIo io;
      io.file = std::fopen(path.c_str(), "rb");
      if (io.file == nullptr) {
        return io_error("cannot read '" + excerpt(path.string()) +
                        "': " + io::errno_message(errno));
      }
      Result<HeightMap> map = read_png(path, io);
      std::fclose(io.file);
      return map;
    }
    Result<std::string> bytes = io::read_bounded(
        path,
        {.max_bytes = std::uint64_t{8} * kMaxHeightMapSide * kMaxHeightMapSide + kMaxNpyHeader,
         .what = {},
         .regular_only = true});
    if (!bytes.ok()) return bytes.status();
    return read_npy(path, bytes.value());
  } catch (const std::exception& e) {
    return io_error("cannot read '" + excerpt(path.string()) + "': " + e.what());
  }
}

}  // namespace ocean::waves
