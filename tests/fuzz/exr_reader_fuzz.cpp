// Fuzz target: the OpenEXR reader read_exr (ocean/io.hpp), on any bytes.
// An image it accepts has one width*height plane per named channel; anything else is an error
// (OpenEXR's exceptions included), never a crash or a leak.
//
// OpenEXR sizes its line and tile buffers from the header's data window and tile size before it
// reads any pixel, so a few hundred bytes can make it allocate a gigabyte, which is legitimate
// for an image that large but leaves the fuzzer spending seconds per input in the allocator.
// The target sets OpenEXR's limits for untrusted files (Header::setMaxImageSize,
// setMaxTileSize) below the reader's own (kExrMaxDimension, 1 GiB of samples): larger images
// are refused by OpenEXR's header check, and every input runs in milliseconds.
#include <ImfHeader.h>

#include <cstddef>
#include <cstdint>

#include "expect.hpp"
#include "memory_file.hpp"
#include "support/exr_reader.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  Imf::Header::setMaxImageSize(1024, 1024);
  Imf::Header::setMaxTileSize(256, 256);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto image = ocean::fuzz::read_as_file(data, size, ocean::io::read_exr);
  if (!image.ok()) return 0;
  const ocean::io::ExrImage& exr = image.value();
  using ocean::fuzz::expect;
  expect(exr.width > 0 && exr.height > 0, "exr: empty image accepted");
  expect(exr.planes.size() == exr.channel_names.size() &&
             exr.pixel_types.size() == exr.channel_names.size(),
         "exr: channel names, types and planes disagree");
  const std::size_t count =
      static_cast<std::size_t>(exr.width) * static_cast<std::size_t>(exr.height);
  for (const std::vector<float>& plane : exr.planes)
    expect(plane.size() == count, "exr: plane size != width*height");
  return 0;
}
