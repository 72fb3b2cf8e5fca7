#pragma once
// A whole scene as plain data: the world settings and every loaded model (immutable after loading).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/body_spec.hpp"
#include "ambf_like/joint_spec.hpp"
#include "ambf_like/soft_body_spec.hpp"

namespace ambf_like {

/// One multibody file (ADF or URDF): its bodies, joints and soft bodies.
struct ModelSpec {
  std::filesystem::path file;
  std::string name_space;
  std::vector<BodySpec> bodies;
  std::vector<JointSpec> joints;
  std::vector<SoftBodySpec> soft_bodies;
  bool ignore_inter_collision =
      false;                    ///< no collisions between any two rigid bodies of this model
  std::optional<Vec3> gravity;  ///< model-wide override of the world gravity
};

/// World-file settings that matter to the physics.
struct WorldSpec {
  std::filesystem::path file;  ///< empty when defaults are used
  std::string name_space = "/ambf/env/";
  Vec3 gravity{0.0, 0.0, -9.81};
  int max_iterations = 10;  ///< Bullet max sub-steps per outer iteration
  /// This simulator's own settings (an `ambf_like:` block AMBF ignores); WorldOptions given in
  /// code take precedence.
  std::optional<int> solver_iterations;
  std::optional<double> sdf_voxel_size;
};

/// Everything needed to build a simulation.
struct SceneSpec {
  WorldSpec world;
  std::vector<ModelSpec> models;
};

}  // namespace ambf_like
