#include "twin/grasp_forces.hpp"

#include <algorithm>

namespace twin {

GrasperForces graspForces(const ambf_like::World& world, const std::array<std::string, 2>& jaws,
                          const std::vector<std::string>& arm, const Eigen::Vector3d& about) {
  GrasperForces out;
  out.time = world.time();
  const double h = world.stepSize();
  auto add = [&](JawForces& jaw, const Eigen::Vector3d& at, const Eigen::Vector3d& normal,
                 const Eigen::Vector3d& friction) {
    jaw.normal += normal;
    jaw.friction += friction;
    ++jaw.contacts;
    out.force += normal + friction;
    out.torque += (at - about).cross(normal + friction);
  };
  auto ownArm = [&](const std::string& body) {
    return std::find(arm.begin(), arm.end(), body) != arm.end();
  };
  for (std::size_t j = 0; j < 2; ++j) {
    for (const auto& c : world.contacts(jaws[j])) {
      if (c.soft) continue;
      // Bullet's impulses act on body a; the object gets the opposite when the jaw is a.
      const bool jaw_is_a = c.body_a == jaws[j];
      const std::string& object = jaw_is_a ? c.body_b : c.body_a;
      if (ownArm(object)) continue;
      const double sign = jaw_is_a ? -1.0 : 1.0;
      add(out.jaws[j], c.position_on_b, sign * c.normal_on_b * c.normal_impulse / h,
          sign * c.friction_impulse / h);
    }
    for (const auto& f : world.softContactForces(jaws[j])) {
      add(out.jaws[j], f.position, f.normal_force, f.friction_force);
    }
  }
  return out;
}

}  // namespace twin
