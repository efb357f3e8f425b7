// Fuzz target: a preset document and `--set` overrides (src/preset, ocean/preset.hpp).
//
// Input: the JSON document, then optionally a line "--set" and one key=value assignment per
// line after it (empty lines skipped):
//     {"resolution": 64, "sea": {"wind_sea": {"fetch_m": 5e4}}}
//     --set
//     sea.wind_sea.model=tma
// The document goes through from_json and, as a file, through Document::merge_preset; the
// assignments through Document::set; then Document::config. Each returns a value or a one-line
// error and never crashes, throws or leaks. A configuration read back is written again: to_json →
// from_json round-trips it exactly (the header's promise).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "expect.hpp"
#include "memory_file.hpp"
#include "ocean/preset.hpp"

namespace {

using ocean::SimulationConfig;
using ocean::fuzz::expect;

constexpr std::string_view kSetLine = "--set";

// The document and the assignment lines of an input.
struct Input {
  std::string_view document;
  std::vector<std::string_view> assignments;
};

Input split(std::string_view text) {
  Input in{.document = text, .assignments = {}};
  std::size_t line = 0;
  while (line <= text.size()) {
    const std::size_t end = std::min(text.find('\n', line), text.size());
    const std::string_view current = text.substr(line, end - line);
    if (in.document.size() != text.size()) {
      if (!current.empty()) in.assignments.push_back(current);
    } else if (current == kSetLine) {
      in.document = text.substr(0, line);
    }
    line = end + 1;
  }
  return in;
}

// Whether the call succeeded; a refusal is one line.
bool accepted(const ocean::Status& status, const char* call) {
  ocean::fuzz::expect_one_line(status, call);
  return status.ok();
}
template <class T>
bool accepted(const ocean::Result<T>& result, const char* call) {
  return accepted(result.ok() ? ocean::Status() : result.status(), call);
}

// A configuration that was read back must be written and read again unchanged.
void expect_round_trip(const SimulationConfig& config, std::string_view where) {
  const std::string written = ocean::preset::to_json(config);
  ocean::Result<SimulationConfig> again = ocean::preset::from_json(written);
  expect(again.ok(), std::string(where) + ": to_json output rejected: " +
                         (again.ok() ? "" : again.status().message()) + "\n" + written);
  expect(ocean::preset::to_json(again.value()) == written,
         std::string(where) + ": to_json → from_json changed the document\n" + written);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Input in = split(std::string_view(reinterpret_cast<const char*>(data), size));

  ocean::Result<SimulationConfig> direct = ocean::preset::from_json(in.document);
  if (accepted(direct, "from_json")) expect_round_trip(direct.value(), "from_json");

  const ocean::fuzz::MemoryFile file(reinterpret_cast<const std::uint8_t*>(in.document.data()),
                                     in.document.size());
  ocean::preset::Document document;
  if (!accepted(document.merge_preset(file.path().string(), "--preset"), "merge_preset")) return 0;
  for (std::string_view assignment : in.assignments) {
    if (!accepted(document.set(assignment, "--set"), "Document::set")) return 0;
  }
  ocean::Result<SimulationConfig> layered = document.config();
  if (accepted(layered, "Document::config")) expect_round_trip(layered.value(), "Document::config");
  return 0;
}
