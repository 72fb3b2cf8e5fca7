#include "scenario/grasp_assist.hpp"

#include <BulletCollision/CollisionShapes/btConvexShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBody.h>
#include <spdlog/spdlog.h>

#include <algorithm>

namespace scenario {

namespace {

/// The jaws let go once they open this much (rad) past the tightest they closed while holding.
constexpr double kReleaseOpening = 0.05;

}  // namespace

GraspAssist::GraspAssist(ambf_like::World& world, const std::vector<std::string>& pegs,
                         GraspAssistSettings settings)
    : settings_(settings) {
  for (const auto& name : pegs) pegs_.push_back(&world.softBody(name));
  for (raven::Arm arm : raven::kArms) {
    const std::string prefix = "/raven2/" + std::string(raven::armName(arm)) + "/";
    jaws_[slot(arm)] = {&world.body(prefix + "jaw1_link"), &world.body(prefix + "jaw2_link")};
  }
}

std::vector<int> GraspAssist::touching(const ambf_like::SoftBody& peg,
                                       const ambf_like::RigidBody& jaw) const {
  const btRigidBody& body = jaw.bullet();
  const auto* shape = dynamic_cast<const btConvexShape*>(body.getCollisionShape());
  std::vector<int> nodes;
  if (shape == nullptr) return nodes;
  const btSoftBody& soft = peg.bullet();
  btVector3 low, high;
  body.getAabb(low, high);
  const btVector3 pad(settings_.touch_distance, settings_.touch_distance, settings_.touch_distance);
  for (int i = 0; i < soft.m_nodes.size(); ++i) {
    const btVector3& x = soft.m_nodes[i].m_x;
    if (x.x() < low.x() - pad.x() || x.y() < low.y() - pad.y() || x.z() < low.z() - pad.z() ||
        x.x() > high.x() + pad.x() || x.y() > high.y() + pad.y() || x.z() > high.z() + pad.z()) {
      continue;
    }
    btGjkEpaSolver2::sResults result;
    const btScalar distance =
        btGjkEpaSolver2::SignedDistance(x, 0.0, shape, body.getWorldTransform(), result);
    if (distance < settings_.touch_distance) nodes.push_back(i);
  }
  return nodes;
}

void GraspAssist::update(raven::Arm arm, double commanded_opening) {
  const auto a = slot(arm);
  const bool closing = commanded_opening < last_opening_[a];
  last_opening_[a] = commanded_opening;
  auto& hold = holds_[a];
  if (hold) {
    hold->opening = std::min(hold->opening, commanded_opening);
    if (commanded_opening > hold->opening + kReleaseOpening) release(arm);
    return;
  }
  if (!closing) return;
  for (ambf_like::SoftBody* peg : pegs_) {
    const auto one = touching(*peg, *jaws_[a][0]);
    const auto two = touching(*peg, *jaws_[a][1]);
    if (one.empty() || two.empty()) continue;
    btSoftBody& soft = peg->bullet();
    Hold h{peg, {}, commanded_opening};
    for (int jaw = 0; jaw < 2; ++jaw) {
      for (int node : jaw == 0 ? one : two) {
        soft.appendAnchor(node, &jaws_[a][static_cast<std::size_t>(jaw)]->bullet(), false, 1.0);
        h.nodes.push_back(node);
      }
    }
    spdlog::debug("grasp assist: {} grasper holds {} by {} nodes", raven::armName(arm), peg->name(),
                  h.nodes.size());
    hold = std::move(h);
    ++grasps_;
    return;
  }
}

void GraspAssist::release(raven::Arm arm) {
  auto& hold = holds_[slot(arm)];
  // btSoftBody::removeAnchor only knows the deformable world's anchors: drop ours by hand.
  btSoftBody& soft = hold->peg->bullet();
  for (int i = soft.m_anchors.size() - 1; i >= 0; --i) {
    const auto& anchor = soft.m_anchors[i];
    if (anchor.m_body == &jaws_[slot(arm)][0]->bullet() ||
        anchor.m_body == &jaws_[slot(arm)][1]->bullet()) {
      anchor.m_node->m_battach = 0;
      soft.m_anchors.removeAtIndex(i);
    }
  }
  spdlog::debug("grasp assist: {} grasper lets {} go", raven::armName(arm), hold->peg->name());
  hold.reset();
}

const ambf_like::SoftBody* GraspAssist::held(raven::Arm arm) const {
  const auto& hold = holds_[slot(arm)];
  return hold ? hold->peg : nullptr;
}

}  // namespace scenario
