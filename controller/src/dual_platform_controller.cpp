#include "controller/dual_platform_controller.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "raven/control_cycle.hpp"

namespace controller {

namespace {

ArmPair measuredOf(const bridge::RavenPlatform& platform) {
  return {platform.measuredJs(Arm::Left).position, platform.measuredJs(Arm::Right).position};
}

}  // namespace

DualPlatformController::DualPlatformController(std::vector<PlatformSlot> platforms,
                                               ControllerOptions options)
    : platforms_(std::move(platforms)),
      options_(std::move(options)),
      profile_(raven::builtinProfile(options_.profile)),
      commanded_(measuredOf(*platforms_.at(0).platform)),
      mapping_(profile_, options_.scheme, commanded_, options_.mapping) {
  if (!(options_.rate >= 1.0 && options_.rate <= raven::kControlRate)) {
    throw std::invalid_argument("the command rate must be 1.." +
                                std::to_string(int(raven::kControlRate)) +
                                " Hz (one command per robot cycle at most)");
  }
  if (!(options_.iteration_overhead >= 0.0 && options_.iteration_overhead <= 1.0)) {
    throw std::invalid_argument("the iteration overhead must be within 0..1 s");
  }
}

ArmPair DualPlatformController::measured(const PlatformSlot& slot) const {
  return measuredOf(*slot.platform);
}

bool DualPlatformController::holdAtFollowingLimit(InterpolationPlan& plan, int done,
                                                  ArmPair& jump) const {
  const bridge::RavenPlatform& robot = *platforms_.front().platform;
  const FollowingLimit& limit = *options_.following_limit;
  const std::optional<bridge::RavenStateSnapshot> state = robot.ravenState();
  const raven::ArmJoints most_back = options_.caps.perStep(period());
  const ArmPair now = plan.at(done);
  const ArmPair next = plan.at(done + 1);
  bool held = false;
  for (Arm arm : raven::kArms) {
    const auto a = raven::slot(arm);
    const raven::ArmJoints lead = robot.setpointJs(arm).position - robot.measuredJs(arm).position;
    for (int i = 0; i < raven::kJointCount; ++i) {
      const auto hold_at = [&](double position) {
        plan.start[a](i) = position;
        plan.delta[a](i) = 0.0;
        held = true;
      };
      if (std::abs(lead(i)) > limit.lead(i) && lead(i) * plan.delta[a](i) > 0.0) hold_at(now[a](i));
      if (!state) continue;
      const double torque = state->tau[static_cast<std::size_t>(bridge::ravenStateIndex(arm, i))];
      const double past = std::abs(torque) - limit.torque(i);
      if (!(past > 0.0)) continue;
      // Never past the joint's limit: the robot clamps its setpoint there, so a setpoint drawn
      // on beyond it relieves nothing and would run away from the arm a command at a time.
      const double relieved = std::clamp(
          now[a](i) - std::copysign(std::min(past * limit.give(i), most_back(i)), torque),
          profile_.limits.low(i), profile_.limits.high(i));
      if ((next[a](i) - relieved) * torque > 0.0) {  // the move would push on past it
        jump[a](i) = relieved - now[a](i);
        hold_at(relieved);
      }
    }
  }
  return held;
}

void DualPlatformController::readPose() {
  commanded_ = measured(platforms_.front());
  mapping_.reset(commanded_);
}

void DualPlatformController::clamp(ArmPair& joints, IterationReport& report) const {
  for (auto& q : joints) {
    const raven::ArmJoints before = q;
    q = q.cwiseMax(profile_.limits.low).cwiseMin(profile_.limits.high);
    report.clamped = report.clamped || q != before;
  }
}

void DualPlatformController::send(const InterpolationPlan& plan, int k, IterationReport& report,
                                  const ArmPair& jump) {
  const ArmPair positions = plan.at(k);
  const ArmPair increment = plan.increment(k);
  for (const PlatformSlot& slot : platforms_) {
    for (Arm arm : raven::kArms) {
      const auto a = raven::slot(arm);
      const bridge::PlatformCommand command =
          slot.style == CommandStyle::ServoJr
              ? bridge::PlatformCommand{bridge::ServoJr{arm, increment[a] + jump[a]}}
              : bridge::PlatformCommand{bridge::ServoJp{arm, positions[a]}};
      const bridge::CommandResult result = slot.platform->send(command);
      if (!result) {
        if (report.refused++ == 0) report.refusal = slot.name + ": " + result.note;
      }
    }
  }
  since_command_ = 0.0;
}

void DualPlatformController::advanceAll(double seconds) {
  for (const PlatformSlot& slot : platforms_) slot.platform->advance(seconds);
  since_command_ += seconds;
}

bool DualPlatformController::waitPeriod(const std::function<bool()>& stop, bool final) {
  const int cycles = stop ? cyclesPerPeriod() : 1;
  for (int c = 1; c <= cycles; ++c) {
    advanceAll(period() / cycles);
    if (c == cycles) since_command_ = period();  // (the slices' sum, exactly)
    if ((c < cycles || !final) && stop && stop()) return true;
  }
  return false;
}

int DualPlatformController::cyclesPerPeriod() const {
  return std::max(1, static_cast<int>(std::lround(period() / raven::kControlCycle)));
}

IterationReport DualPlatformController::execute(const ArmPair& next, int most,
                                                const std::function<bool()>& stop, bool following,
                                                const ArmPair* first_jump) {
  const double lead = std::min(since_command_ / period(), 1.0);
  InterpolationPlan plan = planMove(commanded_, next, options_.caps, period(), lead);
  IterationReport report;
  report.capped = plan.steps > options_.caps.min_steps;
  report.steps = std::min(plan.commands(), most);
  for (int k = 1; k <= report.steps; ++k) {
    ArmPair jump{raven::ArmJoints::Zero(), raven::ArmJoints::Zero()};
    if (first_jump && k == 1) jump = *first_jump;
    if (following && holdAtFollowingLimit(plan, k - 1, jump)) {
      report.held_back = true;
      const auto still = [](const ArmPair& p) { return p[0].isZero(0.0) && p[1].isZero(0.0); };
      if (still(plan.delta) && still(jump)) {  // nothing left to move
        report.steps = k - 1;
        break;
      }
    }
    send(plan, k, report, jump);
    if (waitPeriod(stop, k == report.steps)) {
      report.cut_short = k < plan.commands();
      report.steps = k;
    }
  }
  if (report.steps == plan.commands() && !report.held_back) {
    commanded_ = next;
  } else if (report.steps > 0) {
    commanded_ = plan.at(report.steps);
  }
  return report;
}

IterationReport DualPlatformController::home() {
  ArmPair target{profile_.home, profile_.home};
  const IterationReport report = execute(target);
  mapping_.reset(commanded_);
  return report;
}

IterationReport DualPlatformController::manual(const recording::GamepadState& pad,
                                               const LivePad& live) {
  const ArmPair now = measured(platforms_.front());
  // A re-reads the pose: this iteration's move starts where the arms are, so a re-read alone
  // sends no motion (servo_jr increments are taken from the re-read joints, as the released
  // controller takes them).
  if (pad.a) commanded_ = now;
  const MappingResult mapped = mapping_.apply(pad, now);
  ArmPair next = mapped.joints;
  IterationReport clamp_report;
  clamp(next, clamp_report);
  if (first_move_) {  // this iteration's increments: the recorded first move
    for (std::size_t a = 0; a < 2; ++a) commanded_[a] = next[a] - (*first_move_)[a];
    first_move_.reset();
  }
  const auto changed = [&] {
    const auto now_read = live();
    return !now_read || !(*now_read == pad);
  };
  IterationReport report =
      live ? execute(next, std::numeric_limits<int>::max(), changed) : execute(next);
  // Cut short, the targets are part-way: the mapping continues from them.
  if (report.cut_short) mapping_.reset(commanded_);
  report.clamped = mapped.clamped || clamp_report.clamped;
  if (options_.iteration_overhead > 0.0) {
    advanceAll(options_.iteration_overhead);
  }
  return report;
}

void DualPlatformController::beginMode() {
  dance_count_ = 0;
  mode_start_ = platforms_.front().platform->now();
}

IterationReport DualPlatformController::replayJoints(const ArmPair& joints, double due) {
  const IterationReport report = moveTo(joints);
  // The recording's timing: wait (on the platforms' own clocks) until the row is due.
  const auto& reference = *platforms_.front().platform;
  while (reference.now() - mode_start_ + 0.5 * period() < due) idle();
  return report;
}

IterationReport DualPlatformController::sineDance() {
  const double ramp = std::min(static_cast<double>(dance_count_) * dance_.ramp_per_call, 1.0);
  ArmPair next;
  for (Arm arm : raven::kArms) {
    const int a = raven::index(arm);
    for (int i = 0; i < raven::kJointCount; ++i) {
      next[raven::slot(arm)](i) =
          ramp * dance_.scale(i) *
              std::sin(dance_.speed * (static_cast<double>(dance_count_) + (i + a) * M_PI / 2.0)) +
          profile_.home(i);
    }
  }
  ++dance_count_;
  return moveTo(next);
}

IterationReport DualPlatformController::moveTo(const ArmPair& joints) {
  IterationReport report = scriptedMove(joints, std::numeric_limits<int>::max());
  if (options_.arrival) arrive(report);
  return report;
}

void DualPlatformController::arrive(IterationReport& report) {
  const bridge::RavenPlatform& robot = *platforms_.front().platform;
  std::optional<raven::ArmJoints> most_lead;
  if (options_.following_limit) most_lead = options_.following_limit->lead;
  const raven::ArmJoints most_per_step = options_.caps.perStep(period());
  std::array<ArmArrival, 2> arms{
      ArmArrival(*options_.arrival, raven::ArmKinematics::of(profile_, Arm::Left), most_per_step,
                 most_lead, period()),
      ArmArrival(*options_.arrival, raven::ArmKinematics::of(profile_, Arm::Right), most_per_step,
                 most_lead, period())};
  const auto most = std::lround(options_.arrival->most_wait / period());
  for (long k = 0;; ++k) {
    bool arrived = true;
    ArmPair make_up;
    for (Arm arm : raven::kArms) {
      const auto a = raven::slot(arm);
      const bool this_one = arms[a].arrived(commanded_[a], robot.measuredJs(arm).position,
                                            robot.setpointJs(arm).position, make_up[a]);
      arrived = arrived && this_one;
    }
    if (arrived || k == most) return;
    const IterationReport held = holdStill(&make_up);
    if (report.refused == 0) report.refusal = held.refusal;
    report.refused += held.refused;
    ++report.steps;
  }
}

IterationReport DualPlatformController::scriptedMove(const ArmPair& joints, int most) {
  ArmPair next = joints;
  IterationReport clamp_report;
  clamp(next, clamp_report);
  IterationReport report = execute(next, most, {}, options_.following_limit.has_value());
  // Held back before its first command, the move still lasts a period: the arm settles.
  if (report.steps == 0 && report.held_back) {
    idle();
    report.steps = 1;
  }
  report.clamped = clamp_report.clamped;
  mapping_.reset(commanded_);
  return report;
}

IterationReport DualPlatformController::moveFor(const ArmPair& joints, int steps) {
  IterationReport report = scriptedMove(joints, steps);
  for (int k = report.steps; k < steps; ++k) holdStill();
  report.steps = steps;
  return report;
}

void DualPlatformController::idle() {
  advanceAll(period());
}

IterationReport DualPlatformController::holdStill(const ArmPair* make_up) {
  const bool following = options_.following_limit.has_value();
  IterationReport report;
  if (following || make_up) report = execute(commanded_, 1, {}, following, make_up);
  if (report.steps == 0) idle();
  return report;
}

double DualPlatformController::divergence() const {
  if (platforms_.size() < 2) return 0.0;
  const ArmPair a = measured(platforms_[0]);
  const ArmPair b = measured(platforms_[1]);
  return std::max((a[0] - b[0]).cwiseAbs().maxCoeff(), (a[1] - b[1]).cwiseAbs().maxCoeff());
}

}  // namespace controller
