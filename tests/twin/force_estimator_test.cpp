// The twin's model read backwards (twin::ArmForceEstimator): the statics it was given come back,
// friction it cannot see widens the estimate instead of moving it, and a tool pressed on a
// rigid slab in the twin is estimated from the motor signals the robot would log.

#include "twin/force_estimator.hpp"

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "ambf_like/bullet_conversions.hpp"
#include "arm_contacts.hpp"
#include "bridge/raven_state.hpp"
#include "twin/calibration_profile.hpp"
#include "twin/gravity_compensation.hpp"
#include "twin/motor_controller.hpp"
#include "twin_fixtures.hpp"

namespace {

using raven::Arm;
using raven::ArmJoints;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The position Jacobian in the shoulder, elbow and insertion of the point `depth` along the
/// jaws from the tool point (the tool frame's x): central differences of the kinematics' pose
/// of that point (the estimator composes the tool's twist instead).
Eigen::Matrix3d tipJacobian(const raven::ArmKinematics& k, const ArmJoints& q, double depth) {
  constexpr double kStep = 1e-6;
  const Eigen::Vector3d grip(depth, 0.0, 0.0);
  Eigen::Matrix3d j;
  for (int c = 0; c < 3; ++c) {
    const ArmJoints step = kStep * ArmJoints::Unit(c);
    j.col(c) = (k.toolPose(q + step) * grip - k.toolPose(q - step) * grip) / (2.0 * kStep);
  }
  return j;
}

/// A still arm at `q` whose tool pushes `tip` (N, on what it touches) and whose jaws squeeze
/// `jaws` at `depth`: the torques its motors apply when each also holds `friction` (gearbox
/// output scale), as `rows` rows of the signals the robot logs (Tau; no DAC counts).
std::vector<recording::ArmSignals> heldRows(Arm arm, const twin::MotorMechanics& m,
                                            const ArmJoints& q, const Eigen::Vector3d& tip,
                                            const Eigen::Vector2d& jaws, double depth,
                                            const ArmJoints& friction, int rows) {
  const auto drive = twin::DriveTrain::raven2();
  const auto kinematics = raven::ArmKinematics::of(test_support::physicalProfile(), arm);
  ArmJoints contact = ArmJoints::Zero();  // what the world puts on the joints
  contact.head<3>() = tipJacobian(kinematics, q, depth).transpose() * -tip;
  contact(raven::kJaw1) = jaws(0) * depth;
  contact(raven::kJaw2) = jaws(1) * depth;
  const Eigen::Matrix<double, 7, 7> to_joints =
      drive.coupling(arm).transpose() * drive.gearbox.cwiseInverse().asDiagonal();
  const ArmJoints weight =
      (ArmJoints::Ones() + m.gravity_error).cwiseProduct(twin::gravityCompensation(arm, q, drive));
  recording::ArmSignals s;
  s.joints = q;
  s.motor = drive.toMotor(arm, q);
  s.motor_velocity.setZero();
  s.torque = weight + m.offset + friction - to_joints.lu().solve(contact);
  s.dac.setConstant(kNaN);
  s.joint_setpoint = s.joints;
  s.motor_setpoint = s.motor;
  return std::vector<recording::ArmSignals>(static_cast<std::size_t>(rows), s);
}

std::vector<double> times(std::size_t rows, double period) {
  std::vector<double> t;
  for (std::size_t k = 0; k < rows; ++k) t.push_back(static_cast<double>(k) * period);
  return t;
}

twin::MotorMechanics noUncertainty() {
  twin::MotorMechanics u;
  for (std::size_t f = 0; f < twin::MotorMechanics::kNames.size(); ++f) u.field(f).setZero();
  return u;
}

/// How far the estimate at row `at` may move off for the DAC alone: the firmware applies Tau's
/// whole counts, so each motor may lose up to one count; the sum over the motors of what one
/// count of each, taken alone, moves the tip's force and the jaws' (N).
Eigen::Matrix<double, 5, 1> dacResolution(const twin::ArmForceEstimator& estimator, Arm arm,
                                          const std::vector<recording::ArmSignals>& rows,
                                          double period, std::size_t at) {
  const auto dac = twin::DacConversion::raven2(arm);
  const auto forces = [&](const std::vector<recording::ArmSignals>& signals) {
    const auto e = estimator.estimate(times(signals.size(), period), signals)[at];
    Eigen::Matrix<double, 5, 1> f;
    f << e.tip, e.jaw[0], e.jaw[1];
    return f;
  };
  const Eigen::Matrix<double, 5, 1> base = forces(rows);
  Eigen::Matrix<double, 5, 1> resolution = Eigen::Matrix<double, 5, 1>::Zero();
  for (int i = 0; i < raven::kJointCount; ++i) {
    auto counted = rows;
    for (auto& s : counted) s.torque(i) += 1.0 / dac.counts_per_torque(i);
    resolution += (forces(counted) - base).cwiseAbs();
  }
  return resolution;
}

TEST(ForceEstimator, WithoutFrictionTheStaticsComeBack) {
  const auto profile = twin::CalibrationProfile::shipped();
  for (Arm arm : raven::kArms) {
    twin::MotorMechanics m = profile.mechanics[raven::slot(arm)];
    m.coulomb.setZero();
    m.load_friction.setZero();
    m.offset << 0.01, -0.02, 0.03, 0.0, 0.001, -0.002, 0.002;
    const ArmJoints q = test_support::physicalProfile().home;
    const Eigen::Vector3d tip(1.5, -2.0, 3.0);
    const Eigen::Vector2d jaws(2.0, 3.5);
    const auto rows = heldRows(arm, m, q, tip, jaws, 0.007, ArmJoints::Zero(), 5);
    const twin::ArmForceEstimator estimator(
        arm, m, noUncertainty(), raven::ArmKinematics::of(test_support::physicalProfile(), arm));
    const auto e = estimator.estimate(times(rows.size(), 0.001), rows)[2];
    // Tau passes the DAC's whole counts: off by at most a count of each motor.
    const auto off = dacResolution(estimator, arm, rows, 0.001, 2);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(e.tip(i), tip(i), off(i)) << raven::armName(arm) << i;
    EXPECT_NEAR(e.jaw[0], jaws(0), off(3)) << raven::armName(arm);
    EXPECT_NEAR(e.jaw[1], jaws(1), off(4)) << raven::armName(arm);
    EXPECT_LT(e.tip_sd.maxCoeff(), 1e-9) << "nothing uncertain was given";
  }
}

TEST(ForceEstimator, TimesThatRunBackOrDoNotMatchTheRowsAreRefused) {
  const auto profile = twin::CalibrationProfile::shipped();
  const twin::ArmForceEstimator estimator(
      Arm::Left, profile.mechanics[0], noUncertainty(),
      raven::ArmKinematics::of(test_support::physicalProfile(), Arm::Left));
  const auto rows =
      heldRows(Arm::Left, profile.mechanics[0], test_support::physicalProfile().home,
               Eigen::Vector3d::Zero(), Eigen::Vector2d::Zero(), 0.007, ArmJoints::Zero(), 3);
  EXPECT_THROW(estimator.estimate({0.0, 0.002, 0.001}, rows), std::invalid_argument);
  EXPECT_THROW(estimator.estimate({0.0, 0.001}, rows), std::invalid_argument);
  EXPECT_EQ(estimator.estimate({0.0, 0.0, 0.0}, rows).size(), 3u);  // a clock standing still
}

TEST(ForceEstimator, FrictionAtRestWidensTheEstimateToCoverIt) {
  // A motor at rest holds anything within its friction band: the same signals could come from
  // any friction there, so the estimate is the band's middle and its sd the band's (uniform).
  // Frictions drawn across the bands: at least 90 % of the estimates lie within 2 sd of the
  // truth on every channel, and without friction the estimate is the truth.
  const auto profile = twin::CalibrationProfile::shipped();
  const Arm arm = Arm::Right;
  const twin::MotorMechanics& m = profile.mechanics[raven::slot(arm)];
  const ArmJoints q = test_support::physicalProfile().home;
  const Eigen::Vector3d tip(0.5, 1.0, -2.0);
  const Eigen::Vector2d jaws(2.5, 2.5);
  const twin::ArmForceEstimator estimator(
      arm, m, noUncertainty(), raven::ArmKinematics::of(test_support::physicalProfile(), arm));
  const auto exact = estimator.estimate(
      times(3, 0.001), heldRows(arm, m, q, tip, jaws, 0.007, ArmJoints::Zero(), 3))[1];
  EXPECT_NEAR(exact.jaw[0], jaws(0), 0.05);
  EXPECT_NEAR(exact.tip(2), tip(2), 0.1);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> share(-1.0, 1.0);
  constexpr int kDraws = 400;
  std::array<int, 5> within{};
  for (int d = 0; d < kDraws; ++d) {
    ArmJoints friction;  // Tau is small here: each band is about its Coulomb part
    for (int i = 0; i < raven::kJointCount; ++i) friction(i) = share(random) * m.coulomb(i);
    const auto rows = heldRows(arm, m, q, tip, jaws, 0.007, friction, 3);
    const auto e = estimator.estimate(times(rows.size(), 0.001), rows)[1];
    for (int i = 0; i < 3; ++i)
      within[std::size_t(i)] += std::abs(e.tip(i) - tip(i)) <= 2.0 * e.tip_sd(i);
    for (int j = 0; j < 2; ++j) {
      within[std::size_t(3 + j)] +=
          std::abs(e.jaw[std::size_t(j)] - jaws(j)) <= 2.0 * e.jaw_sd[std::size_t(j)];
    }
  }
  for (std::size_t c = 0; c < within.size(); ++c) EXPECT_GE(within[c], 0.9 * kDraws) << c;
}

TEST(ForceEstimator, ASlidingMotorsFrictionIsAtItsBandsEdge) {
  // Motors turning steadily (5 encoder counts per ms) rub at the edge of their band, against the
  // motion, and drag by their viscous friction: the estimate takes both and comes back to the
  // force. Logged every ms (the robot) or every 50 ms (a twin's batch recording, where a row's
  // window holds no other row and its speed is the one the row logged).
  const auto profile = twin::CalibrationProfile::shipped();
  const Arm arm = Arm::Left;
  const twin::MotorMechanics& m = profile.mechanics[raven::slot(arm)];
  const ArmJoints q = test_support::physicalProfile().home;
  const Eigen::Vector3d tip(0.0, 0.0, 2.0);
  const Eigen::Vector2d jaws(3.0, 3.0);
  const double count = 2.0 * M_PI / 4000.0;
  const double speed = 5.0 * count / 0.001;
  for (const double period : {0.001, 0.05}) {
    auto rows = heldRows(arm, m, q, tip, jaws, 0.007, ArmJoints::Zero(), 40);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      auto& s = rows[k];
      s.motor_velocity.setConstant(speed);
      s.motor.array() += speed * period * static_cast<double>(k);
      // Turning forward, each motor applies its load, its viscous drag, its cable's pull (the
      // friction beyond it, taken up over the cable's travel: c min(1, turned / travel)) and the
      // band's edge, which grows with what it applies:
      // applied = load + b w + cable + coulomb + load_friction |applied|.
      const double turned = speed * period * static_cast<double>(k);
      ArmJoints cable = ArmJoints::Zero();
      for (int i = 0; i < raven::kJointCount; ++i) {
        if (m.cable_travel(i) > 0.0) {
          cable(i) = m.cable_friction(i) * std::min(1.0, turned / m.cable_travel(i));
        }
      }
      const ArmJoints load = s.torque + m.viscous * speed + cable;
      for (int it = 0; it < 100; ++it) {
        s.torque = load + m.coulomb + m.load_friction.cwiseProduct(s.torque.cwiseAbs());
      }
    }
    const twin::ArmForceEstimator estimator(
        arm, m, noUncertainty(), raven::ArmKinematics::of(test_support::physicalProfile(), arm));
    const auto e = estimator.estimate(times(rows.size(), period), rows)[20];
    for (bool moving : e.moving) EXPECT_TRUE(moving) << period;
    const auto off = dacResolution(estimator, arm, rows, period, 20);  // Tau's whole counts
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(e.tip(i), tip(i), off(i)) << i << " every " << period;
    EXPECT_NEAR(e.jaw[0], jaws(0), off(3)) << "every " << period << " s";
    EXPECT_NEAR(e.jaw[1], jaws(1), off(4)) << "every " << period << " s";
  }
}

