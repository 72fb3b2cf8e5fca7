// The recorder's files: rs and ci round trips, every reader variant the reference lists, and
// bad files rejected with the row at fault.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <fstream>

#include "recording/recording_format.hpp"
#include "recording/recording_io.hpp"
#include "test_files.hpp"

namespace {

using recording::GamepadState;
using recording::RecordingError;

bridge::RavenStateSnapshot sampleState(double t, double scale) {
  bridge::RavenStateSnapshot s;
  s.time = t;
  s.runlevel = 3;
  s.sublevel = 1;
  s.last_seq = 42;
  s.type = {24, 10};
  for (std::size_t i = 0; i < 16; ++i) {
    s.jpos[i] = static_cast<float>(scale * (static_cast<double>(i) - 7.5));
    s.jvel[i] = static_cast<float>(0.5 * scale * static_cast<double>(i));
    s.mpos[i] = static_cast<float>(1000.0 * scale + static_cast<double>(i));
    s.enc_vals[i] = static_cast<std::int32_t>(i * 1000);
  }
  s.jpos[2] = static_cast<float>(0.4 * 180.0 / M_PI);  // 0.4 m, as the robot reports it
  s.pos = {-78246, -25305, 13726, -79441, 25664, 13836};
  s.grasp_d = {90.0f, 45.0f};
  return s;
}

TEST(Recording, RsRoundTripKeepsEveryFieldInTheRobotsConventions) {
  test_support::TempDir dir;
  {
    recording::RsWriter w(dir.path() / "a_rs.csv");
    w.write(sampleState(10.0, 1.0));
    w.write(sampleState(10.022, 2.0));
  }
  const auto rec = recording::readRs(dir.path() / "a_rs.csv");
  EXPECT_TRUE(rec.variant.index_column);
  EXPECT_EQ(rec.variant.columns, 240u);
  EXPECT_FALSE(rec.variant.from_ambf);
  EXPECT_FALSE(rec.variant.jpos_in_degrees);
  ASSERT_EQ(rec.rows.size(), 2u);
  EXPECT_EQ(rec.time(0), 0.0) << "time is relative to the first row";
  EXPECT_NEAR(rec.time(1), 0.022, 1e-12);
  const auto expected = recording::rsRow(sampleState(10.022, 2.0), 10.0);
  for (std::size_t c = 0; c < expected.size(); ++c) {
    EXPECT_NEAR(rec.rows[1][c + 1], expected[c], 5e-7) << recording::rsColumnNames()[c];
  }
  EXPECT_NEAR(rec.rows[0][rec.column("jpos2")], 0.4, 1e-6) << "jpos in radians and metres";
  EXPECT_EQ(rec.rows[0][rec.column("pos0")], -78246.0) << "pos stays in microns";
}

TEST(Recording, CiRoundTripIsExact) {
  test_support::TempDir dir;
  GamepadState a;
  a.left_x = 0.0670166015625;
  a.left_y = -0.0087890625;
  a.right_trigger = 3.99609375;
  a.left_bumper = true;
  a.back = true;
  GamepadState b;
  b.right_y = -1.0;
  b.y = true;
  {
    recording::CiWriter w(dir.path() / "a_ci.csv");
    w.write(a);
    w.write(b);
  }
  const auto rows = recording::readCi(dir.path() / "a_ci.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], a);
  EXPECT_EQ(rows[1], b);
  EXPECT_EQ(test_support::readFile(dir.path() / "a_ci.csv").substr(0, 32),
            "Left Joystick X,Left Joystick Y,");
}

TEST(Recording, ValuesArePrintedAsThePapersRecorderPrintsThem) {
  EXPECT_EQ(recording::formatRsValue(0.0), "0.0");
  EXPECT_EQ(recording::formatRsValue(-0.0), "0.0");
  EXPECT_EQ(recording::formatRsValue(0.5221714), "0.522171");
  EXPECT_EQ(recording::formatRsValue(-78246.0), "-78246.0");
  EXPECT_EQ(recording::formatRsValue(std::nan("")), "");
  EXPECT_EQ(recording::formatRsValue(1.3640589714050293, false), "1.3640589714050293");
}

std::string header(const std::vector<std::string>& names, bool index) {
  std::string h = index ? "," : "";
  for (std::size_t i = 0; i < names.size(); ++i) h += (i ? "," : "") + names[i];
  return h;
}

TEST(Recording, TheReaderTellsEachVariantApart) {
  test_support::TempDir dir;
  auto names = recording::rsColumnNames();
  std::vector<std::string> row(names.size(), "0.0");
  auto write = [&](const std::string& file, const std::vector<std::string>& cols, bool index,
                   const std::vector<std::string>& values) {
    std::string text = header(cols, index) + "\n" + (index ? "0," : "");
    for (std::size_t i = 0; i < values.size(); ++i) text += (i ? "," : "") + values[i];
    return dir.write(file, text + "\n");
  };
  // Degrees: an insertion of 22.9 "m" cannot be metres.
  auto degrees = row;
  degrees[3] = "22.918312";  // jpos2
  degrees[1] = "30.0";       // jpos0
  auto rec = recording::readRs(write("deg.csv", names, true, degrees));
  EXPECT_TRUE(rec.variant.jpos_in_degrees);
  EXPECT_NEAR(rec.rows[0][rec.column("jpos2")], 0.4, 1e-6);
  EXPECT_NEAR(rec.rows[0][rec.column("jpos0")], M_PI / 6, 1e-9);

  // AMBF rows: robot-only fields empty, the recorder's offsets on jpos.
  auto ambf = row;
  ambf[3] = "0.39";   // jpos2 = -0.07 + 0.46
  ambf[5] = "0.0";    // jpos4 = roll + pi/4 with roll -pi/4
  ambf[15] = "-0.5";  // jpos14: the right jaw 1, negated by AMBF
  for (std::size_t c = 17; c < 200; ++c) ambf[c] = "";
  rec = recording::readRs(write("ambf.csv", names, true, ambf));
  EXPECT_TRUE(rec.variant.from_ambf);
  EXPECT_TRUE(std::isnan(rec.rows[0][rec.column("runlevel")]));
  const auto right = rec.joints(0, raven::Arm::Right);
  EXPECT_NEAR(rec.joints(0, raven::Arm::Left)(raven::kInsertion), -0.07, 1e-12);
  EXPECT_NEAR(rec.joints(0, raven::Arm::Left)(raven::kRoll), -M_PI / 4, 1e-12);
  EXPECT_NEAR(right(raven::kJaw1), 0.5, 1e-12);

  // October 2023: no mpos_d, 16 grasp_d; and no index column.
  std::vector<std::string> legacy;
  for (const auto& n : names) {
    if (n.rfind("mpos_d", 0) == 0 || n.rfind("grasp_d", 0) == 0) continue;
    legacy.push_back(n);
  }
  for (int i = 0; i < 16; ++i) legacy.push_back("grasp_d" + std::to_string(i));
  EXPECT_EQ(legacy.size(), 238u);
  rec = recording::readRs(
      write("legacy.csv", legacy, false, std::vector<std::string>(legacy.size(), "0.1")));
  EXPECT_TRUE(rec.variant.legacy);
  EXPECT_FALSE(rec.variant.index_column);
  EXPECT_NE(rec.variant.describe().find("Oct 2023"), std::string::npos);
}

TEST(Recording, ThePapersFilesAreRecognised) {
  const auto shared = test_support::sharedDataDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent: the paper's recordings are needed";
  const auto dir = shared / "recordings/paper_2arm";
  const auto physical = recording::readRs(dir / "2arm_physical_1.csv");
  EXPECT_EQ(physical.rows.size(), 1351u);
  EXPECT_FALSE(physical.variant.from_ambf);
  EXPECT_EQ(physical.variant.columns, 240u);
  const auto ambf = recording::readRs(dir / "2arm_ambf_1.csv");
  EXPECT_TRUE(ambf.variant.from_ambf);
  EXPECT_NEAR(ambf.joints(0, raven::Arm::Left)(raven::kInsertion), -0.07, 1e-4);
  EXPECT_EQ(recording::readCi(dir / "2arm_ci.csv").size(), 1351u);
}

/// Writes a ci file with `rows` after a correct header.
std::filesystem::path ciFile(const test_support::TempDir& dir, const std::string& rows) {
  std::string text;
  for (auto name : GamepadState::ciColumnNames())
    text += (text.empty() ? "" : ",") + std::string(name);
  const std::string good = "0.1,0.2,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0\n";
  return dir.write("bad_ci.csv", text + "\n" + good + good + rows);
}

std::string errorOf(const std::filesystem::path& file) {
  try {
    recording::readCi(file);
  } catch (const RecordingError& e) {
    return e.what();
  }
  return "";
}

TEST(Recording, BadCiFilesNameTheRow) {
  test_support::TempDir dir;
  EXPECT_NE(errorOf(ciFile(dir, "0.1,0.2,0.0\n")).find("row 4: 3 columns, expected 14"),
            std::string::npos);
  EXPECT_NE(errorOf(ciFile(dir, "0.1,abc,0,0,0,0,0,0,0,0,0,0,0,0\n"))
                .find("row 4, column 'Left Joystick Y': 'abc' is not a finite number"),
            std::string::npos);
  EXPECT_NE(errorOf(ciFile(dir, "0.1,nan,0,0,0,0,0,0,0,0,0,0,0,0\n")).find("row 4"),
            std::string::npos);
  EXPECT_NE(errorOf(ciFile(dir, "0.1,0.2,0.0,0.0,0.0,0")).find("a truncated last line?"),
            std::string::npos);
  EXPECT_NE(errorOf(dir.write("h.csv", "a,b\n1,2\n")).find("row 1: the header has 2 columns"),
            std::string::npos);
  EXPECT_NE(errorOf(dir.path() / "missing.csv").find("missing.csv: file not found"),
            std::string::npos);
  // A pipe would block the reader until a writer came; /dev/zero would never end.
  const auto pipe = dir.path() / "pipe.csv";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  EXPECT_NE(errorOf(pipe).find("pipe.csv: not a regular file"), std::string::npos);
  // A header and no rows: a replay would wait for its first row forever.
  std::string header;
  for (auto name : GamepadState::ciColumnNames())
    header += (header.empty() ? "" : ",") + std::string(name);
  EXPECT_NE(errorOf(dir.write("empty_ci.csv", header + "\n")).find("no rows after the header"),
            std::string::npos);
}

/// Writes an rs file of rows at `times` (s) and returns its path.
std::filesystem::path rsFileAt(const test_support::TempDir& dir, const std::vector<double>& times) {
  const auto path = dir.path() / "t_rs.csv";
  recording::RsWriter w(path);
  for (std::size_t i = 0; i < times.size(); ++i) w.write(sampleState(times[i], 1.0 + i));
  return path;
}

/// The message readRs (for a replay) throws for `file` ("" when it reads it).
std::string rsErrorOf(const std::filesystem::path& file) {
  try {
    recording::readRs(file);
  } catch (const RecordingError& e) {
    return e.what();
  }
  return "";
}

std::string rsErrorAt(const test_support::TempDir& dir, const std::vector<double>& times) {
  return rsErrorOf(rsFileAt(dir, times));
}

TEST(Recording, AnRsFileWithTwoColumnsOfOneNameIsRefused) {
  test_support::TempDir dir;
  std::string text = test_support::readFile(rsFileAt(dir, {10.0, 10.001}));
  const auto jpos3 = text.find(",jpos3,");
  ASSERT_NE(jpos3, std::string::npos);
  text.replace(jpos3, 7, ",jpos2,");
  const std::string error = rsErrorOf(dir.write("twice_rs.csv", text));
  EXPECT_NE(error.find("a second 'jpos2' column"), std::string::npos) << error;
}

TEST(Recording, AReplayRefusesTimesThatDoNotMoveOnOrJumpAway) {
  test_support::TempDir dir;
  EXPECT_EQ(rsErrorAt(dir, {10.0, 10.001, 10.002}), "");
  EXPECT_NE(rsErrorAt(dir, {10.0, 10.002, 10.001}).find("row 4, column 'time'"), std::string::npos);
  EXPECT_NE(rsErrorAt(dir, {10.0, 10.001, 10.001}).find("not after the row before"),
            std::string::npos);
  EXPECT_NE(rsErrorAt(dir, {10.0, 10.001, 1e9}).find("more than a minute after"),
            std::string::npos);
}

}  // namespace

namespace {

TEST(Recording, AJointBeyondAnyRobotsReachIsRefusedForAReplayAndSkippedForAnalysis) {
  // A jpos of 1e300 passed as finite, and the analysis' sums over it overflowed to inf.
  test_support::TempDir dir;
  const auto rs = rsFileAt(dir, {10.0, 10.001, 10.002});
  auto lines = test_support::readFile(rs);
  // Row 3 of the file (the second sample): its first jpos field after the index and time.
  const auto second = lines.find('\n', lines.find('\n') + 1) + 1;
  const auto jpos0 = lines.find(',', lines.find(',', second) + 1) + 1;
  lines.replace(jpos0, lines.find(',', jpos0) - jpos0, "1e300");
  const auto broken = dir.write("broken_rs.csv", lines);
  const std::string error = rsErrorOf(broken);
  EXPECT_NE(error.find("row 3, column 'jpos0'"), std::string::npos) << error;
  EXPECT_NE(error.find("beyond +-1e3"), std::string::npos) << error;
  const auto kept = recording::readRs(broken, recording::NonFiniteJoints::Keep);
  EXPECT_TRUE(std::isnan(kept.rows[1][kept.column("jpos0")]));
  EXPECT_TRUE(std::isfinite(kept.rows[0][kept.column("jpos0")]));
}

}  // namespace
