// The Raven-II kinematics reproduce the reference's check values, invert exactly, and never
// leave the joint limits.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "common/wrap_angle.hpp"
#include "raven/arm_kinematics.hpp"
#include "twin_fixtures.hpp"

namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;
using raven::Arm;
using raven::ArmJoints;
using raven::ArmKinematics;

// The joint readings' and the kinematics' angle folding: std::remainder(angle, 2 pi), bit for bit
// (signed zeros, pi itself, angles just past it, whole turns, NaN), with its shortcut for
// angles already in [-pi, pi].
TEST(WrapToPi, GivesStdRemaindersBits) {
  const double pi_up = std::nextafter(M_PI, 4.0);
  std::vector<double> angles = {0.0,
                                -0.0,
                                1e-300,
                                M_PI,
                                -M_PI,
                                pi_up,
                                -pi_up,
                                3.0 * M_PI,
                                -5.0 * M_PI,
                                2.0 * M_PI,
                                1e6,
                                -1e12,
                                std::numeric_limits<double>::infinity()};
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> any(-20.0, 20.0);
  for (int i = 0; i < 10000; ++i) angles.push_back(any(random));
  for (double a : angles) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(common::wrapToPi(a)),
              std::bit_cast<std::uint64_t>(std::remainder(a, 2.0 * M_PI)))
        << a;
  }
  EXPECT_TRUE(std::isnan(common::wrapToPi(std::numeric_limits<double>::quiet_NaN())));
}

const raven::PlatformProfile& ambf() {
  static const auto profile = raven::builtinProfile("ambf");
  return profile;
}

ArmJoints joints(std::initializer_list<double> values) {
  ArmJoints q;
  std::copy(values.begin(), values.end(), q.data());
  return q;
}

/// Uniformly random joints within the limits.
ArmJoints randomJoints(const raven::JointLimits& limits, std::mt19937_64& random) {
  ArmJoints q;
  for (int i = 0; i < raven::kJointCount; ++i) {
    q(i) = std::uniform_real_distribution<double>(limits.low(i), limits.high(i))(random);
  }
  return q;
}

bool withinLimits(const ArmJoints& q, const raven::JointLimits& limits) {
  return (q.array() >= limits.low.array()).all() && (q.array() <= limits.high.array()).all();
}

TEST(Kinematics, FirmwareToolPointCheckValue) {
  // Reference section A: J = [pi/6, pi/2, 0.4, 0, 0, 0], in each arm's base frame.
  const auto& firmware = *test_support::physicalProfile().firmware_kinematics;
  const ArmJoints q = joints({M_PI / 6, M_PI / 2, 0.4, 0, 0, 0, 0});
  const ArmKinematics left(firmware[0], test_support::physicalProfile().limits),
      right(firmware[1], test_support::physicalProfile().limits);
  EXPECT_LT((left.toolPose(q).translation() - Vector3d(-0.07795, -0.02527, 0.01323)).norm(), 1e-5);
  EXPECT_LT((right.toolPose(q).translation() - Vector3d(-0.07795, 0.02527, 0.01323)).norm(), 1e-5);
}

TEST(Kinematics, WristPointAtThePhysicalHome) {
  const auto& home = test_support::physicalProfile().home;
  EXPECT_LT((ArmKinematics::of(test_support::physicalProfile(), Arm::Left).wristPoint(home) -
             Vector3d(0.31186, 0.08231, -0.07274))
                .norm(),
            1e-5);
  EXPECT_LT((ArmKinematics::of(test_support::physicalProfile(), Arm::Right).wristPoint(home) -
             Vector3d(-0.31186, 0.08231, -0.07274))
                .norm(),
            1e-5);
}

TEST(Kinematics, AmbfSetGivesTheSameWristPointWithItsInsertionOffset) {
  // Joint 1 at pi/6 and the insertion at -0.07: insertion + d4 is -0.07 on both platforms.
  ArmJoints q = ambf().home;
  q(raven::kShoulder) = M_PI / 6;
  EXPECT_LT(
      (ArmKinematics::of(ambf(), Arm::Left).wristPoint(q) - Vector3d(0.31186, 0.08231, -0.07274))
          .norm(),
      1e-5);
  EXPECT_LT(
      (ArmKinematics::of(ambf(), Arm::Right).wristPoint(q) - Vector3d(-0.31186, 0.08231, -0.07274))
          .norm(),
      1e-5);
}

TEST(Kinematics, WristPointWithAmbfJointOneAtSevenPiOver36) {
  EXPECT_NEAR(ambf().home(raven::kShoulder), 7 * M_PI / 36, 1e-15);
  EXPECT_LT((ArmKinematics::of(ambf(), Arm::Left).wristPoint(ambf().home) -
             Vector3d(0.31186, 0.08796, -0.07063))
                .norm(),
            1e-5);
}

