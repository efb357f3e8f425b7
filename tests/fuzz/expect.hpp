// The fuzz targets' own checks: a property of the code under test that does not hold for an
// input stops the run like a sanitizer report, and libFuzzer saves the input as a crash artifact.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace ocean::fuzz {

/// Aborts with "fuzz: expectation failed: <what>" on stderr unless `holds`.
inline void expect(bool holds, const std::string& what) {
  if (holds) return;
  std::fprintf(stderr, "fuzz: expectation failed: %s\n", what.c_str());
  std::abort();
}

}  // namespace ocean::fuzz
