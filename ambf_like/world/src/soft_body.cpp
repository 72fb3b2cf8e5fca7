#include "ambf_like/soft_body.hpp"

#include <BulletSoftBody/btSoftBody.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "ambf_like/bullet_conversions.hpp"

namespace ambf_like {

SoftBody::SoftBody(SoftBodySpec spec, std::string qualified_name, std::unique_ptr<btSoftBody> body)
    : spec_(std::move(spec)), qualified_name_(std::move(qualified_name)), body_(std::move(body)) {
  // The nodes as made are the rest shape, placed at the spec's location.
  const std::vector<Vec3> nodes = nodePositions();
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : nodes) mean += p;
  mean /= static_cast<double>(std::max<std::size_t>(1, nodes.size()));
  rest_shape_.reserve(nodes.size());
  for (const Vec3& p : nodes)
    rest_shape_.push_back(spec_.location.linear().transpose() * (p - mean));
  rest_volume_ = volume();
}

SoftBody::~SoftBody() = default;

std::size_t SoftBody::nodeCount() const {
  return static_cast<std::size_t>(body_->m_nodes.size());
}

Vec3 SoftBody::nodePosition(std::size_t index) const {
  return toEigen(body_->m_nodes[static_cast<int>(index)].m_x);
}

std::vector<Vec3> SoftBody::nodePositions() const {
  std::vector<Vec3> out;
  out.reserve(nodeCount());
  for (int i = 0; i < body_->m_nodes.size(); ++i) out.push_back(toEigen(body_->m_nodes[i].m_x));
  return out;
}

Vec3 SoftBody::centerOfMass() const {
  return toEigen(body_->getCenterOfMass());
}

Transform SoftBody::pose() const {
  const std::vector<Vec3> nodes = nodePositions();
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : nodes) mean += p;
  mean /= static_cast<double>(std::max<std::size_t>(1, nodes.size()));
  Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < nodes.size(); ++i)
    moment += (nodes[i] - mean) * rest_shape_[i].transpose();
  // The rotation nearest the moment matrix: U V^T, its last axis flipped if that reflects.
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(moment, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d flip = Eigen::Matrix3d::Identity();
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0) flip(2, 2) = -1.0;
  Transform pose = Transform::Identity();
  pose.linear() = svd.matrixU() * flip * svd.matrixV().transpose();
  pose.translation() = mean;
  return pose;
}

double SoftBody::volume() const {
  double volume = 0.0;  // signed tetrahedra from the origin to each face
  for (int f = 0; f < body_->m_faces.size(); ++f) {
    const auto& face = body_->m_faces[f];
    volume += face.m_n[0]->m_x.dot(face.m_n[1]->m_x.cross(face.m_n[2]->m_x)) / 6.0;
  }
  return std::abs(volume);
}

bool SoftBody::isFinite() const {
  // A body asleep has not moved since it fell asleep, which a body that is not finite never does.
  if (isAsleep()) return true;
  for (int i = 0; i < body_->m_nodes.size(); ++i) {
    const auto& node = body_->m_nodes[i];
    if (!toEigen(node.m_x).allFinite() || !toEigen(node.m_v).allFinite()) return false;
  }
  return true;
}

bool SoftBody::isAsleep() const {
  return body_->getActivationState() == DISABLE_SIMULATION;
}

}  // namespace ambf_like
