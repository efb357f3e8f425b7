// Fuzz target: the .npy reader of the tests (tests/support/npy_reader.hpp), on any bytes.
// A file it accepts holds exactly product(shape) values; anything else is an error, never a
// crash, a leak or an allocation larger than the file allows.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numeric>

#include "expect.hpp"
#include "memory_file.hpp"
#include "support/npy_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto array = ocean::fuzz::read_as_file(data, size, ocean::io::read_npy);
  if (!array.ok()) return 0;
  const std::vector<std::size_t>& shape = array.value().shape;
  const std::size_t count =
      std::accumulate(shape.begin(), shape.end(), std::size_t{1}, std::multiplies<>());
  ocean::fuzz::expect(array.value().data.size() == count, "npy: data size != product(shape)");
  ocean::fuzz::expect(count * sizeof(float) <= size, "npy: more values than the file holds");
  return 0;
}
