// The raven_controller program's keyboard thread, driven through a pseudo-terminal: mode keys,
// recording start and stop, quitting; and a replay stopped by SIGTERM.

#include <gtest/gtest.h>
#include <poll.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>

#include "raven/platform_profile.hpp"
#include "recording/recording_io.hpp"
#include "test_files.hpp"

namespace {

/// The program on the slave side of a pseudo-terminal; the test types and reads on the master.
class TerminalSession {
 public:
  explicit TerminalSession(const std::vector<std::string>& args) {
    pid_ = forkpty(&master_, nullptr, nullptr, nullptr);
    if (pid_ == 0) {
      std::vector<char*> argv;
      for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
  }
  ~TerminalSession() {
    if (pid_ > 0 && !exited_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    close(master_);
  }
  void type(char key) { ASSERT_EQ(write(master_, &key, 1), 1); }
  void signal(int number) { ASSERT_EQ(kill(pid_, number), 0); }
  /// Reads output until `text` appears; false after `seconds` of wall time (or end of output).
  bool waitFor(const std::string& text, double seconds = 30.0) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (output_.find(text, seen_) == std::string::npos) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return false;
      pollfd p{master_, POLLIN, 0};
      if (poll(&p, 1, static_cast<int>(left.count())) <= 0) return false;
      char buffer[4096];
      const ssize_t n = read(master_, buffer, sizeof(buffer));
      if (n <= 0) return false;
      output_.append(buffer, static_cast<std::size_t>(n));
    }
    seen_ = output_.find(text, seen_) + text.size();
    return true;
  }
  int exitCode() {
    int status = 0;
    waitpid(pid_, &status, 0);
    exited_ = true;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  const std::string& output() const { return output_; }

 private:
  int master_ = -1;
  pid_t pid_ = -1;
  bool exited_ = false;
  std::string output_;
  std::size_t seen_ = 0;
};

TEST(Keyboard, ModeKeysRecordingAndQuitReachTheCommandThread) {
  test_support::TempDir out;
  TerminalSession program(
      {RAVEN_CONTROLLER, "--no-gamepad", "--out", out.path().string(), "--duration", "120"});
  ASSERT_TRUE(program.waitFor("keys: 1-5")) << program.output();
  program.type('5');
  ASSERT_TRUE(program.waitFor("mode O5 sine dance")) << program.output();
  program.type('r');
  ASSERT_TRUE(program.waitFor("recording to")) << program.output();
  program.type('s');
  ASSERT_TRUE(program.waitFor("recording stopped (")) << program.output();
  program.type('3');  // no file loaded: refused, and the program carries on
  ASSERT_TRUE(program.waitFor("O3 needs a controller-input file")) << program.output();
  program.type('q');
  ASSERT_TRUE(program.waitFor("done:")) << program.output();
  EXPECT_EQ(program.exitCode(), 0);
  std::size_t rs_files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(out.path())) {
    if (entry.path().string().find("_rs.csv") == std::string::npos) continue;
    ++rs_files;
    EXPECT_GT(recording::readRs(entry.path()).rows.size(), 0u);
  }
  EXPECT_EQ(rs_files, 1u);
}

/// The one rs file in `folder`.
std::filesystem::path onlyRsFile(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> found;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().string().find("_rs.csv") != std::string::npos) found.push_back(entry.path());
  }
  EXPECT_EQ(found.size(), 1u) << folder;
  return found.empty() ? std::filesystem::path() : found.front();
}

TEST(Keyboard, SigtermStopsAReplayCleanlyWithItsRecordingOnDisk) {
  // Six seconds of a slow roll about home, 10 ms a row, to replay on the wall clock.
  test_support::TempDir first;
  const auto roll = first.path() / "roll_rs.csv";
  constexpr std::size_t kRows = 600;
  {
    recording::RsWriter writer(roll);
    const auto home = raven::builtinProfile("physical").home;
    for (std::size_t r = 0; r < kRows; ++r) {
      bridge::RavenStateSnapshot s;
      s.time = 0.01 * static_cast<double>(r);
      for (int j = 0; j < raven::kJointCount; ++j) {
        const double q = home(j) + (j == raven::kRoll ? 0.2 * std::sin(s.time) : 0.0);
        s.jpos[static_cast<std::size_t>(j)] = static_cast<float>(q * 180.0 / M_PI);
        s.jpos[static_cast<std::size_t>(8 + j)] = static_cast<float>(home(j) * 180.0 / M_PI);
      }
      writer.write(s);
    }
  }
  // Its replay, recorded too, stopped by SIGTERM as soon as it has started.
  test_support::TempDir second;
  TerminalSession replay({RAVEN_CONTROLLER, "--no-gamepad", "--no-keyboard", "--replay-rs",
                          roll.string(), "--record", "yes", "--name", "replay", "--out",
                          second.path().string()});
  ASSERT_TRUE(replay.waitFor("mode O4")) << replay.output();
  replay.signal(SIGTERM);
  ASSERT_TRUE(replay.waitFor("done:", 10.0)) << replay.output();
  EXPECT_EQ(replay.exitCode(), 0) << replay.output();
  // The recording is whole: a header and complete rows (none if the signal came before the
  // first turn), fewer than the replay has.
  const std::string text = test_support::readFile(onlyRsFile(second.path()));
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "a row cut short";
  const auto rows = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) - 1;
  EXPECT_LT(rows, kRows) << "the replay ran to its end: the signal did not stop it";
  if (rows > 0) {
    EXPECT_EQ(recording::readRs(onlyRsFile(second.path())).rows.size(), rows);
  }
}

}  // namespace
