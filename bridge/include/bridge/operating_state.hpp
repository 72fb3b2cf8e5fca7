#pragma once
// The CRTK operating state of a robot (DISABLED, ENABLED, PAUSED, FAULT; homed; busy) and the
// state commands that move it, exactly as ../shared/reference/crtk.md describes them.

#include <optional>
#include <string>
#include <string_view>

#include "bridge/command_result.hpp"

namespace bridge {

enum class OperatingState { Disabled, Enabled, Paused, Fault };

/// The CRTK state commands, by their wire names "enable", "disable", ...
enum class StateCommand { Enable, Disable, Pause, Resume, Home, Unhome };

/// What crtk_msgs/operating_state carries.
struct OperatingStatus {
  OperatingState state = OperatingState::Disabled;
  bool is_homed = false;
  bool is_busy = false;

  /// CRTK's "ready": enabled and homed.
  bool ready() const { return state == OperatingState::Enabled && is_homed; }
  bool operator==(const OperatingStatus& o) const {
    return state == o.state && is_homed == o.is_homed && is_busy == o.is_busy;
  }
  bool operator!=(const OperatingStatus& o) const { return !(*this == o); }
};

/// "DISABLED", "ENABLED", "PAUSED", "FAULT".
std::string_view wireName(OperatingState state);
std::optional<OperatingState> parseOperatingState(std::string_view text);
std::string_view wireName(StateCommand command);
/// Exact, lower-case wire names only; anything else is not a command.
std::optional<StateCommand> parseStateCommand(std::string_view text);

/// The transitions of the state machine. `home` and `unhome` are valid only when ENABLED and
/// change only the homed and busy flags; `disable` from any state also forgets the homing (the
/// Raven-II re-homes after an E-stop). Every other pair is refused and changes nothing.
class OperatingStateMachine {
 public:
  const OperatingStatus& status() const { return status_; }

  /// Applies a state command. `home` only starts homing: the owner calls homingDone() when the
  /// arms have arrived.
  CommandResult apply(StateCommand command);
  /// Enters FAULT (from any state), ending any homing; `why` is kept for the log.
  void fault(std::string why);
  const std::string& faultReason() const { return fault_reason_; }

  void setBusy(bool busy) { status_.is_busy = busy; }
  void homingDone();
  bool homing() const { return homing_; }

 private:
  OperatingStatus status_;
  bool homing_ = false;
  std::string fault_reason_;
};

}  // namespace bridge
