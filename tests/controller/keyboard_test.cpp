// The raven_controller program's keyboard thread, driven through a pseudo-terminal: mode keys,
// recording start and stop, quitting.

#include <gtest/gtest.h>
#include <poll.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>

#include "controller/recording_io.hpp"
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
    EXPECT_GT(controller::readRs(entry.path()).rows.size(), 0u);
  }
  EXPECT_EQ(rs_files, 1u);
}

}  // namespace
