#pragma once
// A test fixture: the shipped peg-transfer scene on the simulated clock, the left arm taking ring1
// through the scripted routine (the path a pad's iterations take), the right arm still.

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>

#include "raven/platform_profile.hpp"
#include "scenario/arm_routine.hpp"
#include "scenario/peg_layout.hpp"
#include "scenario/scripted_session.hpp"
#include "twin/world_perception.hpp"

namespace scenario_test {

/// The peg-transfer scene with every ring awake (a sleeping ring reports no contacts), changed
/// further by `adjust` if given.
inline twin::TwinOptions pegScene(std::function<void(ambf_like::SceneSpec&)> adjust = {}) {
  twin::TwinOptions options;
  options.launch_file = raven::modelDirectory() / "peg_transfer" / "launch.yaml";
  options.adjust_scene = [adjust](ambf_like::SceneSpec& scene) {
    scene.world.soft_body_sleep.enabled = false;
    if (adjust) adjust(scene);
  };
  return options;
}

/// The left arm and ring1.
class OneArmGrasp : public ::testing::Test {
 protected:
  explicit OneArmGrasp(double squeeze = scenario::ArmRoutine::kDefaultSqueeze,
                       const twin::TwinOptions& options = pegScene())
      : session_(options),
        routine_(raven::Arm::Left, raven::builtinProfile("physical"), layout_, {layout_.jobs[0]},
                 squeeze) {
    session_.makeReady(60.0);
  }

  ambf_like::World& world() { return session_.twin().world(); }
  const ambf_like::SoftBody& ring() { return world().softBody("ring1"); }
  double ringBottom() {
    double low = std::numeric_limits<double>::infinity();
    for (const auto& p : ring().nodePositions()) low = std::min(low, p.z());
    return low;
  }
  /// One manual-loop iteration of the routine; the report of the controller's move.
  controller::IterationReport iterate() {
    auto& controller = session_.controller();
    const auto current = controller.commanded();
    const auto measured = session_.twin().measuredJs(raven::Arm::Left).position;
    return controller.moveTo({routine_.next(current[0], measured, scene_), current[1]});
  }
  /// Iterates until the routine enters `phase` (at most `limit` iterations), calling `each`
  /// after every iteration.
  void runUntil(scenario::Phase phase, const std::function<void()>& each = {}, int limit = 2000) {
    for (int i = 0; i < limit && routine_.phase() != phase; ++i) {
      iterate();
      if (each) each();
    }
    ASSERT_EQ(routine_.phase(), phase) << "the routine did not get there";
  }
  /// Holds the arms where they are for `seconds`.
  void hold(double seconds) { session_.twin().advance(seconds); }
  /// Commands the left outer jaw to `angle`, the rest of the arm where it is.
  void setOuterJaw(double angle) {
    auto& controller = session_.controller();
    auto target = controller.commanded();
    target[0](raven::kJaw2) = angle;
    controller.moveTo(target);
  }

  scenario::PegLayout layout_;
  scenario::ScriptedSession session_;
  twin::WorldPerception scene_{session_.twin().world()};
  scenario::ArmRoutine routine_;
};

}  // namespace scenario_test
