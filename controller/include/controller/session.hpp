#pragma once
// The command thread's work: the selected mode (O1-O5) one iteration at a time, its inputs (a
// live pad, replayed inputs or joints), and the recorder.

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "controller/dual_platform_controller.hpp"
#include "controller/sdl_gamepad.hpp"
#include "recording/cf_recording.hpp"
#include "recording/recording_io.hpp"

namespace controller {

/// The paper's operation modes, and idling between them.
enum class Mode { Idle, Homing, Manual, ReplayInputs, ReplayJoints, SineDance };

/// "O1 homing", "O2 manual", ...
std::string_view modeName(Mode mode);

/// Where a session's inputs come from.
struct SessionInputs {
  SdlGamepad* gamepad = nullptr;                 ///< O2's live pad (may be absent)
  std::vector<recording::GamepadState> inputs;   ///< O3: one row per manual-loop iteration
  std::optional<recording::RsRecording> joints;  ///< O4: recorded joint positions
};

/// Session settings.
struct SessionOptions {
  std::filesystem::path out_dir = "recordings";
  std::string record_name = "raven";
  double replay_delay = 1.0;  ///< O3 waits this long after loading (s of platform time)
  /// After O3 or O4 reach the end of their file the session ends (else it idles).
  bool end_after_replay = false;
  /// Called with each platform's state (its index in the controller's platforms) at every
  /// iteration a recording would write a row for, whether or not files are being written.
  std::function<void(std::size_t, const bridge::RavenStateSnapshot&)> on_state;
  /// Applied to every live pad reading before the mapping and the recorder see it (a study's
  /// condition keeps its scheme and IK this way); unset: readings pass as they are.
  std::function<recording::GamepadState(const recording::GamepadState&)> gate;
  /// Called with what every iteration of every mode did (clamps, command steps, refusals).
  std::function<void(const IterationReport&)> on_iteration;
};

/// One controller session: modes, inputs and recordings.
class ControllerSession {
 public:
  ControllerSession(DualPlatformController& controller, SessionInputs inputs,
                    SessionOptions options);
  ~ControllerSession();

  /// Switches mode (takes effect at the next turn). O3 / O4 without a loaded file refuse.
  bool select(Mode mode);
  Mode mode() const { return mode_; }
  /// Starts writing `<name>_<time>[_<platform>]_rs.csv` (and `_ci.csv`), one row per iteration.
  void startRecording();
  /// Closes the files (every row is already on disk); returns how many rows they hold.
  std::size_t stopRecording();
  bool recording() const { return !rs_.empty(); }
  /// Ends the session at the next turn.
  void quit() { quit_ = true; }

  /// One turn of the command thread: one iteration of the mode (or one idle period). False
  /// once the session is over.
  bool turn();

  /// Files written so far.
  const std::vector<std::filesystem::path>& recordings() const { return files_; }
  /// Rows of the last joint replay (O4) that a joint limit clamped (each is logged).
  std::size_t clampedRows() const { return clamped_rows_; }
  /// Manual iterations skipped because the live pad was missing.
  std::size_t padlessTurns() const { return padless_turns_; }

 private:
  void record(const std::optional<recording::GamepadState>& pad);
  void finishReplay();
  void report(const IterationReport& report);

  DualPlatformController& controller_;
  SessionInputs inputs_;
  SessionOptions options_;
  Mode mode_ = Mode::Idle;
  std::size_t next_row_ = 0;
  std::size_t clamped_rows_ = 0;  ///< replayed rows a joint limit clamped
  std::vector<std::unique_ptr<recording::RsWriter>> rs_;
  std::vector<std::unique_ptr<recording::CfWriter>>
      cf_;  ///< per platform; null where it has no forces
  std::unique_ptr<recording::CiWriter> ci_;
  std::vector<std::filesystem::path> files_;
  std::size_t padless_turns_ = 0;
  bool warned_padless_ = false;
  bool quit_ = false;
  std::size_t refusals_logged_ = 0;
};

}  // namespace controller
