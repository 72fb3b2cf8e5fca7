#include "ambf_like/dynamics/polar_rotation.hpp"

namespace ambf_like::detail {

namespace {

/// At most this many turns per call to followRotation.
constexpr int kMostIterations = 4;
/// A rotation is followed once |t| / |tr U| is below this (t the torque of U = R^T F, see
/// followRotation), about two thirds of the angle left: that moves a force by about 1e-4 of the
/// stress (to first order in the turn times the strain).
constexpr double kConverged = 1e-4;

/// The matrix of the unit quaternion (w, x, y, z).
template <typename T>
Matrix9<T> rotationMatrix(const T& w, const T& x, const T& y, const T& z) {
  const T tx = 2.0 * x, ty = 2.0 * y, tz = 2.0 * z;
  const T twx = tx * w, twy = ty * w, twz = tz * w;
  const T txx = tx * x, txy = ty * x, txz = tz * x, tyy = ty * y, tyz = tz * y, tzz = tz * z;
  return {1.0 - (tyy + tzz), txy + twz,         txz - twy,  // column 0
          txy - twz,         1.0 - (txx + tzz), tyz + twx,  // column 1
          txz + twy,         tyz - twx,         1.0 - (txx + tyy)};
}

}  // namespace

template <typename T>
Matrix9<T> followRotation(const Matrix9<T>& f, FollowedRotation<T>& rotation) {
  // With U = R^T F, R is F's polar rotation when U is symmetric: when the torque
  // sum_i r_i x f_i = R t, t = (U21 - U12, U02 - U20, U10 - U01), vanishes. Turning R by a small
  // d in its own frame changes t by -(tr S I - S) d, S = sym(U), so each iteration turns R by
  // Newton's d = (tr S I - S)^-1 t (the quaternion (1, d / 2) normalised, multiplied from the
  // right), which converges quadratically while S is positive definite. Mueller et al.'s
  // (2016) turn t / tr U is the fallback for an element too crushed for that: it is safe at
  // any stretch but takes only part of the turn (a third of what is left stays, at S = I).
  const T zero{};
  Matrix9<T> u = transposedProduct(rotation.matrix, f);
  for (int i = 0; i < kMostIterations; ++i) {
    const T t0 = u[5] - u[7], t1 = u[6] - u[2], t2 = u[1] - u[3];
    const T trace = u[0] + u[4] + u[8];
    const T scale = (trace < 0.0 ? -trace : trace) + 1e-9;
    const auto turning = t0 * t0 + t1 * t1 + t2 * t2 > kConverged * kConverged * scale * scale;
    if (!any(turning)) break;
    // M = tr S I - S and its adjugate; M is positive definite when its leading minors are.
    const T m00 = trace - u[0], m11 = trace - u[4], m22 = trace - u[8];
    const T m01 = -0.5 * (u[1] + u[3]), m02 = -0.5 * (u[2] + u[6]), m12 = -0.5 * (u[5] + u[7]);
    const T c00 = m11 * m22 - m12 * m12, c01 = m02 * m12 - m01 * m22, c02 = m01 * m12 - m02 * m11;
    const T c11 = m00 * m22 - m02 * m02, c12 = m01 * m02 - m00 * m12, c22 = m00 * m11 - m01 * m01;
    const T det = m00 * c00 + m01 * c01 + m02 * c02;
    const auto newton = (m00 > 0.0) & (c22 > 0.0) & (det > 0.0);
    const T half = turning ? (newton ? 0.5 / det : 0.5 / scale) : zero;
    const T h0 = half * (newton ? c00 * t0 + c01 * t1 + c02 * t2 : t0);
    const T h1 = half * (newton ? c01 * t0 + c11 * t1 + c12 * t2 : t1);
    const T h2 = half * (newton ? c02 * t0 + c12 * t1 + c22 * t2 : t2);
    // q (1, h), normalised.
    const T& w = rotation.w;
    const T& x = rotation.x;
    const T& y = rotation.y;
    const T& z = rotation.z;
    T nw = w - x * h0 - y * h1 - z * h2;
    T nx = w * h0 + x + y * h2 - z * h1;
    T ny = w * h1 + y + z * h0 - x * h2;
    T nz = w * h2 + z + x * h1 - y * h0;
    const T norm = 1.0 / squareRoot(nw * nw + nx * nx + ny * ny + nz * nz);
    nw *= norm, nx *= norm, ny *= norm, nz *= norm;
    const Matrix9<T> turned = rotationMatrix(nw, nx, ny, nz);
    rotation.w = turning ? nw : w;
    rotation.x = turning ? nx : x;
    rotation.y = turning ? ny : y;
    rotation.z = turning ? nz : z;
    for (int e = 0; e < 9; ++e) rotation.matrix[e] = turning ? turned[e] : rotation.matrix[e];
    u = transposedProduct(rotation.matrix, f);
  }
  return u;
}

template Matrix9<double> followRotation(const Matrix9<double>&, FollowedRotation<double>&);
template Matrix9<Lanes> followRotation(const Matrix9<Lanes>&, FollowedRotation<Lanes>&);

Eigen::Matrix3d followRotation(const Eigen::Matrix3d& f, Rotation& rotation) {
  Matrix9<double> each_f;
  FollowedRotation<double> followed;
  Eigen::Map<Eigen::Matrix3d>(each_f.data()) = f;
  Eigen::Map<Eigen::Matrix3d>(followed.matrix.data()) = rotation.matrix;
  const Eigen::Quaterniond& q = rotation.quaternion;
  followed.w = q.w(), followed.x = q.x(), followed.y = q.y(), followed.z = q.z();
  const Matrix9<double> u = followRotation(each_f, followed);
  rotation.quaternion = Eigen::Quaterniond(followed.w, followed.x, followed.y, followed.z);
  rotation.matrix = Eigen::Map<const Eigen::Matrix3d>(followed.matrix.data());
  return Eigen::Map<const Eigen::Matrix3d>(u.data());
}

}  // namespace ambf_like::detail
