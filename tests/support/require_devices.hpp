// Tests that need a Vulkan device or a display skip where the machine has none, so that the suite
// passes on any developer's machine; a machine that is meant to have them (CI installs lavapipe
// and Xvfb) sets OCEAN_REQUIRE_DEVICES=1, and then each such skip is a failure instead: a broken
// driver or a missing package cannot pass unnoticed as a row of skipped tests.
//
//   if (!have_device()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
//
// Use it for a missing device or display only; other skips (one hardware thread, ...) stay
// GTEST_SKIP. Like GTEST_SKIP and GTEST_FAIL it returns from the calling function, which must
// return void (a test body, SetUp, or a helper called through ASSERT_NO_FATAL_FAILURE).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <string_view>

namespace ocean_test {

/// Whether OCEAN_REQUIRE_DEVICES is set to a value other than "" and "0".
inline bool devices_required() {
  const char* v = std::getenv("OCEAN_REQUIRE_DEVICES");
  return v != nullptr && std::string_view(v) != "" && std::string_view(v) != "0";
}

}  // namespace ocean_test

/// Skips the test with `reason` (a std::string or string literal), or fails it when
/// OCEAN_REQUIRE_DEVICES=1.
#define OCEAN_SKIP_OR_FAIL(reason)                                                         \
  do {                                                                                     \
    if (::ocean_test::devices_required())                                                  \
      GTEST_FAIL() << "OCEAN_REQUIRE_DEVICES is set, and a device or display is missing: " \
                   << std::string(reason);                                                 \
    GTEST_SKIP() << std::string(reason);                                                   \
  } while (false)
