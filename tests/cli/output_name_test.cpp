// The output-name rule of the ocean tool (apps/ocean/output_name.hpp): at most one frame-number
// field, %d or %0Nd with N from 1 to 18; %% a percent sign; every other % refused; names within
// the kernel's PATH_MAX and NAME_MAX. Expected names are written out by hand from the rule.
#include "output_name.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using ocean::cli::OutputPattern;
using ocean::cli::parse_output_pattern;

OutputPattern parsed(const std::string& name) {
  ocean::Result<OutputPattern> p = parse_output_pattern(name);
  EXPECT_TRUE(p.ok()) << name << ": " << p.status().message();
  return p.ok() ? p.value() : OutputPattern{};
}

std::string refusal(const std::string& name) {
  ocean::Result<OutputPattern> p = parse_output_pattern(name);
  EXPECT_FALSE(p.ok()) << name;
  EXPECT_EQ(p.status().code(), ocean::ErrorCode::invalid_argument) << name;
  return p.status().message();
}

TEST(OutputName, AFieldIsFilledWithTheFrameNumber) {
  const OutputPattern p = parsed("shot_%05d.png");
  EXPECT_TRUE(p.numbered);
  EXPECT_EQ(p.name_for(0), "shot_00000.png");
  EXPECT_EQ(p.name_for(42), "shot_00042.png");
  EXPECT_EQ(p.name_for(1234567), "shot_1234567.png");  // wider numbers are not cut
  EXPECT_EQ(p.name(), "shot_00000.png");               // a lone frame is frame 0
  EXPECT_EQ(parsed("%d.exr").name_for(7), "7.exr");
  EXPECT_EQ(parsed("%d.exr").name_for(1000000), "1000000.exr");
  EXPECT_EQ(parsed("a%01db.png").name_for(3), "a3b.png");
  EXPECT_EQ(parsed("%018d.png").name_for(5), "000000000000000005.png");
  EXPECT_EQ(parsed("dir_%03d/f.png").name_for(9), "dir_009/f.png");
}

TEST(OutputName, DoublePercentIsAPercentSign) {
  EXPECT_EQ(parsed("100%%.png").name(), "100%.png");
  EXPECT_EQ(parsed("100%%_%02d.png").name_for(4), "100%_04.png");
  EXPECT_EQ(parsed("%%d.png").name(), "%d.png");  // not a field
  EXPECT_EQ(parsed("%%s%%n.png").name_for(1), "%s%n_00001.png");
  EXPECT_EQ(parsed("%%%d.png").name_for(2), "%2.png");  // %% then a field
  EXPECT_FALSE(parsed("%%d.png").numbered);
}

TEST(OutputName, WithoutAFieldASequenceNumbersBeforeTheExtension) {
  const OutputPattern p = parsed("out/seq.png");
  EXPECT_FALSE(p.numbered);
  EXPECT_EQ(p.name(), "out/seq.png");
  EXPECT_EQ(p.name_for(0), "out/seq_00000.png");
  EXPECT_EQ(p.name_for(99999), "out/seq_99999.png");
  EXPECT_EQ(p.name_for(123456), "out/seq_123456.png");
  EXPECT_EQ(parsed("a.b/c.d.exr").name_for(3), "a.b/c.d_00003.exr");
  EXPECT_EQ(parsed("noext").name_for(1), "noext_00001");
}

TEST(OutputName, AnyBytesButPercentAreData) {
  for (const std::string name : {"it's.png", "say \"hi\".png", "$(touch x).png", "`id`;.png",
                                 "with space.png", "new\nline.png", "\xff\xfe.png", "\\n.png"}) {
    EXPECT_EQ(parsed(name).name(), name);
  }
  EXPECT_EQ(parsed("it's %d.png").name_for(1), "it's 1.png");
  EXPECT_EQ(parsed("\xff%02d\n.png").name_for(1),
            "\xff"
            "01\n.png");
}

TEST(OutputName, OtherConversionsAreRefusedNamingTheRule) {
  const std::string rule = "%d or %0Nd with N from 1 to 18";
  for (const std::string name :
       {"a%s.png", "a%n.png", "%x.png", "a%5d.png", "a%00d.png", "a%0d.png", "a%019d.png",
        "a%005d.png", "a%ld.png", "a%lld.png", "a%.3d.png", "a%-5d.png", "50%.png", "a%", "a%0",
        "a%05", "%\xff.png", "a%*d.png", "a%1$d.png"}) {
    const std::string message = refusal(name);
    EXPECT_NE(message.find("--out = '"), std::string::npos) << message;
    EXPECT_NE(message.find(rule), std::string::npos) << message;
    EXPECT_NE(message.find("%%"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_NE(refusal("a%s.png").find("'%s' is not a frame-number field"), std::string::npos);
  EXPECT_NE(refusal("a%019d.png").find("'%019d' is not"), std::string::npos);
  EXPECT_NE(refusal("%\xff.png").find("'%\\xff' is not"), std::string::npos);
  // The name is echoed as ocean::excerpt writes it: escapes, no newline.
  EXPECT_NE(refusal("new\nline%s.png").find("'new\\nline%s.png'"), std::string::npos);
}

TEST(OutputName, TwoFieldsAreRefused) {
  for (const std::string name : {"a%05d%05d.png", "%d_%d.png", "%d/%03d.png"}) {
    const std::string message = refusal(name);
    EXPECT_NE(message.find("has two frame-number fields"), std::string::npos) << message;
  }
}

TEST(OutputName, EmptyAndOverlongNamesAreRefusedShortly) {
  EXPECT_NE(refusal("").find("is empty"), std::string::npos);
  const std::string huge(100000, 'x');
  const std::string message = refusal(huge + ".png");
  EXPECT_NE(message.find("longer than 4095 bytes"), std::string::npos) << message.substr(0, 200);
  EXPECT_LT(message.size(), 300u);
  const std::string component = refusal("dir/" + std::string(256, 'y') + ".png");
  EXPECT_NE(component.find("longer than 255 bytes"), std::string::npos) << component;
  EXPECT_LT(component.size(), 300u);
  // At the limits: accepted.
  EXPECT_TRUE(parse_output_pattern(std::string(251, 'z') + ".png").ok());
  std::string deep;
  while (deep.size() + 100 <= 4095) deep += std::string(99, 'd') + "/";
  deep += std::string(4095 - deep.size() - 4, 'f') + ".png";
  ASSERT_EQ(deep.size(), 4095u);
  EXPECT_TRUE(parse_output_pattern(deep).ok());
}

TEST(OutputName, TheFlagIsNamed) {
  ocean::Result<OutputPattern> p = parse_output_pattern("a%s.png", "--contact-sheet");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.status().message().rfind("--contact-sheet = 'a%s.png'", 0), 0u)
      << p.status().message();
  EXPECT_TRUE(ocean::cli::check_output_name("--plot", "p%s.png").ok());  // not a pattern
  EXPECT_FALSE(ocean::cli::check_output_name("--plot", "").ok());
  EXPECT_FALSE(ocean::cli::check_output_name("--plot", std::string(5000, 'p')).ok());
}

}  // namespace
