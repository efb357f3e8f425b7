// Fuzz target: the PNG reader of the tests (tests/support/png_reader.hpp), on any bytes.
// An image it accepts has width*height*channels samples, each within its bit depth; anything
// else is an error, never a crash or a leak (libpng's longjmp error path included).
#include <cstddef>
#include <cstdint>

#include "expect.hpp"
#include "memory_file.hpp"
#include "support/png_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto image = ocean::fuzz::read_as_file(data, size, ocean::io::read_png);
  if (!image.ok()) return 0;
  const ocean::io::PngImage& png = image.value();
  using ocean::fuzz::expect;
  expect(png.width > 0 && png.height > 0, "png: empty image accepted");
  expect(png.channels >= 1 && png.channels <= 4, "png: channels outside 1..4");
  expect(png.bit_depth == 8 || png.bit_depth == 16, "png: bit depth neither 8 nor 16");
  const std::size_t count = static_cast<std::size_t>(png.width) *
                            static_cast<std::size_t>(png.height) *
                            static_cast<std::size_t>(png.channels);
  expect(png.samples.size() == count, "png: samples != width*height*channels");
  const std::uint32_t limit = 1u << png.bit_depth;
  for (std::uint16_t s : png.samples) expect(s < limit, "png: sample beyond its bit depth");
  return 0;
}
