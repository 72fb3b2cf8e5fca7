// The CRTK operating-state machine: every state x command pair, valid and invalid.

#include "bridge/operating_state.hpp"

#include <gtest/gtest.h>

namespace {

using bridge::OperatingState;
using bridge::OperatingStateMachine;
using bridge::StateCommand;

/// A machine driven into `state` (homed when asked) through valid commands only.
OperatingStateMachine machineIn(OperatingState state, bool homed = false) {
  OperatingStateMachine m;
  if (state == OperatingState::Disabled) return m;
  EXPECT_TRUE(m.apply(StateCommand::Enable));
  if (homed) {
    EXPECT_TRUE(m.apply(StateCommand::Home));
    m.homingDone();
  }
  if (state == OperatingState::Paused) {
    EXPECT_TRUE(m.apply(StateCommand::Pause));
  }
  if (state == OperatingState::Fault) m.fault("test");
  return m;
}

struct Transition {
  OperatingState from;
  StateCommand command;
  bool valid;
  OperatingState to;
};

TEST(OperatingState, EveryPairOfStateAndCommand) {
  using S = OperatingState;
  using C = StateCommand;
  const Transition table[] = {
      {S::Disabled, C::Enable, true, S::Enabled},  {S::Disabled, C::Disable, true, S::Disabled},
      {S::Disabled, C::Pause, false, S::Disabled}, {S::Disabled, C::Resume, false, S::Disabled},
      {S::Disabled, C::Home, false, S::Disabled},  {S::Disabled, C::Unhome, false, S::Disabled},
      {S::Enabled, C::Enable, false, S::Enabled},  {S::Enabled, C::Disable, true, S::Disabled},
      {S::Enabled, C::Pause, true, S::Paused},     {S::Enabled, C::Resume, false, S::Enabled},
      {S::Enabled, C::Home, true, S::Enabled},     {S::Enabled, C::Unhome, true, S::Enabled},
      {S::Paused, C::Enable, false, S::Paused},    {S::Paused, C::Disable, true, S::Disabled},
      {S::Paused, C::Pause, false, S::Paused},     {S::Paused, C::Resume, true, S::Enabled},
      {S::Paused, C::Home, false, S::Paused},      {S::Paused, C::Unhome, false, S::Paused},
      {S::Fault, C::Enable, true, S::Enabled},     {S::Fault, C::Disable, true, S::Disabled},
      {S::Fault, C::Pause, false, S::Fault},       {S::Fault, C::Resume, false, S::Fault},
      {S::Fault, C::Home, false, S::Fault},        {S::Fault, C::Unhome, false, S::Fault},
  };
  for (const auto& t : table) {
    auto m = machineIn(t.from);
    const auto before = m.status();
    const auto result = m.apply(t.command);
    SCOPED_TRACE(std::string(wireName(t.from)) + " + " + std::string(wireName(t.command)));
    EXPECT_EQ(result.accepted, t.valid) << result.note;
    EXPECT_EQ(m.status().state, t.to);
    if (!t.valid) {
      EXPECT_EQ(m.status(), before) << "a refused command must change nothing";
      EXPECT_NE(result.note.find("not valid in state"), std::string::npos) << result.note;
    }
  }
}

TEST(OperatingState, HomingIsBusyUntilDoneAndThenHomed) {
  auto m = machineIn(OperatingState::Enabled);
  ASSERT_TRUE(m.apply(StateCommand::Home));
  EXPECT_TRUE(m.status().is_busy);
  EXPECT_FALSE(m.status().is_homed);
  EXPECT_FALSE(m.status().ready());
  m.homingDone();
  EXPECT_FALSE(m.status().is_busy);
  EXPECT_TRUE(m.status().ready());
  ASSERT_TRUE(m.apply(StateCommand::Unhome));
  EXPECT_FALSE(m.status().is_homed);
}

TEST(OperatingState, DisableForgetsTheHomingPauseKeepsIt) {
  auto paused = machineIn(OperatingState::Paused, /*homed=*/true);
  EXPECT_TRUE(paused.status().is_homed);
  ASSERT_TRUE(paused.apply(StateCommand::Resume));
  EXPECT_TRUE(paused.status().ready());
  ASSERT_TRUE(paused.apply(StateCommand::Disable));
  EXPECT_FALSE(paused.status().is_homed);
}

TEST(OperatingState, FaultEndsHomingAndEnableRetries) {
  auto m = machineIn(OperatingState::Enabled);
  ASSERT_TRUE(m.apply(StateCommand::Home));
  m.fault("encoder lost");
  EXPECT_EQ(m.status().state, OperatingState::Fault);
  EXPECT_FALSE(m.status().is_busy);
  EXPECT_FALSE(m.homing());
  EXPECT_EQ(m.faultReason(), "encoder lost");
  ASSERT_TRUE(m.apply(StateCommand::Enable));
  EXPECT_TRUE(m.faultReason().empty());
}

TEST(OperatingState, WireNamesRoundTripAndAreExact) {
  for (auto c : {StateCommand::Enable, StateCommand::Disable, StateCommand::Pause,
                 StateCommand::Resume, StateCommand::Home, StateCommand::Unhome}) {
    EXPECT_EQ(bridge::parseStateCommand(wireName(c)), c);
  }
  for (auto s : {OperatingState::Disabled, OperatingState::Enabled, OperatingState::Paused,
                 OperatingState::Fault}) {
    EXPECT_EQ(bridge::parseOperatingState(wireName(s)), s);
  }
  EXPECT_FALSE(bridge::parseStateCommand("Enable"));
  EXPECT_FALSE(bridge::parseStateCommand("enable "));
  EXPECT_FALSE(bridge::parseStateCommand(""));
}

}  // namespace
