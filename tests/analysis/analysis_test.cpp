// The disparity analysis: the reference table reproduced from the paper's recordings, per-joint
// metrics on recordings with known differences, LOWESS and correlations, malformed files, and
// raven_analyze end to end with our twin as a third platform.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "analysis/factors.hpp"
#include "analysis/lowess.hpp"
#include "analysis/metrics.hpp"
#include "analysis/report.hpp"
#include "analysis/trial_set.hpp"
#include "common/load_error.hpp"
#include "recording/cf_recording.hpp"
#include "recording/recording_io.hpp"
#include "test_files.hpp"

namespace {

using analysis::Quantity;

std::vector<analysis::RecordingSource> defaultProfiles() {
  return analysis::readRecordingSources(analysis::defaultRecordingSourcesFile());
}

/// Writes an rs file of `rows` rows, 50 Hz, whose jpos column c is value(row, c) (rad, m).
template <typename Value>
std::filesystem::path writeRs(const test_support::TempDir& dir, const std::string& name, int rows,
                              Value value) {
  const auto path = dir.path() / name;
  recording::RsWriter writer(path);
  for (int r = 0; r < rows; ++r) {
    bridge::RavenStateSnapshot s;
    s.time = 0.02 * r;
    for (int c = 0; c < analysis::kJointColumns; ++c) {
      s.jpos[static_cast<std::size_t>(c)] = static_cast<float>(value(r, c) * 180.0 / M_PI);
    }
    writer.write(s);
  }
  return path;
}

/// Writes an rs file with one row per entry of `times` (s), every joint at 0.1 rad.
std::filesystem::path writeRsAt(const test_support::TempDir& dir, const std::string& name,
                                const std::vector<double>& times) {
  const auto path = dir.path() / name;
  recording::RsWriter writer(path);
  for (double t : times) {
    bridge::RavenStateSnapshot s;
    s.time = t;
    s.jpos.fill(static_cast<float>(0.1 * 180.0 / M_PI));
    writer.write(s);
  }
  return path;
}

std::string rounded(double value, int decimals) {
  return fmt::format("{:.{}f}", value, decimals);
}

TEST(Analysis, ReproducesEveryFigureOfTheReferenceTable) {
  const auto shared = test_support::sharedDataDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent: the paper's recordings are needed";
  const auto set = analysis::loadTrials({shared / "recordings/paper_2arm"}, defaultProfiles());
  for (const auto& issue : set.issues) ADD_FAILURE() << issue.path << ": " << issue.reason;
  const auto* ambf = set.find("ambf");
  const auto* physical = set.find("physical");
  ASSERT_TRUE(ambf && physical);
  ASSERT_EQ(ambf->trials.size(), 3u);
  ASSERT_EQ(physical->trials.size(), 3u);
  const analysis::Comparison ss{ambf, ambf}, pp{physical, physical}, ps{ambf, physical};
  EXPECT_EQ(ss.symbol(), "T_SS");
  EXPECT_EQ(pp.symbol(), "T_PP");
  EXPECT_EQ(ps.symbol(), "T_PS");
  const auto rev = analysis::revoluteJoints();
  const auto pri = analysis::prismaticJoints();
  const auto p = Quantity::Position;
  // ../shared/reference/recordings.md, as printed there (rad to 4 decimals, mm to 2).
  EXPECT_EQ(rounded(analysis::groupFigure(ss, rev, p, false), 4), "0.0006");
  EXPECT_EQ(rounded(analysis::groupFigure(ss, pri, p, false), 2), "1.73");
  EXPECT_EQ(rounded(analysis::groupFigure(pp, rev, p, false), 4), "0.0135");
  EXPECT_EQ(rounded(analysis::groupFigure(pp, pri, p, false), 2), "1.40");
  EXPECT_EQ(rounded(analysis::groupFigure(ps, rev, p, false), 4), "0.0218");
  EXPECT_EQ(rounded(analysis::groupFigure(ps, pri, p, false), 2), "11.27");
  EXPECT_EQ(rounded(analysis::groupFigure(ps, rev, p, true), 4), "0.0248");
  EXPECT_EQ(rounded(analysis::groupFigure(ps, pri, p, true), 2), "2.12");
}

TEST(Analysis, TheAmbfProfileAlignsTheRollSoItCanBeCompared) {
  const auto shared = test_support::sharedDataDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent: the paper's recordings are needed";
  const auto set = analysis::loadTrials({shared / "recordings/paper_2arm"}, defaultProfiles());
  const analysis::Comparison ps{set.find("ambf"), set.find("physical")};
  // Recorded, AMBF's roll reads -pi where the robot's reads 0; with the profile's offset the
  // two rolls differ by the robot's own motion (tenths of a radian), not by pi.
  for (int roll : {4, 12}) {
    const auto stats = analysis::jointStats(ps, Quantity::Position, roll, false);
    EXPECT_LT(stats.mean_abs, 0.3) << "jpos" << roll;
  }
}

TEST(Analysis, PerJointStatisticsOfAKnownDifference) {
  test_support::TempDir dir;
  auto base = [](int r, int c) { return 0.1 * c + 0.001 * r; };
  const auto a = writeRs(dir, "a_physical_rs.csv", 200, base);
  // b: jpos0 0.01 rad higher everywhere, jpos2 (insertion) 0.002 m higher after row 100.
  const auto b = writeRs(dir, "b_physical_rs.csv", 200, [&](int r, int c) {
    return base(r, c) + (c == 0 ? 0.01 : 0.0) + (c == 2 && r >= 100 ? 0.002 : 0.0);
  });
  const auto set = analysis::loadTrials({a, b}, defaultProfiles());
  ASSERT_TRUE(set.issues.empty()) << set.issues.front().reason;
  const analysis::Comparison pp{set.find("physical"), set.find("physical")};
  const auto shoulder = analysis::jointStats(pp, Quantity::Position, 0, false);
  // The recorder keeps micro-units, so figures hold to a few 1e-6.
  EXPECT_NEAR(shoulder.mean_abs, 0.01, 3e-6);
  EXPECT_NEAR(shoulder.rms, 0.01, 3e-6);
  EXPECT_NEAR(shoulder.max, 0.01, 3e-6);
  EXPECT_EQ(shoulder.pairs, 1u);
  EXPECT_EQ(shoulder.samples, 200u);
  EXPECT_NEAR(analysis::jointStats(pp, Quantity::Position, 0, true).max, 0.0, 3e-6);
  const auto insertion = analysis::jointStats(pp, Quantity::Position, 2, false);
  EXPECT_NEAR(insertion.mean_abs, 0.001, 3e-6);  // half the rows differ by 2 mm
  EXPECT_NEAR(insertion.rms, std::sqrt(0.5) * 0.002, 3e-6);
  EXPECT_NEAR(insertion.max, 0.002, 3e-6);
  EXPECT_NEAR(analysis::jointStats(pp, Quantity::Position, 1, false).max, 0.0, 3e-6);
}

TEST(Analysis, CorrelatesADifferenceThatGrowsWithTime) {
  test_support::TempDir dir;
  auto base = [](int r, int c) { return 0.2 + 0.01 * c + 0.1 * std::sin(0.05 * r); };
  const auto robot = writeRs(dir, "run_physical_rs.csv", 500, base);
  const auto twin =
      writeRs(dir, "run_twin_rs.csv", 500, [&](int r, int c) { return base(r, c) + 1e-4 * r; });
  const auto set = analysis::loadTrials({robot, twin}, defaultProfiles());
  const analysis::Comparison ps{set.find("twin"), set.find("physical")};
  ASSERT_EQ(ps.symbol(), "T_PS");
  const auto by_time = analysis::correlate(analysis::factorSamples(ps, 0, analysis::Factor::Time));
  EXPECT_GT(by_time.pearson_difference, 0.999);
  EXPECT_GT(by_time.spearman_magnitude, 0.999);
  ASSERT_FALSE(by_time.trend.x.empty());
  EXPECT_NEAR(by_time.trend.y.back(), 1e-4 * 499, 2e-5);  // the LOWESS follows the drift
  const auto by_position =
      analysis::correlate(analysis::factorSamples(ps, 0, analysis::Factor::Position));
  EXPECT_LT(std::abs(by_position.pearson_difference), 0.5);
}

TEST(Analysis, ARecordingWhoseTimeRunsBackwardsIsSkippedNamingTheRow) {
  test_support::TempDir dir;
  const auto good = writeRsAt(dir, "a_physical_rs.csv", {0.0, 0.02, 0.04, 0.06});
  const auto backwards = writeRsAt(dir, "b_physical_rs.csv", {0.0, 0.02, 0.01, 0.06});
  const auto set = analysis::loadTrials({good, backwards}, defaultProfiles());
  ASSERT_NE(set.find("physical"), nullptr);
  EXPECT_EQ(set.find("physical")->trials.size(), 1u);
  ASSERT_EQ(set.issues.size(), 1u);
  EXPECT_EQ(set.issues[0].path, backwards);
  EXPECT_THAT(set.issues[0].reason, testing::HasSubstr("data row 3: time 0.01 s"));
}

TEST(Analysis, ResamplingAFarTimeJumpIsRefusedNotAllocated) {
  test_support::TempDir dir;
  const auto far = writeRsAt(dir, "a_physical_rs.csv", {0.0, 0.02, 1e9});
  auto set = analysis::loadTrials({far}, defaultProfiles());
  ASSERT_NE(set.find("physical"), nullptr);
  EXPECT_THROW(analysis::resampleOnTime(set, 0.001), std::invalid_argument);
}

TEST(Lowess, RecoversALineAndIgnoresAnOutlier) {
  std::vector<double> x, y;
  for (int i = 0; i < 200; ++i) {
    x.push_back(0.1 * i);
    y.push_back(2.0 * x.back() + 1.0 + (i == 100 ? 50.0 : 0.0));
  }
  const auto curve = analysis::lowess(x, y);
  ASSERT_EQ(curve.x.size(), 200u);
  for (std::size_t i = 0; i < curve.x.size(); ++i) {
    EXPECT_NEAR(curve.y[i], 2.0 * curve.x[i] + 1.0, 1e-6) << "at x = " << curve.x[i];
  }
}

TEST(Lowess, FollowsACurveAndDropsNonFinitePairs) {
  std::vector<double> x, y;
  for (int i = 0; i <= 400; ++i) {
    x.push_back(i / 400.0);
    y.push_back(std::sin(2.0 * M_PI * x.back()));
  }
  x.push_back(NAN);
  y.push_back(1.0);
  analysis::LowessOptions options;
  options.frac = 0.1;
  const auto curve = analysis::lowess(x, y, options);
  ASSERT_EQ(curve.x.size(), 401u);
  for (std::size_t i = 0; i < curve.x.size(); ++i) {
    EXPECT_NEAR(curve.y[i], std::sin(2.0 * M_PI * curve.x[i]), 0.02) << "at x = " << curve.x[i];
  }
  EXPECT_THROW(analysis::lowess({1.0, 2.0}, {1.0}), std::invalid_argument);
}

TEST(Correlation, PearsonAndSpearman) {
  const std::vector<double> x{1, 2, 3, 4, 5, 6};
  EXPECT_NEAR(analysis::pearson(x, {2, 4, 6, 8, 10, 12}), 1.0, 1e-12);
  EXPECT_NEAR(analysis::pearson(x, {6, 5, 4, 3, 2, 1}), -1.0, 1e-12);
  EXPECT_NEAR(analysis::spearman(x, {1, 4, 9, 16, 25, 1000}), 1.0, 1e-12);  // monotone
  EXPECT_LT(analysis::pearson(x, {1, 4, 9, 16, 25, 1000}), 0.8);
  EXPECT_TRUE(std::isnan(analysis::pearson(x, {1, 1, 1, 1, 1, 1})));
}

TEST(Analysis, MalformedRecordingsAreReportedPerFileAndTheRestIsAnalysed) {
  test_support::TempDir dir;
  auto value = [](int r, int c) { return 0.3 + 0.01 * c + 0.001 * r; };
  writeRs(dir, "good1_physical_rs.csv", 100, value);
  writeRs(dir, "good2_physical_rs.csv", 100, value);
  writeRs(dir, "short_physical_rs.csv", 60, value);
  writeRs(dir, "gap_twin_rs.csv", 100,
          [&](int r, int c) { return c == 2 && r >= 20 && r < 40 ? NAN : value(r, c); });
  writeRs(dir, "nobody_rs.csv", 100, value);
  // A recording without its jpos5 column.
  const auto full = test_support::readFile(writeRs(dir, "x.tmp", 10, value));
  std::string cut;
  std::istringstream lines(full);
  int column_of_jpos5 = -1;
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    for (std::string f; std::getline(cells, f, ',');) fields.push_back(f);
    if (column_of_jpos5 < 0) {
      column_of_jpos5 =
          static_cast<int>(std::find(fields.begin(), fields.end(), "jpos5") - fields.begin());
    }
    fields.erase(fields.begin() + column_of_jpos5);
    for (std::size_t i = 0; i < fields.size(); ++i) cut += (i ? "," : "") + fields[i];
    cut += "\n";
  }
  dir.write("cut_physical_rs.csv", cut);
  std::filesystem::remove(dir.path() / "x.tmp");
  dir.write("garbage_physical_rs.csv", "time,jpos0\n0,1\n1\n");

