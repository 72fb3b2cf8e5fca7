#pragma once
// The paper's wide-range motion task D_II as a scripted scenario: both arms trace a rectangle
// in the XY plane under the M2 mapping, driven by pad readings (both sticks together) through
// DualPlatformController::manual(), exactly as a live pad or an O3 replay would drive them.
// The readings are written as a ci file (replayable on the physical robot with O3) and the
// robot state as an rs file.

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "common/actuation_kind.hpp"
#include "controller/gamepad_mapping.hpp"
#include "recording/gamepad_state.hpp"
#include "scenario/run_progress.hpp"
#include "scenario/run_timing.hpp"

namespace scenario {

/// The rectangle and how it is driven.
struct RectangleOptions {
  double width = 0.03;      ///< along x (m); 40 mm takes the right elbow to its limit
  double depth = 0.02;      ///< along y (m)
  double deflection = 1.0;  ///< how far the sticks are pushed (1: full; past the deadzone)
  int dwell = 25;           ///< neutral readings after each edge (the operator's pause)
  /// The Raven-II's motor-level actuation (the shipped calibration), or ideal joint servos.
  common::ActuationKind actuation = common::ActuationKind::Motors;
  std::filesystem::path rs_file, ci_file;  ///< recordings; empty: none
  double time_limit = 60.0;                ///< simulated seconds
  ProgressCallback progress;
};

/// The pad readings that trace the rectangle: +x, +y, -x, -y, both sticks alike, each edge a
/// whole number of iterations at the mapping's metres per loop. Throws std::invalid_argument
/// when the deflection is inside the deadzone or the rectangle is not positive and finite.
std::vector<recording::GamepadState> rectangleInputs(const RectangleOptions& options,
                                                     const controller::MappingConstants& mapping);

/// One run of the rectangle task.
struct RectangleResult {
  /// Per arm, the measured wrist point P5 (what M2 drives) at the start and after every
  /// manual-loop iteration (controller frame, m).
  raven::PerArm<std::vector<Eigen::Vector3d>> wrist_path;
  std::size_t iterations = 0;
  std::size_t refused = 0;  ///< commands the platform refused
  std::size_t clamped = 0;  ///< iterations where a target hit a joint limit
  bool timed_out = false;
  RunTiming timing;
  std::filesystem::path rs_file, ci_file;

  /// Per arm: the path's extent along x and y, and its height range along z (m).
  Eigen::Vector3d extent(raven::Arm arm) const;
  nlohmann::json json() const;
};

RectangleResult runRectangle(const RectangleOptions& options);

}  // namespace scenario