/// `arm`'s signals now, as the robot logs them (the recorder's units undone).
recording::ArmSignals loggedSignals(const twin::TwinPlatform& twin, Arm arm) {
  const auto state = twin.ravenState();
  recording::ArmSignals s;
  s.joints = twin.measuredJs(arm).position;
  s.joint_setpoint = s.joints;
  for (int i = 0; i < raven::kJointCount; ++i) {
    const auto at = static_cast<std::size_t>(bridge::ravenStateIndex(arm, i));
    s.motor(i) = state->mpos[at] * M_PI / 180.0;
    s.motor_velocity(i) = state->mvel[at] * M_PI / 180.0;
    s.motor_setpoint(i) = state->mpos_d[at] * M_PI / 180.0;
    s.torque(i) = state->tau[at];
    s.dac(i) = state->dac_val[at];
  }
  return s;
}

/// A press on the slab: the rows the robot would log, the slab's mean contact force (N) and how
/// far along the jaws from the tool point it pressed (m).
struct Press {
  std::vector<recording::ArmSignals> rows;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  double depth = 0.0;
};

/// The slab's contact force and where it acts (the contacts' force-weighted mean point).
std::pair<Eigen::Vector3d, Eigen::Vector3d> slabContact(const ambf_like::World& world) {
  const Eigen::Vector3d force = test_support::contactForceOn(world, "/test/obstacle");
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  double weight = 0.0;
  for (const auto& c : world.contacts("/test/obstacle")) {
    at += c.normal_impulse * c.position_on_b;
    weight += c.normal_impulse;
  }
  return {force, weight > 0.0 ? Eigen::Vector3d(at / weight) : at};
}

