#pragma once
// THE GRASP ASSIST (only with --grasp-assist contact, kept to compare with friction grasps): the
// scene's jaw sensors and constraint actuators (raven_description's
// peg_transfer/grasp_assist.yaml, AMBF's SENSOR and ACTUATOR blocks) used as SRC uses them for
// its needle: once both jaws of a closing grasper sense the same ring, each jaw's actuator
// anchors the nodes of the faces its sensor sees to that jaw, until the jaws open again. The
// mechanism is the scene's; this class is only the trigger a script would be.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/world.hpp"
#include "raven/arm.hpp"

namespace scenario {

/// Triggers the jaws' actuators on bilateral sensing while closing; releases them on opening.
class GraspAssist {
 public:
  /// The assist's model file, to load after the arms (it names their jaws as parents).
  static std::filesystem::path modelFile();

  /// `rings`: the soft bodies the graspers may take, by name. Needs the sensors and actuators of
  /// modelFile() in `world` (std::out_of_range otherwise).
  GraspAssist(ambf_like::World& world, const std::vector<std::string>& rings);

  /// Called once per manual-loop iteration with the jaws' commanded opening (jaw1 + jaw2):
  /// closing jaws that both sense a ring take it; jaws opening again (0.05 rad past the tightest
  /// they closed to) let it go.
  void update(raven::Arm arm, double commanded_opening);
  /// The ring `arm` holds, if any.
  const ambf_like::SoftBody* held(raven::Arm arm) const;
  /// How many grasps the assist made so far.
  std::size_t grasps() const { return grasps_; }

  /// The nodes of `ring` that jaw `jaw` (0, 1) of `arm` senses: the three nodes of every face
  /// its rays meet (AMBF's constraint actuator takes a soft body by its sensed faces).
  std::vector<int> sensedNodes(raven::Arm arm, std::size_t jaw,
                               const ambf_like::SoftBody& ring) const;

 private:
  /// One arm's grasp.
  struct Hold {
    ambf_like::SoftBody* ring = nullptr;
    double opening = 0.0;  ///< the tightest commanded opening since the grasp
  };
  void release(raven::Arm arm);

  std::vector<ambf_like::SoftBody*> rings_;
  raven::PerArm<std::array<ambf_like::ProximitySensor*, 2>> sensors_{};
  raven::PerArm<std::array<ambf_like::ConstraintActuator*, 2>> actuators_{};
  raven::PerArm<std::optional<Hold>> holds_;
  raven::PerArm<double> last_opening_{};
  std::size_t grasps_ = 0;
};

}  // namespace scenario
