#pragma once
// The arm layer over a simulated Raven-II: both arms' joint vectors, in a platform profile's
// convention, mapped onto a World's joints, whichever model (ours or AMBF's) is loaded.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/world.hpp"
#include "raven/arm.hpp"
#include "raven/platform_profile.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// Where one Raven joint lives in a simulated model: model value = scale * joint + offset.
struct JointBinding {
  std::string name;  ///< the World's joint name (qualified or unique plain name)
  double scale = 1.0;
  double offset = 0.0;
};

/// The seven joints of each arm in a model.
struct ArmBindings {
  raven::PerArm<std::array<JointBinding, kJointCount>> joints;
  /// The jaws' opening (jaw1 + jaw2, rad) at which their gripping faces meet, where the model's
  /// jaws stop on each other; none where the model lets them pass through each other.
  std::optional<double> jaws_meet;

  /// This project's Raven-II (raven_description/models): joints named /raven2/<arm>/<joint>.
  /// Its jaws meet at opening 0: each jaw's gripping face is the plane of its frame's x and z
  /// axes, the other jaw's body lies on the far side of it (jaw1 at y >= 0, jaw2 at y <= 0), and
  /// opening 0 puts the two frames together.
  static ArmBindings ourRaven();
  /// AMBF's blender-raven2.yaml, driven with the `ambf` profile as the paper's controller drove
  /// it: joint values as they are, except the right arm's jaws, which AMBF turns the other way.
  /// Its jaws pass through each other, as in AMBF.
  static ArmBindings ambfRaven();
};

/// Commands and reads both arms of a Raven-II inside a World.
class TwinArms {
 public:
  /// Throws std::out_of_range naming the first bound joint the World does not have. Where the
  /// bindings say the jaws meet and an arm is articulated, its jaws get their stop (a
  /// CoupledStop on jaw1 + jaw2).
  TwinArms(ambf_like::World& world, const ArmBindings& bindings);

  /// Position command for every joint of `arm` (each clamped by its joint's limits in the model).
  /// Throws std::invalid_argument, before moving anything, if a value is NaN or infinite.
  void command(Arm arm, const ArmJoints& joints);
  ArmJoints measured(Arm arm) const;
  /// Puts `arm`'s joints at `joints` moving at `velocities` (see ambf_like::Joint::place).
  void place(Arm arm, const ArmJoints& joints, const ArmJoints& velocities);
  /// The World's names of `arm`'s joints, and how each model value scales with the arm's.
  std::vector<std::string> jointNames(Arm arm) const;
  ArmJoints scales(Arm arm) const;
  /// Whether all of `arm`'s joints are coordinates of articulations (reduced coordinates).
  bool articulated(Arm arm) const;
  /// The model's joint limits of `arm` in the arm's convention: its joints' mechanical stops
  /// (infinite for a joint without limits).
  raven::JointLimits hardStops(Arm arm) const;
  ArmJoints velocities(Arm arm) const;
  /// Joint torques (N m) and the insertion force (N) the drives exert, in the arm's sense.
  ArmJoints efforts(Arm arm) const;
  /// The two jaw bodies of `arm` (the jaw joints' children), qualified names.
  const std::array<std::string, 2>& jawBodies(Arm arm) const { return jaws_[raven::slot(arm)]; }
  /// The jaws' opening where their faces meet (ArmBindings::jaws_meet).
  std::optional<double> jawsMeet() const { return jaws_meet_; }
  /// The World's stop the jaws of `arm` meet at: null where they pass through each other or
  /// the arm is not articulated.
  const ambf_like::CoupledStop* jawStop(Arm arm) const { return jaw_stops_[raven::slot(arm)]; }
  /// Moves the arm's jaws' stop by `offset` (rad of jaw1 + jaw2) from jawsMeet(), where the
  /// robot's faces meet (MotorMechanics::face), and makes it give by `compliance` (rad of
  /// jaw1 + jaw2 per N m on each jaw; MotorMechanics::face_compliance). Nothing without a stop.
  void placeJawsMeet(Arm arm, double offset, double compliance);
  /// Every body the arm's joints connect, qualified names.
  const std::vector<std::string>& bodies(Arm arm) const { return bodies_[raven::slot(arm)]; }

 private:
  struct Bound {
    ambf_like::Joint* joint;
    double scale, offset;
    std::string name;  ///< as bound
  };
  template <typename Read>
  ArmJoints read(Arm arm, Read read) const;
  raven::PerArm<std::array<Bound, kJointCount>> bound_;
  std::array<std::array<std::string, 2>, 2> jaws_;
  raven::PerArm<std::vector<std::string>> bodies_;
  std::optional<double> jaws_meet_;
  /// Where the arm's jaws' stop is without the faces' offset, in the model's coordinates.
  double jawStopLower(Arm arm) const;

  raven::PerArm<ambf_like::CoupledStop*> jaw_stops_{};
};

}  // namespace twin
