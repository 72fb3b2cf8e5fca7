#pragma once
// The twin's side of measured_cf: a grasper's forces summed from the simulation's contacts.

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "ambf_like/world.hpp"
#include "bridge/grasper_forces.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// Sums the last step's contacts of the two jaw bodies (qualified names) on every body that
/// is not one of `arm` (the jaws' own arm, qualified names). Rigid contacts carry Bullet's solver
/// impulses; soft bodies carry forces only with Coulomb contacts (`contact friction: coulomb`):
/// Bullet's own soft contacts record none and count for nothing here.
GrasperForces graspForces(const ambf_like::World& world, const std::array<std::string, 2>& jaws,
                          const std::vector<std::string>& arm, const Eigen::Vector3d& about);

}  // namespace twin