  const auto set = analysis::loadTrials({dir.path()}, defaultProfiles());
  auto reason = [&](const std::string& file) -> const analysis::FileIssue* {
    for (const auto& i : set.issues) {
      if (i.path.filename() == file) return &i;
    }
    return nullptr;
  };
  ASSERT_TRUE(reason("cut_physical_rs.csv"));
  EXPECT_TRUE(reason("cut_physical_rs.csv")->excluded);
  EXPECT_NE(reason("cut_physical_rs.csv")->reason.find("jpos5"), std::string::npos)
      << reason("cut_physical_rs.csv")->reason;
  ASSERT_TRUE(reason("garbage_physical_rs.csv"));
  EXPECT_TRUE(reason("garbage_physical_rs.csv")->excluded);
  ASSERT_TRUE(reason("nobody_rs.csv"));
  EXPECT_NE(reason("nobody_rs.csv")->reason.find("no platform"), std::string::npos);
  ASSERT_TRUE(reason("short_physical_rs.csv"));
  EXPECT_FALSE(reason("short_physical_rs.csv")->excluded);
  EXPECT_NE(reason("short_physical_rs.csv")->reason.find("60 rows where most recordings have 100"),
            std::string::npos);
  ASSERT_TRUE(reason("gap_twin_rs.csv"));
  EXPECT_FALSE(reason("gap_twin_rs.csv")->excluded);
  EXPECT_NE(reason("gap_twin_rs.csv")->reason.find("jpos2 rows 22-41"), std::string::npos)
      << reason("gap_twin_rs.csv")->reason;
  EXPECT_EQ(set.issues.size(), 5u);
  // The usable files still make a report: three physical trials, one twin with its NaN skipped.
  ASSERT_EQ(set.find("physical")->trials.size(), 3u);
  ASSERT_TRUE(set.find("twin"));
  const analysis::Comparison ps{set.find("twin"), set.find("physical")};
  const auto insertion = analysis::jointStats(ps, Quantity::Position, 2, false);
  EXPECT_NEAR(insertion.max, 0.0, 1e-6);
  EXPECT_EQ(insertion.samples, 80u + 80u + 40u);  // 100 and 60 rows, 20 of each NaN
}

