#pragma once
// Our Raven-II arm's build: link shapes, masses and actuator limits around the kinematic chain.
// The one source of these values: the model generator writes them into the ADF files, and the
// scenario reads the jaw length from here.

#include <Eigen/Core>
#include <array>

namespace raven::design {

/// Everything about an arm's build that the kinematics does not fix (our own design).
struct ArmDesign {
  double link1_radius = 0.22;  ///< link 1 arc around the remote centre (m)
  double link2_radius = 0.30;  ///< link 2 arc
  double link_radius = 0.016;  ///< capsule radius of the arcs
  double rail_near = 0.20;     ///< insertion rail on link 2, distance from the remote centre
  double rail_far = 0.62;
  Eigen::Vector3d carriage_size{0.05, 0.05, 0.07};
  double shaft_radius = 0.0042;  ///< 8.4 mm instrument shaft
  double wrist_radius = 0.0025;
  double jaw_length = 0.011, jaw_width = 0.0022, jaw_thickness = 0.005;
  // The instrument's masses (kg), plausible for a laparoscopic one. Links 1 and 2, and the
  // carriage with the instrument, weigh what the robot's own gravity model says (FirmwareLinks).
  double shaft_mass = 0.08, wrist_mass = 0.006, jaw_mass = 0.003;
  /// Serrated grasper jaws: about 3 N of pinch holds a 5 N pull (Heijnsdijk et al. 2004, Surg
  /// Endosc 18:974-979), mu ~ 0.8; the ring's kDF (0.8) times this friction gives it.
  double jaw_friction = 1.0;
  /// Reflected motor inertia behind the instrument's cable-driven joints (kg m^2): roll on the
  /// shaft, wrist and jaws. A 1e-6 kg m^2 rotor behind a 5:1 capstan stage gives 2.5e-5.
  double shaft_armature = 1e-4, wrist_armature = 5e-5, jaw_armature = 2e-5;
  /// Actuator limits: shoulder, elbow (N m), insertion (N), roll, wrist, jaws (N m).
  std::array<double, 6> max_effort{12.0, 12.0, 25.0, 0.4, 0.2, 0.15};
  /// Servo speed limits (rad/s, m/s): the firmware's V_MAX of 3 rad/s for the revolute joints
  /// (reference section A); 0.5 m/s for the insertion (our choice).
  std::array<double, 6> max_velocity{3.0, 3.0, 0.5, 3.0, 3.0, 3.0};
};

}  // namespace raven::design