TEST(Kinematics, DhRoundTrip) {
  std::mt19937_64 random(7);
  for (const auto* profile : {&test_support::physicalProfile(), &ambf()}) {
    for (Arm arm : raven::kArms) {
      const auto kin = ArmKinematics::of(*profile, arm);
      for (int n = 0; n < 1000; ++n) {
        const ArmJoints q = randomJoints(profile->limits, random);
        const ArmJoints back = kin.fromDh(kin.toDh(q), q(raven::kJaw1) + q(raven::kJaw2), q);
        ASSERT_LT((back - q).cwiseAbs().maxCoeff(), 1e-12);
      }
    }
  }
}

/// FK(IK(FK(q))) = FK(q) over random reachable poses.
void expectExactInverse(const ArmKinematics& kin, const raven::JointLimits& limits,
                        std::mt19937_64& random, int samples) {
  double worst_position = 0.0, worst_rotation = 0.0;
  int rejected = 0;
  for (int n = 0; n < samples; ++n) {
    const ArmJoints q = randomJoints(limits, random);
    const Isometry3d target = kin.toolPose(q);
    const auto solution = kin.inverse(target, q(raven::kJaw1) + q(raven::kJaw2), q);
    if (!solution.ok) {
      ++rejected;
      continue;
    }
    const Isometry3d reached = kin.toolPose(solution.joints);
    worst_position =
        std::max(worst_position, (reached.translation() - target.translation()).norm());
    worst_rotation =
        std::max(worst_rotation, (reached.linear() - target.linear()).cwiseAbs().maxCoeff());
  }
  EXPECT_EQ(rejected, 0);
  EXPECT_LT(worst_position, 1e-9);
  EXPECT_LT(worst_rotation, 1e-9);
}

TEST(Kinematics, InverseOfForwardIsExactOnBothArmsOfBothProfiles) {
  std::mt19937_64 random(42);
  for (const auto* profile : {&test_support::physicalProfile(), &ambf()}) {
    for (Arm arm : raven::kArms) {
      SCOPED_TRACE(profile->name + " " + std::string(raven::armName(arm)));
      expectExactInverse(ArmKinematics::of(*profile, arm), profile->limits, random, 10000);
    }
  }
}

TEST(Kinematics, InverseOfTheFirmwareChainIsExactToo) {
  std::mt19937_64 random(43);
  for (std::size_t a = 0; a < 2; ++a) {
    expectExactInverse(ArmKinematics((*test_support::physicalProfile().firmware_kinematics)[a],
                                     test_support::physicalProfile().limits),
                       test_support::physicalProfile().limits, random, 2000);
  }
}

TEST(Kinematics, UpToEightCandidatesIncludingTheTrueJoints) {
  // Two jaw-axis placements x two insertion signs x two elbows; each placement has its own
  // wrist point, and the reversed insertion needs the mechanism to point the shaft the other
  // way, which it cannot always do: 2 to 8 candidates, in elbow pairs.
  std::mt19937_64 random(3);
  const auto kin = ArmKinematics::of(test_support::physicalProfile(), Arm::Left);
  for (int n = 0; n < 100; ++n) {
    const ArmJoints q = randomJoints(test_support::physicalProfile().limits, random);
    const auto candidates =
        kin.inverseCandidates(kin.toolPose(q), q(raven::kJaw1) + q(raven::kJaw2), q);
    ASSERT_GE(candidates.size(), 2u);
    ASSERT_LE(candidates.size(), 8u);
    ASSERT_EQ(candidates.size() % 2, 0u);
    // The true joints are among them.
    EXPECT_TRUE(std::any_of(candidates.begin(), candidates.end(), [&](const ArmJoints& c) {
      return (c - q).cwiseAbs().maxCoeff() < 1e-9;
    }));
  }
}

TEST(Kinematics, WristLockedInverseKeepsRollWristAndJawsBitIdentical) {
  std::mt19937_64 random(11);
  for (const auto* profile : {&test_support::physicalProfile(), &ambf()}) {
    for (Arm arm : raven::kArms) {
      const auto kin = ArmKinematics::of(*profile, arm);
      for (int n = 0; n < 2000; ++n) {
        const ArmJoints target = randomJoints(profile->limits, random);
        const ArmJoints current = randomJoints(profile->limits, random);
        const auto solution =
            kin.inverseWristLocked(kin.wristPoint(target), current, profile->home);
        ASSERT_TRUE(solution.ok);
        EXPECT_EQ(std::memcmp(solution.joints.data() + raven::kRoll, current.data() + raven::kRoll,
                              4 * sizeof(double)),
                  0);
        if (!solution.clamp.any()) {
          EXPECT_LT((kin.wristPoint(solution.joints) - kin.wristPoint(target)).norm(), 1e-9);
        }
      }
    }
  }
}