TEST(Analysis, ProfilesFileErrorsNameTheKey) {
  test_support::TempDir dir;
  const auto file = dir.write("p.yaml",
                              "platforms:\n  - name: sim\n    role: simulation\n"
                              "    position offsets: {jpos16: 1.0}\n");
  try {
    analysis::readRecordingSources(file);
    FAIL() << "accepted jpos16";
  } catch (const common::LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("jpos16"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("p.yaml"), std::string::npos) << e.what();
  }
  const auto bad_role = dir.write("r.yaml", "platforms:\n  - {name: x, role: robot}\n");
  EXPECT_THROW(analysis::readRecordingSources(bad_role), common::LoadError);
}

TEST(Analysis, ResamplingOnTimeAlignsTrialsRecordedAtDifferentRates) {
  test_support::TempDir dir;
  const auto slow = dir.path() / "slow_physical_rs.csv";
  const auto fast = dir.path() / "fast_physical_rs.csv";
  for (auto [path, period] : {std::pair{slow, 0.04}, std::pair{fast, 0.01}}) {
    recording::RsWriter writer(path);
    for (double t = 0.0; t <= 2.0 + 1e-9; t += period) {
      bridge::RavenStateSnapshot s;
      s.time = t;
      s.jpos[0] = static_cast<float>(t * 180.0 / M_PI);  // the shoulder turns at 1 rad/s
      writer.write(s);
    }
  }
  auto set = analysis::loadTrials({slow, fast}, defaultProfiles());
  const analysis::Comparison pp{set.find("physical"), set.find("physical")};
  EXPECT_GT(analysis::jointStats(pp, Quantity::Position, 0, false).mean_abs, 0.1);  // by index
  analysis::resampleOnTime(set, 0.02);
  EXPECT_EQ(set.platforms.front().trials.front().rows(), 101u);
  EXPECT_LT(analysis::jointStats(pp, Quantity::Position, 0, false).max, 1e-5);  // by time
}

