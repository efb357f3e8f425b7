// Fuzz target: output names typed by a user (apps/ocean/output_name.hpp), the input being the
// name. check_output_name and parse_output_pattern give a value or a one-line error, never a
// crash, UB or a leak. An accepted pattern names every frame differently (a sequence never
// writes two frames to one file), a name without `%` is read as itself, and a lone file's name is
// frame 0's.
#include <climits>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "expect.hpp"
#include "output_name.hpp"

namespace {

using ocean::fuzz::expect;

constexpr long long kFrames[] = {0, 1, 9, 10, 99999, 100000, LLONG_MAX};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view name(reinterpret_cast<const char*>(data), size);
  const ocean::Status checked = ocean::cli::check_output_name("--out", name);
  ocean::fuzz::expect_one_line(checked, "check_output_name");
  const ocean::Result<ocean::cli::OutputPattern> pattern = ocean::cli::parse_output_pattern(name);
  if (!pattern.ok()) {
    ocean::fuzz::expect_one_line(pattern.status(), "parse_output_pattern");
    return 0;
  }
  const ocean::cli::OutputPattern& p = pattern.value();
  expect(checked.ok(), "parse_output_pattern accepted a name check_output_name refuses");
  if (name.find('%') == std::string_view::npos)
    expect(!p.numbered && p.head == name && p.name() == name, "a name without % was changed");
  expect(!p.numbered || p.name() == p.name_for(0), "a numbered name is not frame 0's");
  for (long long a : kFrames) {
    for (long long b : kFrames) {
      if (a < b) expect(p.name_for(a) != p.name_for(b), "two frames share a file name");
    }
  }
  return 0;
}
