// The compute kernels as SPIR-V words, compiled from shaders/*.comp by glslc at build time and
// embedded by cmake/EmbedSpirv.cmake (one generated .cpp per shader).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

extern const std::uint32_t ocean_spv_fft_rows[];
extern const std::size_t ocean_spv_fft_rows_words;
extern const std::uint32_t ocean_spv_fft_columns[];
extern const std::size_t ocean_spv_fft_columns_words;
extern const std::uint32_t ocean_spv_finalize[];
extern const std::size_t ocean_spv_finalize_words;
extern const std::uint32_t ocean_spv_far_noise[];
extern const std::size_t ocean_spv_far_noise_words;
extern const std::uint32_t ocean_spv_mips[];
extern const std::size_t ocean_spv_mips_words;

namespace ocean::vk::spirv {
inline std::span<const std::uint32_t> fft_rows() {
  return {ocean_spv_fft_rows, ocean_spv_fft_rows_words};
}
inline std::span<const std::uint32_t> fft_columns() {
  return {ocean_spv_fft_columns, ocean_spv_fft_columns_words};
}
inline std::span<const std::uint32_t> finalize() {
  return {ocean_spv_finalize, ocean_spv_finalize_words};
}
inline std::span<const std::uint32_t> far_noise() {
  return {ocean_spv_far_noise, ocean_spv_far_noise_words};
}
inline std::span<const std::uint32_t> mips() { return {ocean_spv_mips, ocean_spv_mips_words}; }
}  // namespace ocean::vk::spirv