TEST(Profiles, ThePapersDatasetNamesAreRecognised) {
  const auto profiles = analysis::readRecordingSources(analysis::defaultRecordingSourcesFile());
  auto platformOf = [&](const std::string& name) -> std::string {
    const auto* p = analysis::sourceOf(profiles, name, {});
    return p ? p->name : "none";
  };
  EXPECT_EQ(platformOf("m1left_p1.csv"), "physical");
  EXPECT_EQ(platformOf("2arm_p12.csv"), "physical");
  EXPECT_EQ(platformOf("m1right_a3.csv"), "ambf");
  EXPECT_EQ(platformOf("2arm_physical_2.csv"), "physical");
  EXPECT_EQ(platformOf("twin_2arm_20261124_rs.csv"), "twin");
  EXPECT_EQ(platformOf("peg_transfer_seed7_rs.csv"), "twin");
  EXPECT_EQ(platformOf("set_px.csv"), "none");
  EXPECT_EQ(platformOf("set_p1.csv.bak"), "none");
}

TEST(Analysis, GraspForceRecordingsBesideRsFilesAreListedForTheirFigureNotReadAsTrials) {
  test_support::TempDir dir;
  const auto twin = writeRs(dir, "run_twin_rs.csv", 50, [](int r, int) { return 1e-3 * r; });
  {
    recording::CfWriter cf(recording::cfPathFor(twin));
    bridge::GrasperForces held;
    held.jaws[0].normal = Eigen::Vector3d(0.15, 0, 0);
    held.jaws[0].contacts = 3;
    held.force = Eigen::Vector3d(0, 0, 0.0196);
    for (int r = 0; r < 50; ++r) cf.write(0.02 * r, {held, std::nullopt});
  }
  writeRs(dir, "run_physical_rs.csv", 50, [](int r, int) { return 1e-3 * r; });
  const auto set = analysis::loadTrials({dir.path()}, defaultProfiles());
  EXPECT_TRUE(set.issues.empty()) << set.issues.front().path << ": " << set.issues.front().reason;
  ASSERT_TRUE(set.find("twin"));
  ASSERT_TRUE(set.find("physical"));

  const auto out = dir.path() / "report";
  analysis::writeReportData(set, {}, out);
  const std::string listing = test_support::readFile(out / "grasp_forces.csv");
  EXPECT_NE(listing.find("run_twin_cf.csv"), std::string::npos) << listing;
  EXPECT_EQ(listing.find("physical"), std::string::npos) << "no forces beside the robot's file";

  const std::string cf = test_support::readFile(recording::cfPathFor(twin));
  EXPECT_EQ(cf.substr(0, cf.find('\n')).find("time,left_fx,"), 0u);
  EXPECT_NE(cf.find(",0.15,0,0,0,3,nan,"), std::string::npos) << "jaw 1 normal 0.15 N, 3 contacts";
  // Read back: the same values, the arm without forces NaN.
  const recording::CfRecording back = recording::readCf(recording::cfPathFor(twin));
  ASSERT_EQ(back.rows.size(), 50u);
  EXPECT_DOUBLE_EQ(back.rows[7][back.column("time")], 0.14);
  EXPECT_DOUBLE_EQ(back.rows[7][back.column("left_jaw1_normal")], 0.15);
  EXPECT_DOUBLE_EQ(back.rows[7][back.column("left_contacts")], 3.0);
  EXPECT_TRUE(std::isnan(back.rows[7][back.column("right_fx")]));
  EXPECT_THROW(back.column("left_torque"), recording::RecordingError);
  try {
    recording::readCf(twin);  // an rs file
    FAIL() << "an rs file read as a cf file";
  } catch (const recording::RecordingError& e) {
    EXPECT_NE(std::string(e.what()).find("run_twin_rs.csv: row 1: not a cf file's header"),
              std::string::npos)
        << e.what();
  }
}

