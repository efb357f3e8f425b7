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
