#include "scenario/grasp_assist.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "raven/platform_profile.hpp"

namespace scenario {

namespace {

/// The jaws let go once they open this much (rad) past the tightest they closed while holding.
constexpr double kReleaseOpening = 0.05;

}  // namespace

std::filesystem::path GraspAssist::modelFile() {
  return raven::modelDirectory() / "peg_transfer" / "grasp_assist.yaml";
}

GraspAssist::GraspAssist(ambf_like::World& world, const std::vector<std::string>& rings) {
  for (const auto& name : rings) rings_.push_back(&world.softBody(name));
  for (raven::Arm arm : raven::kArms) {
    for (std::size_t jaw = 0; jaw < 2; ++jaw) {
      const std::string base = std::string(raven::armName(arm)) + "_jaw" + std::to_string(jaw + 1);
      sensors_[slot(arm)][jaw] = &world.sensor(base + "_sensor");
      sensors_[slot(arm)][jaw]->setActive(false);  // cast only while the jaws close
      actuators_[slot(arm)][jaw] = &world.actuator(base + "_gripper");
    }
  }
}

std::vector<int> GraspAssist::sensedNodes(raven::Arm arm, std::size_t jaw,
                                          const ambf_like::SoftBody& ring) const {
  std::vector<int> nodes;
  for (const auto& ray : sensors_[slot(arm)][jaw]->readings()) {
    if (!ray.triggered || ray.soft_face < 0 || ray.body != ring.qualifiedName()) continue;
    for (int node : ray.face_nodes) {
      if (std::find(nodes.begin(), nodes.end(), node) == nodes.end()) nodes.push_back(node);
    }
  }
  return nodes;
}

void GraspAssist::update(raven::Arm arm, double commanded_opening) {
  const auto a = slot(arm);
  const bool closing = commanded_opening < last_opening_[a];
  last_opening_[a] = commanded_opening;
  auto& hold = holds_[a];
  // The sensors look only while the jaws close on nothing: that is when a grasp can start.
  for (auto* sensor : sensors_[a]) sensor->setActive(closing && !hold);
  if (hold) {
    hold->opening = std::min(hold->opening, commanded_opening);
    if (commanded_opening > hold->opening + kReleaseOpening) release(arm);
    return;
  }
  if (!closing) return;
  for (ambf_like::SoftBody* ring : rings_) {
    const std::array<std::vector<int>, 2> seen{sensedNodes(arm, 0, *ring),
                                               sensedNodes(arm, 1, *ring)};
    if (seen[0].empty() || seen[1].empty()) continue;
    for (std::size_t jaw = 0; jaw < 2; ++jaw) actuators_[a][jaw]->actuate(*ring, seen[jaw]);
    spdlog::debug("grasp assist: {} grasper holds {} by {} + {} nodes", raven::armName(arm),
                  ring->name(), seen[0].size(), seen[1].size());
    hold = Hold{ring, commanded_opening};
    ++grasps_;
    return;
  }
}

void GraspAssist::release(raven::Arm arm) {
  for (auto* actuator : actuators_[slot(arm)]) actuator->release();
  spdlog::debug("grasp assist: {} grasper lets {} go", raven::armName(arm),
                holds_[slot(arm)]->ring->name());
  holds_[slot(arm)].reset();
}

const ambf_like::SoftBody* GraspAssist::held(raven::Arm arm) const {
  const auto& hold = holds_[slot(arm)];
  return hold ? hold->ring : nullptr;
}

}  // namespace scenario