/// The tool pressed on a slab at `pose` by `joint` of `arm` with about `force` (N): the joint
/// moves the tool toward it at 0.5 mm/s until the slab bears a load, then at 0.05 mm/s until it
/// bears `force`, and holds that setpoint. Logged over 0.3 s after 2 s of settling.
Press pressOnSlab(const twin::TwinOptions& motors, const ambf_like::Transform& pose, Arm arm,
                  int joint, double toward, double force) {
  ambf_like::PrimitiveShape slab;
  slab.box_size = Eigen::Vector3d(0.04, 0.04, 0.01);
  auto pressed = test_support::readyTwin(test_support::withObstacle(motors, slab, pose, 0.5));
  const auto kinematics = raven::ArmKinematics::of(test_support::physicalProfile(), arm);
  const double lever =
      tipJacobian(kinematics, pressed->measuredJs(arm).position, twin::GripLever{}.depth)
          .col(joint)
          .norm();
  ArmJoints step = ArmJoints::Zero();
  step(joint) = toward * 5e-7 / lever;
  const auto bearing = [&] { return slabContact(pressed->world()).first.norm() > 0.01; };
  for (int k = 0; k < 100000 && !bearing(); ++k) {
    pressed->send(bridge::ServoJr{arm, step});
    pressed->advance(0.001);
  }
  EXPECT_TRUE(bearing()) << "joint " << joint;
  // Pressed on at 0.05 mm/s until the slab bears `force`, as against a force gauge; held there.
  step *= 0.1;
  for (int k = 0; k < 20000 && slabContact(pressed->world()).first.norm() < force; ++k) {
    pressed->send(bridge::ServoJr{arm, step});
    pressed->advance(0.001);
  }
  pressed->advance(2.0);
  Press press;
  constexpr int kCycles = 300;
  for (int k = 0; k < kCycles; ++k) {
    pressed->advance(0.001);
    press.rows.push_back(loggedSignals(*pressed, arm));
    const auto [f, at] = slabContact(pressed->world());
    press.force += f / kCycles;
    const Eigen::Isometry3d tool = kinematics.toolPose(pressed->measuredJs(arm).position);
    press.depth += (at - tool.translation()).dot(tool.linear().col(0)) / kCycles;
  }
  return press;
}

