#pragma once
// The mechanics behind each Raven-II motor, on the scale the robot logs torques (N m at the
// gearbox output, per motor radian): the inertia the motor moves (rotor, gearbox and the link
// reflected through its cable), Coulomb friction (a constant part and a part that grows with the
// torque transmitted: the gearbox's and capstans' efficiency loss), its asymmetry, viscous
// friction, and how far the firmware's gravity compensation is from the arm's real weight.

#include <array>
#include <limits>
#include <string>
#include <string_view>

#include "twin/vocabulary.hpp"

namespace twin {

/// Per motor, in raven::ArmJoints order. The values the reference leaves unknown (§8 of
/// raven2-actuation.md) are fitted by raven_calibrate.
struct MotorMechanics {
  ArmJoints inertia = ArmJoints::Constant(1e-4);  ///< N m s^2 per motor rad
  ArmJoints coulomb = ArmJoints::Zero();          ///< N m
  /// Coulomb friction per N m of torque the motor applies (0 .. 0.9): efficiency loss.
  ArmJoints load_friction = ArmJoints::Zero();
  ArmJoints viscous = ArmJoints::Zero();  ///< N m s per motor rad
  /// A constant torque every move overcomes (N m): moving up takes coulomb + offset, moving down
  /// coulomb - offset. Asymmetric Coulomb friction and the amplifier's zero offset, the offset
  /// term of the standard identification model (Gautier & Khalil).
  ArmJoints offset = ArmJoints::Zero();
  /// The jaws only: each jaw's angle (rad, from the model's zero) at which its face meets the
  /// other's, in the encoders' terms: the pair stops at jaw1 + jaw2 = face(jaw1) + face(jaw2)
  /// over where the model's meshes meet. Where the robot's jaw faces meet is no number the
  /// reference gives (the tool's homing and its wear set it); the data do.
  ArmJoints face = ArmJoints::Zero();
  /// The jaws only: how far each jaw gives (rad) per N m its joint is pressed with where the
  /// faces meet: its cable stretching and its face in series. The pair gives by the sum of the
  /// two (only the sum shows in the data); 0, the default, is a rigid stop.
  ArmJoints face_compliance = ArmJoints::Zero();
  /// The arm motors only: friction beyond the cable (N m at the motor; the joint's bearings and
  /// the pulleys the cable runs over), which the cable takes up as it stretches. A motor turns
  /// against it while its cable stretches or unwinds and the link stands, so after a reversal
  /// it moves under less torque than it slides under; the motor's own `coulomb` holds it still.
  ArmJoints cable_friction = ArmJoints::Zero();
  /// The arm motors only: how far the motor turns (motor rad) while its cable's stretch comes to
  /// carry all of `cable_friction` (the friction over the cable's stiffness); 0: a rigid cable,
  /// whose friction beyond acts as the motor's own.
  ArmJoints cable_travel = ArmJoints::Zero();
  /// The arm's weight over the firmware's estimate, minus one (joints 1-3): 0 = exact.
  ArmJoints gravity_error = ArmJoints::Zero();

