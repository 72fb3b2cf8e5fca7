#include "controller/session.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <ctime>

namespace controller {

namespace {

std::string timestamp() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm local{};
  localtime_r(&now, &local);
  char text[32];
  std::strftime(text, sizeof(text), "%Y%m%d-%H%M%S", &local);
  return text;
}

}  // namespace

std::string_view modeName(Mode mode) {
  switch (mode) {
    case Mode::Idle:
      return "idle";
    case Mode::Homing:
      return "O1 homing";
    case Mode::Manual:
      return "O2 manual";
    case Mode::ReplayInputs:
      return "O3 replay controller inputs";
    case Mode::ReplayJoints:
      return "O4 replay joint positions";
    case Mode::SineDance:
      return "O5 sine dance";
  }
  return "?";
}

ControllerSession::ControllerSession(DualPlatformController& controller, SessionInputs inputs,
                                     SessionOptions options)
    : controller_(controller), inputs_(std::move(inputs)), options_(std::move(options)) {}

ControllerSession::~ControllerSession() {
  if (recording()) stopRecording();
}

bool ControllerSession::select(Mode mode) {
  if (mode == Mode::ReplayInputs && inputs_.inputs.empty()) {
    spdlog::warn("O3 needs a controller-input file (--replay-ci)");
    return false;
  }
  if (mode == Mode::ReplayJoints && !inputs_.joints) {
    spdlog::warn("O4 needs a robot-state file (--replay-rs)");
    return false;
  }
  mode_ = mode;
  next_row_ = 0;
  clamped_rows_ = 0;
  controller_.beginMode();
  if (mode == Mode::Manual || mode == Mode::ReplayInputs) controller_.readPose();
  if (mode == Mode::ReplayInputs) {  // the released controller waits a second after loading
    const double until = controller_.platforms().front().platform->now() + options_.replay_delay;
    while (controller_.platforms().front().platform->now() + 0.5 * controller_.period() < until) {
      controller_.idle();
    }
  }
  spdlog::info("mode {}", modeName(mode));
  return true;
}

void ControllerSession::startRecording() {
  if (recording()) return;
  const std::string stem = options_.record_name + "_" + timestamp();
  const auto& platforms = controller_.platforms();
  for (const auto& slot : platforms) {
    const std::string suffix = platforms.size() > 1 ? "_" + slot.name : "";
    rs_.push_back(
        std::make_unique<recording::RsWriter>(options_.out_dir / (stem + suffix + "_rs.csv")));
    files_.push_back(rs_.back()->path());
    const bool has_forces = slot.platform->measuredCf(raven::Arm::Left).has_value();
    cf_.push_back(
        has_forces ? std::make_unique<recording::CfWriter>(recording::cfPathFor(rs_.back()->path()))
                   : nullptr);
    if (cf_.back()) files_.push_back(cf_.back()->path());
  }
  ci_ = std::make_unique<recording::CiWriter>(options_.out_dir / (stem + "_ci.csv"));
  files_.push_back(options_.out_dir / (stem + "_ci.csv"));
  spdlog::info("recording to {}", (options_.out_dir / stem).string());
}

std::size_t ControllerSession::stopRecording() {
  const std::size_t rows = rs_.empty() ? 0 : rs_.front()->rows();
  rs_.clear();
  cf_.clear();
  ci_.reset();
  spdlog::info("recording stopped ({} rows)", rows);
  return rows;
}

void ControllerSession::record(const std::optional<recording::GamepadState>& pad) {
  if (!recording() && !options_.on_state) return;
  const auto& platforms = controller_.platforms();
  for (std::size_t i = 0; i < platforms.size(); ++i) {
    const auto state = platforms[i].platform->ravenState();
    if (!state) continue;
    if (options_.on_state) options_.on_state(i, *state);
    if (!recording()) continue;
    rs_[i]->write(*state);
    if (cf_[i]) {
      const auto& p = *platforms[i].platform;
      cf_[i]->write(state->time, {p.measuredCf(raven::Arm::Left), p.measuredCf(raven::Arm::Right)});
    }
  }
  if (pad && ci_) ci_->write(*pad);
}

void ControllerSession::report(const IterationReport& r) {
  if (options_.on_iteration) options_.on_iteration(r);
  if (r.clamped && inputs_.gamepad) inputs_.gamepad->rumble();
  if (r.refused > 0 && refusals_logged_++ < 5) {
    spdlog::warn("{} command(s) refused: {}", r.refused, r.refusal);
  }
}

void ControllerSession::finishReplay() {
  spdlog::info("{}: end of file after {} rows", modeName(mode_), next_row_);
  if (clamped_rows_ > 0) {
    spdlog::warn("{}: {} of {} rows were clamped to the joint limits", modeName(mode_),
                 clamped_rows_, next_row_);
  }
  mode_ = Mode::Idle;
  if (options_.end_after_replay) quit_ = true;
}

bool ControllerSession::turn() {
  if (quit_) return false;
  switch (mode_) {
    case Mode::Idle:
      controller_.idle();
      break;
    case Mode::Homing:
      record(std::nullopt);
      report(controller_.home());
      spdlog::info("O1: at the home joints");
      mode_ = Mode::Idle;
      break;
    case Mode::Manual: {
      const auto read_pad = [this]() -> std::optional<recording::GamepadState> {
        auto reading = inputs_.gamepad ? inputs_.gamepad->read() : std::nullopt;
        if (reading && options_.gate) reading = options_.gate(*reading);
        return reading;
      };
      const auto pad = read_pad();
      if (!pad) {  // unplugged (or never there): no motion, and say so once
        if (!warned_padless_) spdlog::warn("O2: no gamepad connected; holding still");
        warned_padless_ = true;
        ++padless_turns_;
        controller_.idle();
        break;
      }
      if (warned_padless_) controller_.readPose();  // back from an unplug: from where we are
      warned_padless_ = false;
      record(pad);
      report(controller_.manual(*pad, read_pad));
      break;
    }
    case Mode::ReplayInputs:
      if (next_row_ >= inputs_.inputs.size()) {
        finishReplay();
        break;
      }
      record(inputs_.inputs[next_row_]);
      report(controller_.manual(inputs_.inputs[next_row_++]));
      break;
    case Mode::ReplayJoints: {
      const recording::RsRecording& rs = *inputs_.joints;
      if (next_row_ >= rs.rows.size()) {
        finishReplay();
        break;
      }
      record(std::nullopt);
      const ArmPair joints{rs.joints(next_row_, Arm::Left), rs.joints(next_row_, Arm::Right)};
      const IterationReport moved =
          controller_.replayJoints(joints, rs.time(next_row_) - rs.time(0));
      if (moved.clamped && clamped_rows_++ == 0) {
        spdlog::warn(
            "{}: data row {} asks for joints beyond the limits; clamped to them (the "
            "count of such rows follows at the end)",
            rs.path.string(), next_row_ + 1);
      }
      report(moved);
      ++next_row_;
      break;
    }
    case Mode::SineDance:
      record(std::nullopt);
      report(controller_.sineDance());
      break;
  }
  return !quit_;
}

}  // namespace controller
