// raven_analyze forces on the robot's own recordings: the columns the twin's cf file has, the
// figure, the jaws' squeeze where they close on each other, and a truth file that does not pair.

#include "analysis/force_report.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "recording/cf_recording.hpp"
#include "recording/recording_io.hpp"
#include "test_files.hpp"

namespace {

std::filesystem::path physicalTrial() {
  const auto shared = test_support::sharedDataDir();
  return shared.empty() ? shared : shared / "recordings/paper_2arm/2arm_physical_1.csv";
}

/// `call` must throw std::invalid_argument saying `says` (a file's name and what is wrong).
template <typename Call>
void expectRefusal(const Call& call, const std::string& says) {
  try {
    call();
    ADD_FAILURE() << "not refused: " << says;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
  }
}

TEST(RavenAnalyzeForces, WritesTheCfColumnsWithTheirSdAndAFigure) {
  const auto trial = physicalTrial();
  if (trial.empty()) GTEST_SKIP() << "../shared/data is absent: the robot's recordings are needed";
  test_support::TempDir dir;
  const std::string command =
      fmt::format("{} forces {} --out {} > {} 2>&1", RAVEN_ANALYZE, trial.string(),
                  dir.path().string(), (dir.path() / "log").string());
  ASSERT_EQ(std::system(command.c_str()), 0) << test_support::readFile(dir.path() / "log");
  std::ifstream csv(dir.path() / "forces.csv");
  std::string header;
  std::getline(csv, header);
  for (const char* column : {"time,left_fx,", "left_jaw2_normal,", "right_jaw1_normal_sd"}) {
    EXPECT_NE(header.find(column), std::string::npos) << column << " in " << header;
  }
  // Every estimate's name is a cf column: they line up column by column.
  for (const auto& name :
       analysis::estimateForces(trial, twin::CalibrationProfile::shipped(), {}).names) {
    if (name.ends_with("_sd") || name.ends_with("_opening")) continue;
    const auto& cf = recording::CfWriter::columnNames();
    EXPECT_NE(std::find(cf.begin(), cf.end(), name), cf.end()) << name;
  }
  EXPECT_GT(std::filesystem::file_size(dir.path() / "forces.png"), 1000u);
  EXPECT_NE(test_support::readFile(dir.path() / "log").find("right_jaw2_normal"),
            std::string::npos);
}

TEST(RavenAnalyzeForces, JawsClosedPastMeetingSqueezeEachOther) {
  // The robot's grasps close the jaws past their meeting (an opening below 0): they press on
  // each other there, and the estimate says so on both. Opened, they touch nothing: there the
  // estimate's band is finite and wide (the jaws' friction; docs/forces.md says how far from
  // zero the means lie).
  const auto trial = physicalTrial();
  if (trial.empty()) GTEST_SKIP() << "../shared/data is absent: the robot's recordings are needed";
  const auto rs = recording::readRs(trial, recording::NonFiniteJoints::Keep);
  const auto table = analysis::estimateForces(trial, twin::CalibrationProfile::shipped(), {});
  const std::size_t jaw1 = table.column("right_jaw1_normal"),
                    jaw2 = table.column("right_jaw2_normal");
  const std::size_t sd1 = table.column("right_jaw1_normal_sd");
  double closed_sum = 0.0, open_sum = 0.0, open_sd = 0.0;
  int closed = 0, open = 0;
  for (std::size_t r = 0; r < rs.rows.size(); ++r) {
    const auto q = rs.joints(r, raven::Arm::Right);
    const double opening = q(raven::kJaw1) + q(raven::kJaw2);
    if (opening < 0.0) {
      closed_sum += 0.5 * (table.rows[r][jaw1] + table.rows[r][jaw2]);
      ++closed;
    } else if (opening > 0.9) {
      open_sum += table.rows[r][jaw1];
      open_sd += table.rows[r][sd1];
      ++open;
    }
  }
  ASSERT_GT(closed, 20);
  ASSERT_GT(open, 20);
  EXPECT_GT(closed_sum / closed, 3.0) << "N per jaw, closed on each other";
  EXPECT_TRUE(std::isfinite(open_sum));
  EXPECT_GT(open_sd / open, 0.5) << "N: a jaw at rest is known to its friction band";
}

TEST(RavenAnalyzeForces, InTheRobotsFreeMotionEveryChannelIsWithinTwoSdOfZero) {
  // Issue 65, acceptance 3: the 2arm trials move in free space. Where an arm's jaws are apart
  // (not on each other), nothing pushes on its tool or jaws: each channel's mean estimate lies
  // within 2 of its mean sd of zero, on every trial.
  const auto trial = physicalTrial();
  if (trial.empty()) GTEST_SKIP() << "../shared/data is absent: the robot's recordings are needed";
  for (const char* name : {"2arm_physical_1.csv", "2arm_physical_2.csv", "2arm_physical_3.csv"}) {
    const auto table = analysis::estimateForces(trial.parent_path() / name,
                                                twin::CalibrationProfile::shipped(), {});
    for (const auto& c : analysis::summarise({{table, std::nullopt}})) {
      EXPECT_GT(c.apart_rows, 900u) << name << " " << c.name;
      EXPECT_LE(std::abs(c.apart_mean), 2.0 * c.apart_sd) << name << " " << c.name;
    }
  }
}

TEST(RavenAnalyzeForces, ARecordingWithoutMotorSignalsIsRefusedNamingIt) {
  // AMBF logs joints only: nothing to read forces from, said so rather than a table of zeros.
  const auto trial = physicalTrial();
  if (trial.empty()) GTEST_SKIP() << "../shared/data is absent: the robot's recordings are needed";
  const auto ambf = trial.parent_path() / "2arm_ambf_1.csv";
  expectRefusal([&] { analysis::estimateForces(ambf, twin::CalibrationProfile::shipped(), {}); },
                "2arm_ambf_1.csv: no row has the motor signals");
}

TEST(RavenAnalyzeForces, ARecordingWhoseTimeRunsBackIsRefusedNamingTheRow) {
  // The motor speeds come from the rows around each row in time: a clock running back is
  // refused by row; one standing still costs no more than one that runs (windows are bounded).
  const auto trial = physicalTrial();
  if (trial.empty()) GTEST_SKIP() << "../shared/data is absent: the robot's recordings are needed";
  const auto rs = recording::readRs(trial, recording::NonFiniteJoints::Keep);
  const std::size_t time = rs.column("time");
  test_support::TempDir dir;
  const auto write = [&](const std::string& name, const auto& timeOf) {
    std::ofstream out(dir.path() / name);
    for (std::size_t c = 0; c < rs.names.size(); ++c) out << (c ? "," : "") << rs.names[c];
    out << "\n";
    for (std::size_t r = 0; r < rs.rows.size(); ++r) {
      for (std::size_t c = 0; c < rs.names.size(); ++c) {
        out << (c ? "," : "") << fmt::format("{}", c == time ? timeOf(r) : rs.rows[r][c]);
      }
      out << "\n";
    }
    return dir.path() / name;
  };
  const auto back =
      write("back_rs.csv", [&](std::size_t r) { return r == 700 ? 0.0 : rs.rows[r][time]; });
  // Row 700 from 0 is data row 701, as the disparity analysis counts them.
  expectRefusal([&] { analysis::estimateForces(back, twin::CalibrationProfile::shipped(), {}); },
                "back_rs.csv: data row 701: time 0.000000 s comes before the row before it");
  const auto still = write("still_rs.csv", [](std::size_t) { return 0.0; });
  const auto table = analysis::estimateForces(still, twin::CalibrationProfile::shipped(), {});
  EXPECT_EQ(table.rows.size(), rs.rows.size());
}

TEST(RavenAnalyzeForces, TheSummaryPoolsRunsAndCountsEstimatesWithin25PercentOfTheirTruth) {
  // A cf file whose left jaw 1 presses 1.2 times the estimate's size: an estimate above zero is
  // 17 % under it (within 25 %), one below zero is 2.2 times its size off (within only under the
  // 0.15 N floor); two runs of it pool row by row.
  const auto trial = physicalTrial();
  if (trial.empty()) GTEST_SKIP() << "../shared/data is absent: the robot's recordings are needed";
  const auto table = analysis::estimateForces(trial, twin::CalibrationProfile::shipped(), {});
  const std::size_t jaw = table.column("left_jaw1_normal");
  test_support::TempDir dir;
  const auto cf = dir.path() / "scaled_cf.csv";
  std::size_t touching = 0, within = 0;
  {
    recording::CfWriter writer(cf);
    for (const auto& row : table.rows) {
      bridge::GrasperForces left;
      const double truth = std::isfinite(row[jaw]) ? 1.2 * std::abs(row[jaw]) : 0.0;
      left.jaws[0].normal = Eigen::Vector3d(truth, 0.0, 0.0);
      writer.write(row[0], {left, std::nullopt});
      if (truth > 0.05) {
        ++touching;
        within += row[jaw] > 0.0 || 2.2 * std::abs(row[jaw]) <= 0.15;
      }
    }
  }
  const auto one = analysis::summarise({{table, cf}});
  const auto two = analysis::summarise({{table, cf}, {table, cf}});
  ASSERT_EQ(one[3].name, "left_jaw1_normal");
  ASSERT_GT(touching, 100u);
  EXPECT_EQ(one[3].truth_rows, touching);
  EXPECT_DOUBLE_EQ(*one[3].within_25_percent,
                   static_cast<double>(within) / static_cast<double>(touching));
  EXPECT_EQ(two[3].truth_rows, 2 * touching);
  EXPECT_EQ(two[3].rows, 2 * one[3].rows);
  EXPECT_DOUBLE_EQ(*two[3].within_25_percent, *one[3].within_25_percent);
  EXPECT_NEAR(two[3].mean, one[3].mean, 1e-12);
}

TEST(RavenAnalyzeForces, ATruthFileOfAnotherRunIsRefusedNamingIt) {
  const auto trial = physicalTrial();
  if (trial.empty()) GTEST_SKIP() << "../shared/data is absent: the robot's recordings are needed";
  test_support::TempDir dir;
  const auto cf = dir.path() / "short_cf.csv";
  {
    recording::CfWriter writer(cf);
    writer.write(0.0, {std::nullopt, std::nullopt});
  }
  const auto table = analysis::estimateForces(trial, twin::CalibrationProfile::shipped(), {});
  expectRefusal(
      [&] {
        analysis::summarise({{table, cf}});
      },
      "short_cf.csv: 1 rows where the recording has 1351");
}

}  // namespace
