#include "raven/arm_kinematics.hpp"

#include <algorithm>
#include <cmath>

#include "common/wrap_angle.hpp"

namespace raven {

namespace {

using common::wrapToPi;
using Eigen::AngleAxisd;
using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Vector3d;

/// `angle` moved by whole turns to lie within pi of `near`.
double nearestTurn(double angle, double near) {
  return near + wrapToPi(angle - near);
}

Matrix3d rotX(double a) {
  return AngleAxisd(a, Vector3d::UnitX()).toRotationMatrix();
}
Matrix3d rotZ(double a) {
  return AngleAxisd(a, Vector3d::UnitZ()).toRotationMatrix();
}

/// Modified (Craig) DH link transform Rx(alpha) Tx(a) Rz(theta) Tz(d).
Isometry3d dhLink(double alpha, double a, double theta, double d) {
  Isometry3d t = Isometry3d::Identity();
  t.linear() = rotX(alpha) * rotZ(theta);
  t.translation() = Vector3d(a, 0.0, 0.0) + t.linear() * Vector3d(0.0, 0.0, d);
  return t;
}

}  // namespace

bool ClampReport::any() const {
  return std::any_of(clamped.begin(), clamped.end(), [](bool c) { return c; });
}

ArmKinematics::ArmKinematics(const ArmConvention& convention, const JointLimits& limits)
    : c_(convention), limits_(limits) {}

ArmKinematics ArmKinematics::of(const PlatformProfile& profile, Arm arm) {
  return ArmKinematics(profile.arm(arm), profile.limits);
}

DhValues ArmKinematics::toDh(const ArmJoints& q) const {
  const auto& o = c_.theta_offset;
  DhValues dh;
  dh << wrapToPi(q(kShoulder) + o[0]), wrapToPi(q(kElbow) + o[1]), q(kInsertion),
      wrapToPi(q(kRoll) + o[3]), wrapToPi(q(kWrist) + o[4]),
      wrapToPi(c_.grasp_scale * (q(kJaw1) - q(kJaw2)));
  return dh;
}

ArmJoints ArmKinematics::fromDh(const DhValues& dh, double grasp, const ArmJoints& near) const {
  const auto& o = c_.theta_offset;
  ArmJoints q;
  q(kShoulder) = nearestTurn(dh(0) - o[0], near(kShoulder));
  q(kElbow) = nearestTurn(dh(1) - o[1], near(kElbow));
  q(kInsertion) = dh(2);
  q(kRoll) = nearestTurn(dh(3) - o[3], near(kRoll));
  q(kWrist) = nearestTurn(dh(4) - o[4], near(kWrist));
  const double difference =
      nearestTurn(dh(5), c_.grasp_scale * (near(kJaw1) - near(kJaw2))) / c_.grasp_scale;
  q(kJaw1) = (grasp + difference) / 2.0;
  q(kJaw2) = (grasp - difference) / 2.0;
  return q;
}

std::array<Isometry3d, 6> ArmKinematics::frames(const ArmJoints& q) const {
  const DhValues dh = toDh(q);
  const auto& a = c_.alpha;
  std::array<Isometry3d, 6> f;
  f[0] = c_.base * dhLink(a[0], 0.0, dh(0), 0.0);
  f[1] = f[0] * dhLink(a[1], 0.0, dh(1), 0.0);
  f[2] = f[1] * dhLink(a[2], 0.0, c_.insertion_theta, dh(2));
  f[3] = f[2] * dhLink(a[3], 0.0, dh(3), c_.d4);
  f[4] = f[3] * dhLink(a[4], 0.0, dh(4), 0.0);
  f[5] = f[4] * dhLink(a[5], c_.tool_length, dh(5), 0.0);
  return f;
}

Isometry3d ArmKinematics::toolPose(const ArmJoints& q) const {
  return frames(q)[5];
}

Vector3d ArmKinematics::wristPoint(const ArmJoints& q) const {
  return frames(q)[4].translation();
}

Eigen::Matrix<double, 6, 1> ArmKinematics::toolTwist(const ArmJoints& q,
                                                     const ArmJoints& qdot) const {
  // A central difference along the motion: exact to O(h^2) for the smooth chain.
  constexpr double h = 1e-6;
  const Isometry3d ahead = toolPose(q + h * qdot);
  const Isometry3d behind = toolPose(q - h * qdot);
  const Eigen::AngleAxisd turn(ahead.linear() * behind.linear().transpose());
  Eigen::Matrix<double, 6, 1> twist;
  twist.head<3>() = (ahead.translation() - behind.translation()) / (2.0 * h);
  twist.tail<3>() = turn.axis() * turn.angle() / (2.0 * h);
  return twist;
}

// The insertion axis z3 = Rx(a0) Rz(t1) Rx(a1) Rz(t2) Rx(a2) z. With w = Rx(-a0) z3, its
// z component fixes the elbow: w_z = cos(a1) cos(a2) - sin(a1) sin(a2) cos(t2); the shoulder
// then turns the remaining (x', y') onto (w_x, w_y).
std::vector<std::array<double, 2>> ArmKinematics::aimShaft(const Vector3d& axis) const {
  const Vector3d w = rotX(-c_.alpha[0]) * axis;
  const double s1 = std::sin(c_.alpha[1]), c1 = std::cos(c_.alpha[1]);
  const double s2 = std::sin(c_.alpha[2]), c2 = std::cos(c_.alpha[2]);
  double cos_t2 = (c1 * c2 - w.z()) / (s1 * s2);
  if (std::abs(cos_t2) > 1.0 + 1e-12) return {};
  cos_t2 = std::clamp(cos_t2, -1.0, 1.0);
  const double t2 = std::acos(cos_t2);
  std::vector<std::array<double, 2>> out;
  for (double elbow : {t2, -t2}) {
    if (!out.empty() && std::abs(elbow - out.front()[1]) < 1e-15) break;
    const double xp = s2 * std::sin(elbow);
    const double yp = -c1 * s2 * std::cos(elbow) - s1 * c2;
    out.push_back({wrapToPi(std::atan2(w.y(), w.x()) - std::atan2(yp, xp)), elbow});
  }
  return out;
}

// With R6, p6 the tool frame in the arm frame and x4 = R6 Rz(-t6) x the wrist link direction,
// P5 = p6 - Lw x4 lies on the insertion axis z3, and the wrist axis z4 = R6 Rz(-t6) Rx(-a5) z
// meets z3 at the fixed angle a4: (P5 . z4)^2 = cos^2(a4) |P5|^2. In the tool frame, with
// p' = R6^T p6 = (A cos b, A sin b, p'_z) and psi = t6 + b, this is (a5 = +-90 deg)
//   A^2 C^2 - 2 k Lw A C + (k (|p'|^2 + Lw^2) - A^2) = 0,  C = cos(psi), k = cos^2(a4),
// giving t6; the insertion follows from |P5|, shoulder and elbow from the axis, and roll and
// wrist from R2^T R4 = Rz(t4) Rx(a4) Rz(t5).
std::vector<ArmJoints> ArmKinematics::inverseCandidates(const Isometry3d& tool, double grasp,
                                                        const ArmJoints& near) const {
  const Isometry3d local = c_.base.inverse() * tool;
  const Matrix3d r6 = local.linear();
  const Vector3d p6 = local.translation();
  const Vector3d pt = r6.transpose() * p6;
  const double lw = c_.tool_length;
  const double A = std::hypot(pt.x(), pt.y());
  if (A < 1e-12) return {};
  const double beta = std::atan2(pt.y(), pt.x());
  const double k = std::pow(std::cos(c_.alpha[4]), 2);
  const double qa = A * A, qb = -2.0 * k * lw * A, qc = k * (pt.squaredNorm() + lw * lw) - A * A;
  // A discriminant within round-off of zero is a double root (always, for a4 = pi).
  double disc = qb * qb - 4.0 * qa * qc;
  const double round_off = 1e-12 * (qb * qb + std::abs(4.0 * qa * qc));
  if (std::abs(disc) <= round_off) {
    disc = 0.0;
  } else if (disc < 0.0) {
    return {};
  }
  std::vector<double> t6s;
  for (double root : {(-qb + std::sqrt(disc)) / (2 * qa), (-qb - std::sqrt(disc)) / (2 * qa)}) {
    if (std::abs(root) > 1.0 + 1e-9) continue;
    const double psi = std::acos(std::clamp(root, -1.0, 1.0));
    for (double t6 : {wrapToPi(psi - beta), wrapToPi(-psi - beta)}) {
      const bool seen = std::any_of(t6s.begin(), t6s.end(),
                                    [&](double s) { return std::abs(wrapToPi(s - t6)) < 1e-12; });
      if (!seen) t6s.push_back(t6);
    }
  }

  const DhValues near_dh = toDh(near);
  const double sa4 = std::sin(c_.alpha[4]), ca4 = std::cos(c_.alpha[4]);
  std::vector<ArmJoints> out;
  for (double t6 : t6s) {
    const Matrix3d r4 = r6 * rotZ(-t6) * rotX(-c_.alpha[5]);
    const Vector3d p5 = p6 - lw * r4.col(0);
    const double reach = p5.norm();
    if (reach < 1e-12) continue;
    for (double r : {reach, -reach}) {
      const Vector3d z3 = p5 / r;
      if (std::abs(z3.dot(r4.col(2)) - ca4) > 1e-6) continue;  // wrist axis at the wrong angle
      for (const auto& [t1, t2] : aimShaft(z3)) {
        const Matrix3d r2 = rotX(c_.alpha[0]) * rotZ(t1) * rotX(c_.alpha[1]) * rotZ(t2) *
                            rotX(c_.alpha[2]) * rotZ(c_.insertion_theta);
        const Matrix3d m = r2.transpose() * r4;  // = Rz(t4) Rx(a4) Rz(t5)
        double t4, t5;
        if (std::abs(sa4) > 1e-9) {
          t4 = std::atan2(m(0, 2) / sa4, -m(1, 2) / sa4);
          t5 = std::atan2(m(2, 0) / sa4, m(2, 1) / sa4);
        } else {
          // Roll and wrist axes coincide (a4 = 0 or pi): only their sum (difference) is fixed;
          // keep the wrist where it is and solve the roll.
          const Matrix3d n = rotX(c_.alpha[4]).transpose() * m;  // = Rz(t5 + t4 * ca4)
          const double combined = std::atan2(n(1, 0), n(0, 0));
          t5 = near_dh(4);
          t4 = ca4 * (combined - t5);
        }
        DhValues dh;
        dh << t1, t2, r - c_.d4, wrapToPi(t4), wrapToPi(t5), t6;
        out.push_back(fromDh(dh, grasp, near));
      }
    }
  }
  // Keep only exact solutions (guards the branches above against round-off surprises).
  std::erase_if(out, [&](const ArmJoints& q) {
    const Isometry3d pose = toolPose(q);
    return (pose.translation() - tool.translation()).norm() > 1e-9 ||
           (pose.linear() - tool.linear()).cwiseAbs().maxCoeff() > 1e-9;
  });
  return out;
}

double ArmKinematics::distance(const ArmJoints& a, const ArmJoints& b) {
  ArmJoints d = (a - b).cwiseAbs();
  d(kInsertion) *= 100.0;
  return d.sum();
}

ClampReport ArmKinematics::clamp(ArmJoints& q) const {
  ClampReport report;
  for (int i = 0; i < kJointCount; ++i) {
    const double limited = std::clamp(q(i), limits_.low(i), limits_.high(i));
    report.clamped[static_cast<std::size_t>(i)] = limited != q(i);
    q(i) = limited;
  }
  return report;
}

std::optional<ArmJoints> ArmKinematics::inverseWithinLimits(const Isometry3d& tool, double grasp,
                                                            const ArmJoints& near) const {
  std::optional<ArmJoints> best;
  for (const ArmJoints& q : inverseCandidates(tool, grasp, near)) {
    const bool within =
        (q.array() >= limits_.low.array()).all() && (q.array() <= limits_.high.array()).all();
    if (within && (!best || distance(q, near) < distance(*best, near))) best = q;
  }
  return best;
}

IkSolution ArmKinematics::inverse(const Isometry3d& tool, double grasp,
                                  const ArmJoints& current) const {
  IkSolution solution;
  solution.joints = current;
  const auto candidates = inverseCandidates(tool, grasp, current);
  if (candidates.empty()) return solution;
  const auto best = std::min_element(candidates.begin(), candidates.end(),
                                     [&](const ArmJoints& x, const ArmJoints& y) {
                                       return distance(x, current) < distance(y, current);
                                     });
  solution.distance = distance(*best, current);
  if (solution.distance > M_PI) return solution;
  solution.ok = true;
  solution.joints = *best;
  solution.clamp = clamp(solution.joints);
  return solution;
}

IkSolution ArmKinematics::inverseWristLocked(const Vector3d& wrist_point, const ArmJoints& current,
                                             const ArmJoints& preferred) const {
  IkSolution solution;
  solution.joints = current;
  const Vector3d p5 = c_.base.inverse() * wrist_point;
  const double reach = p5.norm();
  if (reach < 1e-12) return solution;  // at the remote centre the direction is undefined
  double best = INFINITY;
  for (double r : {reach, -reach}) {
    for (const auto& [t1, t2] : aimShaft(p5 / r)) {
      ArmJoints candidate = current;  // roll, wrist and jaws stay exactly as they are
      candidate(kShoulder) = nearestTurn(t1 - c_.theta_offset[0], preferred(kShoulder));
      candidate(kElbow) = nearestTurn(t2 - c_.theta_offset[1], preferred(kElbow));
      candidate(kInsertion) = r - c_.d4;
      const double d = distance(candidate, preferred);
      if (d < best) {
        best = d;
        solution.joints = candidate;
      }
    }
  }
  if (best == INFINITY) return solution;
  solution.ok = true;
  solution.distance = best;
  solution.clamp = clamp(solution.joints);
  return solution;
}

}  // namespace raven