/// raven_analyze on the paper's recordings and a twin replay of the same inputs.
TEST(RavenAnalyze, ReportsTheTwinAsAThirdPlatformWithFigures) {
  const auto shared = test_support::sharedDataDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent: the paper's recordings are needed";
  const auto paper = shared / "recordings/paper_2arm";
  test_support::TempDir dir;
  const std::string replay = fmt::format(
      "{} --lock-step --paper-deadzone --no-gamepad --no-keyboard --replay-ci {} --record "
      "yes --name twin_2arm --out {} --video {} --video-size 320x240 > {} 2>&1",
      RAVEN_CONTROLLER, (paper / "2arm_ci.csv").string(), dir.path().string(),
      (dir.path() / "twin_2arm.mp4").string(), (dir.path() / "controller.log").string());
  ASSERT_EQ(std::system(replay.c_str()), 0)
      << test_support::readFile(dir.path() / "controller.log");
  const auto report = dir.path() / "report";
  const std::string analyze =
      fmt::format("{} {} {} --out {} > {} 2>&1", RAVEN_ANALYZE, paper.string(), dir.path().string(),
                  report.string(), (dir.path() / "analyze.log").string());
  ASSERT_EQ(std::system(analyze.c_str()), 0) << test_support::readFile(dir.path() / "analyze.log");
  // The summary prints j_V beside j_P: the robot's own T_PP velocities, to the printed decimals.
  const std::string log = test_support::readFile(dir.path() / "analyze.log");
  EXPECT_NE(log.find("j_V"), std::string::npos) << log;
  EXPECT_NE(log.find("revolute     0.0135 /    0.0175 rad     0.0632 rad/s"), std::string::npos)
      << log;
  EXPECT_NE(log.find("prismatic    1.3951 /    0.0998 mm      0.2534 mm/s"), std::string::npos)
      << log;

  const auto metrics = nlohmann::json::parse(test_support::readFile(report / "metrics.json"));
  std::vector<std::string> platforms;
  for (const auto& p : metrics["inputs"]["platforms"]) platforms.push_back(p["name"]);
  EXPECT_EQ(platforms, (std::vector<std::string>{"physical", "ambf", "twin"}));
  std::set<std::string> compared;
  for (const auto& s : metrics["summary"])
    compared.insert(s["symbol"].get<std::string>() + " " + s["comparison"].get<std::string>());
  for (const char* expected :
       {"T_SS ambf vs ambf", "T_PP physical vs physical", "T_PS ambf vs physical",
        "T_PS twin vs physical", "T_SS ambf vs twin"}) {
    EXPECT_TRUE(compared.count(expected)) << expected;
  }
  EXPECT_FALSE(metrics["correlations"].empty());
  for (const char* figure : {"fig6_trajectories.png", "fig7_inconsistency_position.png",
                             "fig7_inconsistency_velocity.png", "fig8_twin_vs_physical_time.png",
                             "fig8_ambf_vs_physical_joint_velocity.png", "index.html",
                             "metrics.csv", "correlations.csv"}) {
    ASSERT_TRUE(std::filesystem::exists(report / figure)) << figure;
    EXPECT_GT(std::filesystem::file_size(report / figure), 1000u) << figure;
  }
  const auto png = test_support::readFile(report / "fig6_trajectories.png");
  EXPECT_EQ(png.substr(1, 3), "PNG");
  const auto page = test_support::readFile(report / "index.html");
  EXPECT_NE(page.find("twin vs physical"), std::string::npos);
  EXPECT_NE(page.find("fig8_twin_vs_physical_joint_position.png"), std::string::npos);
  // The replay's video (recorded headless by raven_controller) is on the page beside the figures.
  EXPECT_GT(std::filesystem::file_size(report / "pictures/twin_2arm.mp4"), 1000u);
  EXPECT_NE(page.find(R"(<video controls src="pictures/twin_2arm.mp4")"), std::string::npos);
}