TEST(ForceEstimator, AToolPressedOnARigidSlabIsEstimatedFromItsMotors) {
  // Acceptance 2 of issue 65: in each direction one of the arm's three joints pushes the tool, a
  // slab across it, pressed with about 1 N and 4 N; frictionless motors (a resting arm's
  // friction is the estimate's uncertainty, tested above). The estimate from the logged signals
  // is within 15 % of the slab's contact force in steady state.
  const twin::TwinOptions motors_only = test_support::frictionlessMotors();
  const auto probe = test_support::readyTwin(motors_only);
  const Arm arm = Arm::Left;
  const auto kinematics = raven::ArmKinematics::of(test_support::physicalProfile(), arm);
  const Eigen::Matrix3d jacobian =
      tipJacobian(kinematics, probe->measuredJs(arm).position, twin::GripLever{}.depth);
  const Eigen::Vector3d jaw_tip =
      probe->world().body("/raven2/left/jaw1_link").pose().translation();
  for (int joint = 0; joint < 3; ++joint) {
    const double toward = joint == raven::kInsertion ? -1.0 : 1.0;  // homing inserts the tool
    const Eigen::Vector3d along = toward * jacobian.col(joint).normalized();
    ambf_like::Transform pose = ambf_like::Transform::Identity();
    pose.translation() = jaw_tip + 0.03 * along;
    pose.linear() =
        Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), along).toRotationMatrix();
    for (const double force : {1.0, 4.0}) {
      const Press press = pressOnSlab(motors_only, pose, arm, joint, toward, force);
      const Eigen::Vector3d& truth = press.force;
      // The force taken where it pressed, as a user who knows the contact tells the estimator.
      const twin::ArmForceEstimator estimator(arm, (*motors_only.motors)[0], noUncertainty(),
                                              kinematics, twin::GripLever{.depth = press.depth});
      Eigen::Vector3d estimate = Eigen::Vector3d::Zero();
      for (const auto& e : estimator.estimate(times(press.rows.size(), 0.001), press.rows)) {
        estimate += e.tip / static_cast<double>(press.rows.size());
      }
      std::printf(
          "joint %d, about %.0f N at %.1f mm: slab force %.3f %.3f %.3f N, estimate %.3f %.3f "
          "%.3f N\n",
          joint, force, 1e3 * press.depth, truth.x(), truth.y(), truth.z(), estimate.x(),
          estimate.y(), estimate.z());
      EXPECT_GT(truth.norm(), 0.5) << "joint " << joint;
      EXPECT_LT(truth.norm(), 6.0) << "joint " << joint;
      EXPECT_LT((estimate - truth).norm(), 0.15 * truth.norm()) << "joint " << joint;
    }
  }
}

}  // namespace

