// Platform profiles carry every value of the paper's Table II and reject bad files clearly.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "raven/platform_profile.hpp"
#include "test_files.hpp"

namespace {

using testing::HasSubstr;

TEST(PlatformProfile, TableTwoValues) {
  const auto p = raven::builtinProfile("physical");
  const auto s = raven::builtinProfile("ambf");
  EXPECT_EQ(p.arm(raven::Arm::Left).d4, -0.47);
  EXPECT_EQ(s.arm(raven::Arm::Left).d4, 0.0);
  EXPECT_NEAR(p.home(0), M_PI / 6, 1e-15);
  EXPECT_NEAR(s.home(0), 7 * M_PI / 36, 1e-15);
  EXPECT_EQ(p.home(2), 0.4);
  EXPECT_EQ(s.home(2), -0.07);
  EXPECT_EQ(p.limits.low(2), 0.23);
  EXPECT_EQ(p.limits.high(2), 0.56);
  EXPECT_EQ(s.limits.low(2), -0.23);
  EXPECT_EQ(s.limits.high(2), 0.10);
  for (auto arm : raven::kArms) {
    EXPECT_NEAR(p.arm(arm).alpha[4], M_PI / 2, 1e-15);
    EXPECT_NEAR(s.arm(arm).alpha[4], M_PI, 1e-15);
  }
  EXPECT_TRUE(p.firmware_kinematics.has_value());
  EXPECT_FALSE(s.firmware_kinematics.has_value());
}

TEST(PlatformProfile, BadFilesNameTheKey) {
  test_support::TempDir dir;
  std::string text = test_support::readFile(raven::profileDirectory() / "physical.yaml");
  text.replace(text.find("tool_length: 0.013"), 18, "tool_lenght: 0.013");
  const auto typo = dir.write("typo.yaml", text);
  EXPECT_THAT(test_support::loadErrorOf([&] { raven::loadPlatformProfile(typo); }),
              testing::AllOf(HasSubstr("typo.yaml:"), HasSubstr("kinematics/tool_lenght"),
                             HasSubstr("did you mean 'tool_length'")));

  text = test_support::readFile(raven::profileDirectory() / "physical.yaml");
  text.replace(text.find("low:  [0, 0.785"), 15, "low:  [2.0, 0.785");
  const auto inverted = dir.write("inverted.yaml", text);
  EXPECT_THAT(test_support::loadErrorOf([&] { raven::loadPlatformProfile(inverted); }),
              HasSubstr("low > high for joint shoulder"));
}

}  // namespace
