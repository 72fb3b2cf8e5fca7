#include "twin/twin_arms.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace twin {

ArmBindings ArmBindings::ourRaven() {
  ArmBindings b;
  for (Arm arm : kArms) {
    for (int i = 0; i < kJointCount; ++i) {
      b.joints[raven::slot(arm)][static_cast<std::size_t>(i)].name =
          "/raven2/" + std::string(armName(arm)) + "/" +
          std::string(kJointNames[static_cast<std::size_t>(i)]);
    }
  }
  b.jaws_meet = 0.0;
  return b;
}

ArmBindings ArmBindings::ambfRaven() {
  ArmBindings b;
  for (Arm arm : kArms) {
    const std::string s = arm == Arm::Left ? "L" : "R";
    const std::array<std::string, kJointCount> names{"base_link_" + s + "-link1_" + s,
                                                     "link1_" + s + "-link2_" + s,
                                                     "link2_" + s + "-link3_" + s,
                                                     "link3_" + s + "-instrument_shaft_" + s,
                                                     "instrument_shaft_" + s + "-wrist_" + s,
                                                     "wrist_" + s + "-grasper1_" + s,
                                                     "wrist_" + s + "-grasper2_" + s};
    for (int i = 0; i < kJointCount; ++i) {
      auto& joint = b.joints[raven::slot(arm)][static_cast<std::size_t>(i)];
      joint.name = names[static_cast<std::size_t>(i)];
      if (arm == Arm::Right && (i == raven::kJaw1 || i == raven::kJaw2)) joint.scale = -1.0;
    }
  }
  return b;
}

namespace {

/// The qualified name of a body a joint (found by `joint_name`) names by its plain name: the
/// joint's namespace, when `joint_name` is qualified, else the body's own unique name.
std::string bodyOf(const ambf_like::World& world, const std::string& joint_name,
                   const ambf_like::Joint& joint, const std::string& body) {
  const std::string& plain = joint.name();
  const bool qualified =
      joint_name.size() > plain.size() &&
      joint_name.compare(joint_name.size() - plain.size(), plain.size(), plain) == 0;
  const std::string prefix =
      qualified ? joint_name.substr(0, joint_name.size() - plain.size()) : "";
  return world.body(prefix + body).qualifiedName();
}

}  // namespace

TwinArms::TwinArms(ambf_like::World& world, const ArmBindings& bindings)
    : jaws_meet_(bindings.jaws_meet) {
  for (std::size_t a = 0; a < 2; ++a) {
    for (std::size_t i = 0; i < kJointCount; ++i) {
      const auto& b = bindings.joints[a][i];
      ambf_like::Joint& joint = world.joint(b.name);
      bound_[a][i] = {&joint, b.scale, b.offset, b.name};
      const std::string child = bodyOf(world, b.name, joint, joint.spec().child);
      for (const auto& name : {bodyOf(world, b.name, joint, joint.spec().parent), child}) {
        if (std::find(bodies_[a].begin(), bodies_[a].end(), name) == bodies_[a].end()) {
          bodies_[a].push_back(name);
        }
      }
      if (i == raven::kJaw1 || i == raven::kJaw2) jaws_[a][i - raven::kJaw1] = child;
    }
  }
  if (!bindings.jaws_meet) return;
  for (Arm arm : kArms) {
    if (!articulated(arm)) continue;
    const auto& jaw1 = bound_[raven::slot(arm)][raven::kJaw1];
    const auto& jaw2 = bound_[raven::slot(arm)][raven::kJaw2];
    jaw_stops_[raven::slot(arm)] = &world.addCoupledStop(
        {{jaw1.name, jaw2.name}, {1.0 / jaw1.scale, 1.0 / jaw2.scale}, jawStopLower(arm)});
  }
}

double TwinArms::jawStopLower(Arm arm) const {
  // jaw1 + jaw2 >= meet, each joint = (model value - offset) / scale.
  const auto& jaw1 = bound_[raven::slot(arm)][raven::kJaw1];
  const auto& jaw2 = bound_[raven::slot(arm)][raven::kJaw2];
  return *jaws_meet_ + jaw1.offset / jaw1.scale + jaw2.offset / jaw2.scale;
}

void TwinArms::placeJawsMeet(Arm arm, double offset, double compliance) {
  auto* stop = jaw_stops_[raven::slot(arm)];
  if (stop == nullptr) return;
  stop->setLower(jawStopLower(arm) + offset);
  stop->setCompliance(compliance);
}

void TwinArms::command(Arm arm, const ArmJoints& joints) {
  if (!joints.allFinite()) {
    throw std::invalid_argument(std::string(armName(arm)) +
                                " arm: joint command holds NaN or inf; nothing moved");
  }
  for (std::size_t i = 0; i < kJointCount; ++i) {
    const auto& b = bound_[raven::slot(arm)][i];
    b.joint->commandPosition(b.scale * joints(static_cast<int>(i)) + b.offset);
  }
}

template <typename Read>
ArmJoints TwinArms::read(Arm arm, Read read) const {
  ArmJoints out;
  for (std::size_t i = 0; i < kJointCount; ++i) {
    out(static_cast<int>(i)) = read(bound_[raven::slot(arm)][i]);
  }
  return out;
}

ArmJoints TwinArms::measured(Arm arm) const {
  return read(arm, [](const Bound& b) { return (b.joint->position() - b.offset) / b.scale; });
}

void TwinArms::place(Arm arm, const ArmJoints& joints, const ArmJoints& velocities) {
  for (std::size_t i = 0; i < kJointCount; ++i) {
    const auto& b = bound_[raven::slot(arm)][i];
    const auto j = static_cast<int>(i);
    b.joint->place(b.scale * joints(j) + b.offset, b.scale * velocities(j));
  }
}

std::vector<std::string> TwinArms::jointNames(Arm arm) const {
  std::vector<std::string> names;
  for (const auto& b : bound_[raven::slot(arm)]) names.push_back(b.name);
  return names;
}

bool TwinArms::articulated(Arm arm) const {
  const auto& arm_joints = bound_[raven::slot(arm)];
  return std::all_of(arm_joints.begin(), arm_joints.end(),
                     [](const Bound& b) { return b.joint->inArticulation(); });
}

ArmJoints TwinArms::scales(Arm arm) const {
  return read(arm, [](const Bound& b) { return b.scale; });
}

raven::JointLimits TwinArms::hardStops(Arm arm) const {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  raven::JointLimits stops{ArmJoints::Constant(-kNone), ArmJoints::Constant(kNone)};
  for (std::size_t i = 0; i < kJointCount; ++i) {
    const auto& b = bound_[raven::slot(arm)][i];
    const auto& limits = b.joint->spec().limits;
    if (!limits) continue;
    const double a = (limits->low - b.offset) / b.scale;
    const double c = (limits->high - b.offset) / b.scale;
    stops.low(static_cast<int>(i)) = std::min(a, c);
    stops.high(static_cast<int>(i)) = std::max(a, c);
  }
  return stops;
}

ArmJoints TwinArms::velocities(Arm arm) const {
  return read(arm, [](const Bound& b) { return b.joint->velocity() / b.scale; });
}

ArmJoints TwinArms::efforts(Arm arm) const {
  return read(arm, [](const Bound& b) { return b.joint->effort() * b.scale; });
}

}  // namespace twin