  /// The fields in a fixed order: calibration files, fits and their uncertainty use it.
  static constexpr std::array<std::string_view, 10> kNames{
      "inertia", "coulomb",         "load_friction",  "viscous",      "offset",
      "face",    "face_compliance", "cable_friction", "cable_travel", "gravity_error"};
  static constexpr int kOffset = 4;          ///< its index: a value that may be negative
  static constexpr int kFace = 5;            ///< its index: only the jaws have one, of either sign
  static constexpr int kFaceCompliance = 6;  ///< its index: only the jaws have one
  static constexpr int kCableFriction = 7;   ///< its index: only the arm motors have one
  static constexpr int kCableTravel = 8;     ///< its index: only the arm motors have one
  static constexpr int kGravityError = 9;    ///< its index (the last): only the arm motors have one
  /// The pair's meeting over the model's (rad of jaw1 + jaw2): the sum of the jaws' faces.
  double jawsMeetOffset() const;
  /// How far the pair closes past where its faces meet (rad of jaw1 + jaw2) per N m each jaw's
  /// joint is pressed with: the sum of the jaws' face compliances (0: a rigid stop).
  double jawsMeetCompliance() const;
  /// The Coulomb friction that stops the motors when `torque` drives them (N m): their own, its
  /// part that grows with the torque, and the friction beyond a rigid cable.
  ArmJoints stickingFriction(const ArmJoints& torque) const;
  /// What a field's values can be: at least `low` (more than it when `open`), at most `high`.
  struct ValueRange {
    double low, high;
    bool open;
    const char* says;
  };
  static constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  /// Per field, in kNames order.
  static constexpr std::array<ValueRange, kNames.size()> kRanges{
      {{0.0, kUnbounded, true, "> 0"},
       {0.0, kUnbounded, false, ">= 0"},
       {0.0, 0.9, false, "within 0..0.9"},
       {0.0, kUnbounded, false, ">= 0"},
       {-kUnbounded, kUnbounded, false, "finite"},
       {-0.5, 0.5, false, "within -0.5..0.5 rad"},
       {0.0, 2.0, false, "within 0..2 rad per N m"},
       {0.0, kUnbounded, false, ">= 0"},
       {0.0, 10.0, false, "within 0..10 motor rad"},
       {-1.0, kUnbounded, true, "> -1"}}};
  ArmJoints& field(std::size_t k);
  const ArmJoints& field(std::size_t k) const;

  /// Why these values cannot be used (naming the field), or empty when they can.
  std::string invalidReason() const;
  /// Itself; throws std::invalid_argument naming `arm` and the field when invalidReason says so.
  const MotorMechanics& checked(Arm arm) const;
};

/// Both arms' mechanics, the left first.
using ArmsMechanics = raven::PerArm<MotorMechanics>;

/// Each arm motor's cable stretched against the friction beyond it (MotorMechanics::
/// cable_friction and cable_travel): a spring in series with a Coulomb slider, Prandtl's play
/// element. The stretch follows the motor until it carries the whole friction; the link then
/// slides and the stretch stays.
class CableStretch {
 public:
  /// Follows the motors turning by `motion` (motor rad).
  void follow(const MotorMechanics& m, const ArmJoints& motion);
  /// The torque the cables hold the motors back with (N m; along their stretch).
  ArmJoints torque(const MotorMechanics& m) const;
  void release() { stretch_.setZero(); }

 private:
  ArmJoints stretch_ = ArmJoints::Zero();  ///< motor rad
};

/// Motor angles and speeds of one arm, stepped under the amplifiers' torque.
class MotorAxes {
 public:
  explicit MotorAxes(const MotorMechanics& mechanics) : mechanics_(mechanics) {}

  /// Advances `seconds` with `torque` held (N m at the gearbox output) against gravity's
  /// `gravity_load` (the firmware's estimate; the real weight is (1 + gravity_error) times it)
  /// and the mechanics' constant offset.
  void step(const ArmJoints& torque, const ArmJoints& gravity_load, double seconds);
  void place(const ArmJoints& position, const ArmJoints& velocity) {
    position_ = position;
    velocity_ = velocity;
    cables_.release();
  }
  const ArmJoints& position() const { return position_; }  ///< motor rad
  const ArmJoints& velocity() const { return velocity_; }
  const MotorMechanics& mechanics() const { return mechanics_; }

  /// Substeps per step: friction's stick-slip and the stiffest tool axis stay resolved.
  static constexpr int kSubsteps = 4;

 private:
  MotorMechanics mechanics_;
  ArmJoints position_ = ArmJoints::Zero();
  ArmJoints velocity_ = ArmJoints::Zero();
  CableStretch cables_;
};

}  // namespace twin
