#include "bridge/operating_state.hpp"

#include <array>
#include <utility>

namespace bridge {

namespace {

constexpr std::array<std::pair<OperatingState, std::string_view>, 4> kStateNames{{
    {OperatingState::Disabled, "DISABLED"},
    {OperatingState::Enabled, "ENABLED"},
    {OperatingState::Paused, "PAUSED"},
    {OperatingState::Fault, "FAULT"},
}};

constexpr std::array<std::pair<StateCommand, std::string_view>, 6> kCommandNames{{
    {StateCommand::Enable, "enable"},
    {StateCommand::Disable, "disable"},
    {StateCommand::Pause, "pause"},
    {StateCommand::Resume, "resume"},
    {StateCommand::Home, "home"},
    {StateCommand::Unhome, "unhome"},
}};

template <typename Enum, std::size_t N>
std::string_view nameOf(const std::array<std::pair<Enum, std::string_view>, N>& table, Enum e) {
  for (const auto& [value, name] : table) {
    if (value == e) return name;
  }
  return "?";
}

template <typename Enum, std::size_t N>
std::optional<Enum> valueOf(const std::array<std::pair<Enum, std::string_view>, N>& table,
                            std::string_view text) {
  for (const auto& [value, name] : table) {
    if (name == text) return value;
  }
  return std::nullopt;
}

std::string refusal(StateCommand command, OperatingState state) {
  std::string why = "'";
  why.append(wireName(command)).append("' is not valid in state ").append(wireName(state));
  return why;
}

}  // namespace

std::string_view wireName(OperatingState state) {
  return nameOf(kStateNames, state);
}
std::optional<OperatingState> parseOperatingState(std::string_view text) {
  return valueOf(kStateNames, text);
}
std::string_view wireName(StateCommand command) {
  return nameOf(kCommandNames, command);
}
std::optional<StateCommand> parseStateCommand(std::string_view text) {
  return valueOf(kCommandNames, text);
}

CommandResult OperatingStateMachine::apply(StateCommand command) {
  const OperatingState state = status_.state;
  switch (command) {
    case StateCommand::Enable:
      if (state != OperatingState::Disabled && state != OperatingState::Fault) break;
      status_.state = OperatingState::Enabled;
      fault_reason_.clear();
      return CommandResult::ok();
    case StateCommand::Disable:
      status_ = OperatingStatus{};
      homing_ = false;
      return CommandResult::ok();
    case StateCommand::Pause:
      if (state != OperatingState::Enabled) break;
      status_.state = OperatingState::Paused;
      status_.is_busy = false;
      homing_ = false;
      return CommandResult::ok();
    case StateCommand::Resume:
      if (state != OperatingState::Paused) break;
      status_.state = OperatingState::Enabled;
      return CommandResult::ok();
    case StateCommand::Home:
      if (state != OperatingState::Enabled) break;
      status_.is_homed = false;
      status_.is_busy = true;
      homing_ = true;
      return CommandResult::ok();
    case StateCommand::Unhome:
      if (state != OperatingState::Enabled) break;
      status_.is_homed = false;
      status_.is_busy = false;
      homing_ = false;
      return CommandResult::ok();
  }
  return CommandResult::refused(refusal(command, state));
}

void OperatingStateMachine::fault(std::string why) {
  status_.state = OperatingState::Fault;
  status_.is_busy = false;
  homing_ = false;
  fault_reason_ = std::move(why);
}

void OperatingStateMachine::homingDone() {
  homing_ = false;
  status_.is_busy = false;
  status_.is_homed = true;
}

}  // namespace bridge
