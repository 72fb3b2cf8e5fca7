#pragma once
// One participant's session of a study, resumable: the plan fixed in `session.json` when it
// begins, each finished trial's recordings, events and metrics in its own folder sealed by
// `trial.json` (written whole or not at all), each condition's questionnaires in their own
// file. A session started again with the same folder and participant skips what is sealed,
// sets aside a trial that was cut short (`aborted/`) and runs it again.

#include <atomic>
#include <csignal>
#include <filesystem>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "controller/sdl_gamepad.hpp"
#include "study/protocol.hpp"
#include "study/questionnaire_desk.hpp"
#include "study/virtual_participant.hpp"
#include "viewer/video_recorder.hpp"

namespace harness {
class VirtualGamepad;
}

namespace study {

/// Who is at the pad and how the session talks to them.
struct SessionSettings {
  std::filesystem::path out;  ///< the study's folder (one per protocol)
  std::string participant;    ///< the participant's code, e.g. "P03"
  /// The participant's place in the counterbalancing; unset: the next free one in the study's
  /// folder (arrival order), kept for a resumed session.
  std::optional<int> position;
  controller::SdlGamepad* pad = nullptr;  ///< the pad the trials read
  /// Set: a simulated person drives `virtual_pad` (SDL's virtual joystick, which `pad` reads)
  /// on the simulated clock; unset: a person, in real time.
  std::optional<ParticipantTraits> traits;
  std::uint64_t seed = 0;  ///< the virtual participant's noise
  harness::VirtualGamepad* virtual_pad = nullptr;
  bool questionnaires = true;  ///< asked after each condition (people; a virtual one skips them)
  bool rests = true;           ///< people rest between conditions
  QuestionnaireDesk* desk = nullptr;        ///< where the questionnaires are answered
  std::ostream* out_text = nullptr;         ///< instructions, countdowns, status, questions
  const std::atomic<bool>* stop = nullptr;  ///< Ctrl-C
  /// Drill: raise `drill_signal` halfway into the trial after this many trials finished in this
  /// run (SIGINT: as Ctrl-C; SIGKILL: as a crash); -1: no drill.
  int drill_after = -1;
  int drill_signal = SIGINT;
  /// Set: every trial's video (its folder's trial.mp4) at this rate and size.
  std::optional<viewer::VideoOptions> video;
};

/// How far a session got.
struct SessionProgress {
  int done = 0;           ///< sealed trials
  int total = 0;          ///< planned trials
  bool finished = false;  ///< every trial sealed and every questionnaire answered
  bool stopped = false;   ///< stopped by the user (or the drill) before the end
};

/// Runs (or resumes) the participant's session. Throws std::runtime_error when the study's
/// folder holds a session of this participant under another protocol.
SessionProgress runSession(const Protocol& protocol, const SessionSettings& settings);

/// Writes `j` to `path` through a temporary file renamed over it: a crash leaves the old file
/// or the new one, never half of one.
void writeJsonAtomically(const std::filesystem::path& path, const nlohmann::json& j);
nlohmann::json readJson(const std::filesystem::path& path);

/// A condition's settings as trial.json records them.
nlohmann::json conditionJson(const Condition& condition);

}  // namespace study
