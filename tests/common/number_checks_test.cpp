// The command line's numbers: what CLI11's own checks let through (NaN passes every comparison)
// is refused by name, with what the option wants.

#include "common/number_checks.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

namespace number_checks_test {

using testing::HasSubstr;

/// The error parsing `--x value` with `check` gives ("" when it parses), and the value read.
std::string parse(const CLI::Validator& check, const std::string& value, double* read = nullptr) {
  CLI::App app;
  double x = -1.0;
  app.add_option("--x", x)->check(check);
  std::vector<std::string> args{value, "--x"};  // CLI11 takes them last first
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  if (read != nullptr) *read = x;
  return "";
}

TEST(CommandLineNumbers, NanInfinityAndWhatIsNotANumberAreRefusedWithWhatTheOptionWants) {
  for (const char* bad : {"nan", "NaN", "-nan", "inf", "-inf", "1e999", "5abc", "", "0x"}) {
    EXPECT_THAT(parse(common::kFiniteNonNegative, bad), HasSubstr("a finite number >= 0")) << bad;
    EXPECT_THAT(parse(common::kFinitePositive, bad), HasSubstr("a finite number > 0")) << bad;
    EXPECT_THAT(parse(common::finiteWithin(1e-6, 0.1), bad),
                HasSubstr("a finite number in [1e-06, 0.1]"))
        << bad;
    EXPECT_THAT(parse(common::kFinite, bad), HasSubstr("is not a finite number")) << bad;
  }
  EXPECT_THAT(parse(common::kFinitePositive, "0"), HasSubstr("'0' is not a finite number > 0"));
  EXPECT_NE(parse(common::kFiniteNonNegative, "-1e-300"), "");
  EXPECT_NE(parse(common::finiteWithin(1e-6, 0.1), "0.1000001"), "");
}

TEST(CommandLineNumbers, AFiniteNumberWithinItsBoundsIsReadAsWritten) {
  double read = 0.0;
  EXPECT_EQ(parse(common::kFiniteNonNegative, "0", &read), "");
  EXPECT_EQ(read, 0.0);
  EXPECT_EQ(parse(common::kFinitePositive, "2.5e-3", &read), "");
  EXPECT_EQ(read, 2.5e-3);
  EXPECT_EQ(parse(common::finiteWithin(1e-6, 0.1), "0.1", &read), "");
  EXPECT_EQ(read, 0.1);
  EXPECT_EQ(parse(common::kFinite, "-1e300", &read), "");
  EXPECT_EQ(read, -1e300);
}

}  // namespace number_checks_test
