// src/io/npy_writer.cpp — .npy 1.0 float32 writing with numpy.save's exact header.
#include <bit>
#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "format_detail.hpp"
#include "ocean/io.hpp"

namespace ocean::io {
namespace {

using detail::byte_swap;
using detail::element_count;

using detail::kNpyMagic;
using detail::kNpyMagicLen;
using detail::kNpyPreludeLen;
constexpr std::size_t kAlign = 64;
constexpr std::size_t kGrowthAxisMaxDigits = 21;  // numpy's spare room for the first axis

}  // namespace

Status write_npy(const std::filesystem::path& path, const float* data,
                 std::span<const std::size_t> shape) {
  try {
    if (shape.size() > kNpyMaxDims) {
      return invalid_argument("npy shape has " + std::to_string(shape.size()) +
                              " dimensions: at most " + std::to_string(kNpyMaxDims));
    }
    const std::optional<std::size_t> count = element_count(shape);
    if (!count) return invalid_argument("npy shape is too large: its size overflows");
    if (data == nullptr && *count > 0) return invalid_argument("npy data pointer is null");

    // Exactly what numpy.save writes: sorted keys, repr() of the values, spare spaces.
    std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (";
    for (std::size_t i = 0; i < shape.size(); ++i) {
      if (i > 0) header.append(", ");
      header.append(std::to_string(shape[i]));
    }
    header.append(shape.size() == 1 ? ",), }" : "), }");
    if (!shape.empty()) {
      header.append(
          kGrowthAxisMaxDigits - std::min(kGrowthAxisMaxDigits, std::to_string(shape[0]).size()),
          ' ');
    }
    const std::size_t unpadded = kNpyPreludeLen + header.size() + 1;  // + '\n'
    header.append(kAlign - unpadded % kAlign, ' ').push_back('\n');
    const std::size_t header_len = header.size();  // at most ~1000 bytes for 32 dimensions

    std::string prelude(kNpyMagic, kNpyMagicLen);
    prelude.append({'\x01', '\x00', static_cast<char>(header_len & 0xFFU),
                    static_cast<char>(header_len >> 8U)});
    prelude.append(header);

    std::span<const std::byte> payload;
    std::vector<float> swapped;
    if (*count > 0) {
      if constexpr (std::endian::native == std::endian::big) {
        swapped.assign(data, data + *count);
        byte_swap(swapped);
        data = swapped.data();
      }
      payload = std::as_bytes(std::span<const float>(data, *count));
    }
    return write_bytes_atomically(path, {std::as_bytes(std::span<const char>(prelude)), payload});
  } catch (const std::exception& e) {
    return io_error(
        std::string("cannot write ").append(quoted(path)).append(": ").append(e.what()));
  }
}

}  // namespace ocean::io
