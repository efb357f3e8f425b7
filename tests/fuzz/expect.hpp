// The fuzz targets' own checks: a property of the code under test that does not hold for an
// input stops the run like a sanitizer report, and libFuzzer saves the input as a crash artifact.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

#include "ocean/core.hpp"

namespace ocean::fuzz {

/// Aborts with "fuzz: expectation failed: <what>" on stderr unless `holds`.
inline void expect(bool holds, const std::string& what) {
  if (holds) return;
  std::fprintf(stderr, "fuzz: expectation failed: %s\n", what.c_str());
  std::abort();
}

/// An error message is one line (the tool prints it as "ocean: error: <message>"): a user's
/// text is echoed through ocean::excerpt, which writes control characters as escapes.
inline void expect_one_line(const Status& status, const std::string& where) {
  expect(status.message().find_first_of("\n\r") == std::string::npos,
         where + ": message of more than one line: " + excerpt(status.message(), 400));
}

}  // namespace ocean::fuzz
