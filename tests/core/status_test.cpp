// Status/Result and the parameter-validation helpers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ocean/core.hpp"

namespace {

TEST(Status, DefaultIsOk) {
  const ocean::Status s;
  EXPECT_TRUE(s.ok());
  EXPECT_EQ(s.code(), ocean::ErrorCode::ok);
  EXPECT_TRUE(s.message().empty());
}

TEST(Result, HoldsValueOrStatus) {
  const ocean::Result<int> good = 3;
  ASSERT_TRUE(good.ok());
  EXPECT_EQ(good.value(), 3);
  EXPECT_TRUE(good.status().ok());
  const ocean::Result<int> bad = ocean::invalid_argument("x = 1 is out of range");
  EXPECT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().code(), ocean::ErrorCode::invalid_argument);
}

TEST(Validation, MessagesNameParameterValueAndRange) {
  const ocean::Status s = ocean::require_positive("wind_speed_mps", -3.0);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(), "wind_speed_mps = -3 is out of range: must be > 0 and finite");
  const ocean::Status r = ocean::require_in_range("alpha", 1.5, 0.0, 1.0);
  EXPECT_EQ(r.message(), "alpha = 1.5 is out of range: must be in [0, 1]");
}

TEST(Validation, RejectsNaNAndInfinity) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(ocean::require_positive("x", nan).ok());
  EXPECT_FALSE(ocean::require_positive("x", inf).ok());
  EXPECT_FALSE(ocean::require_non_negative("x", nan).ok());
  EXPECT_FALSE(ocean::require_in_range("x", nan, 0, 1).ok());
  EXPECT_FALSE(ocean::require_finite("x", inf).ok());
  EXPECT_TRUE(ocean::require_non_negative("x", 0.0).ok());
  EXPECT_TRUE(ocean::require_in_range("x", 1.0, 0, 1).ok());
  EXPECT_NE(ocean::require_positive("x", nan).message().find("nan"), std::string::npos);
}

TEST(FormatNumber, ShortestRoundTrip) {
  EXPECT_EQ(ocean::format_number(0.1), "0.1");
  EXPECT_EQ(ocean::format_number(-3.0), "-3");
  EXPECT_EQ(ocean::format_number(std::numeric_limits<double>::infinity()), "inf");
}

}  // namespace

TEST(Excerpt, ShortPrintableTextComesBackAsItIs) {
  EXPECT_EQ(ocean::excerpt("calm"), "calm");
  EXPECT_EQ(ocean::excerpt("mer calme, 19.47°"), "mer calme, 19.47°");  // UTF-8 kept
}

TEST(Excerpt, ControlBytesInvalidUtf8AndBackslashesAreEscaped) {
  EXPECT_EQ(ocean::excerpt("a\nb\tc\\d"), "a\\nb\\tc\\\\d");
  EXPECT_EQ(ocean::excerpt(std::string("x\0y", 3)), "x\\x00y");
  EXPECT_EQ(ocean::excerpt("\xff\xfe"), "\\xff\\xfe");
  EXPECT_EQ(ocean::excerpt("\xc0\xaf"), "\\xc0\\xaf");          // overlong '/'
  EXPECT_EQ(ocean::excerpt("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a UTF-16 surrogate
  EXPECT_EQ(ocean::excerpt("\xe2\x82"), "\\xe2\\x82");          // cut sequence
}

TEST(Excerpt, LongTextIsCutOnACharacterBoundaryAndSaysHowLongItWas) {
  const std::string huge(300'000'000, 'w');
  const std::string shown = ocean::excerpt(huge);
  EXPECT_EQ(shown, std::string(80, 'w') + "... (300000000 bytes)");
  // "é" is two bytes: a cut between them would leave half a character.
  std::string accents;
  for (int i = 0; i < 50; ++i) accents += "\xc3\xa9";
  const std::string cut = ocean::excerpt(accents, 5);
  EXPECT_EQ(cut, "\xc3\xa9\xc3\xa9... (100 bytes)");
}