namespace {

TEST(ForceEstimator, JawsSqueezingARigidBallAreEstimatedFromTheirMotors) {
  // Each arm's jaws closed on a rigid ball 7 mm from their pivot (the default grip's depth),
  // frictionless motors: each jaw's estimated squeeze is the ball's contact force on it.
  const twin::TwinOptions motors_only = test_support::frictionlessMotors();
  ambf_like::PrimitiveShape ball;
  ball.type = ambf_like::PrimitiveType::Sphere;
  ball.radius = 0.007 * std::sin(0.25);  // met about 0.5 rad open
  ambf_like::Transform away = ambf_like::Transform::Identity();
  away.translation() = Eigen::Vector3d(0, 0, -1);  // out of the jaws' way while they home
  for (Arm arm : raven::kArms) {
    const twin::TwinOptions options = test_support::withObstacle(motors_only, ball, away, 0.0);
    auto twin = test_support::readyTwin(options);
    ambf_like::World& world = twin->world();
    const std::string prefix = "/raven2/" + std::string(raven::armName(arm)) + "/";
    const auto jaw1 = world.body(prefix + "jaw1_link").pose();
    const auto jaw2 = world.body(prefix + "jaw2_link").pose();
    ambf_like::Transform between = ambf_like::Transform::Identity();
    between.translation() =
        jaw1.translation() + 0.007 * (jaw1.linear().col(0) + jaw2.linear().col(0)).normalized();
    world.body("/test/obstacle").bullet().setWorldTransform(ambf_like::toBt(between));
    ArmJoints close = ArmJoints::Zero();
    close(raven::kJaw1) = close(raven::kJaw2) = -1e-3;
    const auto bothPress = [&] {
      return test_support::touching(*twin, arm, raven::kJaw1) &&
             test_support::touching(*twin, arm, raven::kJaw2);
    };
    for (int k = 0; k < 2000 && !bothPress(); ++k) {
      twin->send(bridge::ServoJr{arm, close});
      twin->advance(0.001);
    }
    ASSERT_TRUE(bothPress()) << raven::armName(arm);
    twin->advance(0.3);
    std::vector<recording::ArmSignals> rows;
    std::vector<Eigen::Vector2d> truth;
    for (int k = 0; k < 300; ++k) {
      twin->advance(0.001);
      rows.push_back(loggedSignals(*twin, arm));
      const auto cf = twin->measuredCf(arm);
      truth.emplace_back(cf->jaws[0].normal.norm(), cf->jaws[1].normal.norm());
    }
    const twin::ArmForceEstimator estimator(
        arm, (*motors_only.motors)[raven::slot(arm)], noUncertainty(),
        raven::ArmKinematics::of(test_support::physicalProfile(), arm));
    const auto estimates = estimator.estimate(times(rows.size(), 0.001), rows);
    Eigen::Vector2d mean_truth = Eigen::Vector2d::Zero(), mean_estimate = Eigen::Vector2d::Zero();
    for (std::size_t k = 0; k < rows.size(); ++k) {
      mean_truth += truth[k] / static_cast<double>(rows.size());
      mean_estimate += Eigen::Vector2d(estimates[k].jaw[0], estimates[k].jaw[1]) /
                       static_cast<double>(rows.size());
    }
    std::printf("%s jaws on a ball: contact %.3f / %.3f N, estimate %.3f / %.3f N\n",
                raven::armName(arm).data(), mean_truth(0), mean_truth(1), mean_estimate(0),
                mean_estimate(1));
    for (int j = 0; j < 2; ++j) {
      EXPECT_GT(mean_truth(j), 0.3) << raven::armName(arm) << " jaw " << j + 1;
      EXPECT_NEAR(mean_estimate(j), mean_truth(j), 0.15 * mean_truth(j))
          << raven::armName(arm) << " jaw " << j + 1;
    }
  }
}

}  // namespace