TEST(Kinematics, WristLockedInversePrefersTheSolutionNearestHome) {
  const auto kin = ArmKinematics::of(test_support::physicalProfile(), Arm::Left);
  ArmJoints q = test_support::physicalProfile().home;
  q(raven::kShoulder) += 0.2;
  q(raven::kElbow) -= 0.1;
  q(raven::kInsertion) += 0.03;
  const auto solution =
      kin.inverseWristLocked(kin.wristPoint(q), test_support::physicalProfile().home,
                             test_support::physicalProfile().home);
  ASSERT_TRUE(solution.ok);
  EXPECT_LT((solution.joints.head<3>() - q.head<3>()).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(Kinematics, NoPathLeavesTheLimits) {
  std::mt19937_64 random(5);
  const auto& limits = test_support::physicalProfile().limits;
  const auto kin = ArmKinematics::of(test_support::physicalProfile(), Arm::Right);
  std::uniform_real_distribution<double> wide(-0.6, 0.6);
  int clamped = 0;
  for (int n = 0; n < 5000; ++n) {
    // Targets anywhere in a 1.2 m cube, most of them out of reach or out of the limits.
    const Vector3d p5(wide(random), wide(random), wide(random));
    const ArmJoints current = randomJoints(limits, random);
    const auto locked = kin.inverseWristLocked(p5, current, test_support::physicalProfile().home);
    if (locked.ok) {
      ASSERT_TRUE(withinLimits(locked.joints, limits));
      clamped += locked.clamp.any();
    }
    Isometry3d tool = Isometry3d::Identity();
    tool.translation() = p5;
    tool.linear() = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
    const auto full = kin.inverse(tool, 0.5, current);
    if (full.ok) {
      ASSERT_TRUE(withinLimits(full.joints, limits));
    } else {
      ASSERT_EQ(full.joints, current) << "a refused inverse must not move the arm";
    }
  }
  EXPECT_GT(clamped, 100) << "the sample should exercise clamping";
}

TEST(Kinematics, ClampReportsExactlyWhatItMoved) {
  const auto kin = ArmKinematics::of(test_support::physicalProfile(), Arm::Left);
  ArmJoints q = test_support::physicalProfile().home;
  q(raven::kInsertion) = 0.7;
  q(raven::kWrist) = -3.0;
  const auto report = kin.clamp(q);
  EXPECT_THAT(report.clamped, testing::ElementsAre(false, false, true, false, true, false, false));
  EXPECT_EQ(q(raven::kInsertion), 0.56);
  EXPECT_EQ(q(raven::kWrist), -2.0);
}

}  // namespace

namespace {

/// Joints well inside the limits (so every small motion stays a motion of the chain).
ArmJoints midJoints(const raven::JointLimits& limits) {
  return 0.5 * (limits.low + limits.high) + 0.1 * (limits.high - limits.low);
}

}  // namespace

TEST(Kinematics, ToolTwistOfAnInsertionIsASlideAlongTheShaft) {
  const auto& profile = test_support::physicalProfile();
  const ArmKinematics k = ArmKinematics::of(profile, Arm::Left);
  const ArmJoints q = midJoints(profile.limits);
  ArmJoints qdot = ArmJoints::Zero();
  qdot(raven::kInsertion) = 0.03;  // m/s
  const auto twist = k.toolTwist(q, qdot);
  EXPECT_NEAR(twist.tail<3>().norm(), 0.0, 1e-9);  // a prismatic joint turns nothing
  EXPECT_NEAR(twist.head<3>().norm(), 0.03, 1e-8);
  const Vector3d shaft = k.frames(q)[2].linear().col(2);  // the insertion slides along z of row 2
  EXPECT_NEAR(std::abs(twist.head<3>().normalized().dot(shaft)), 1.0, 1e-9);
}

TEST(Kinematics, ToolTwistOfAShoulderTurnIsARotationAboutItsAxis) {
  for (const auto* profile : {&test_support::physicalProfile(), &ambf()}) {
    const ArmKinematics k = ArmKinematics::of(*profile, Arm::Right);
    const ArmJoints q = midJoints(profile->limits);
    ArmJoints qdot = ArmJoints::Zero();
    qdot(raven::kShoulder) = -0.4;  // rad/s
    const auto twist = k.toolTwist(q, qdot);
    EXPECT_NEAR(twist.tail<3>().norm(), 0.4, 1e-8);
    // v = w x (p - c) for a point c on the axis: the tool point moves across the axis.
    EXPECT_NEAR(twist.head<3>().dot(twist.tail<3>()), 0.0, 1e-9);
    EXPECT_GT(twist.head<3>().norm(), 1e-3);
  }
}

TEST(Kinematics, ToolTwistIsLinearInTheJointVelocity) {
  const auto& profile = test_support::physicalProfile();
  const ArmKinematics k = ArmKinematics::of(profile, Arm::Left);
  std::mt19937_64 random(7);
  for (int trial = 0; trial < 100; ++trial) {
    const ArmJoints q = randomJoints(profile.limits, random);
    const ArmJoints a = ArmJoints::Random() * 0.5, b = ArmJoints::Random() * 0.5;
    const auto sum = k.toolTwist(q, a + b);
    EXPECT_TRUE(sum.isApprox(k.toolTwist(q, a) + k.toolTwist(q, b), 1e-6)) << "trial " << trial;
  }
}