TEST(RavenAnalyze, ListsTheRunsSnapshotsAndVideosWithTheirFirstFrames) {
  test_support::TempDir dir;
  const auto runs = dir.path() / "runs";
  std::filesystem::create_directories(runs);
  for (const char* file : {"peg_overview_after.png", "run.mp4", "run.png", "peg_rs.csv"}) {
    std::ofstream(runs / file) << "bytes of " << file;
  }
  const auto report = dir.path() / "report";
  EXPECT_EQ(analysis::writePictures({runs / "peg_rs.csv"}, report), 2u);
  const auto listed = nlohmann::json::parse(test_support::readFile(report / "pictures.json"));
  ASSERT_EQ(listed.size(), 2u);
  EXPECT_EQ(listed[0]["file"], "pictures/peg_overview_after.png");
  EXPECT_EQ(listed[0]["kind"], "image");
  EXPECT_EQ(listed[1]["file"], "pictures/run.mp4");
  EXPECT_EQ(listed[1]["kind"], "video");
  EXPECT_EQ(listed[1]["poster"], "pictures/run.png");
  EXPECT_EQ(test_support::readFile(report / "pictures/run.png"), "bytes of run.png");
  // Nothing to show: nothing written.
  EXPECT_EQ(analysis::writePictures({dir.path() / "report/pictures.json"}, dir.path() / "none"),
            0u);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "none"));
}

}  // namespace
