#pragma once
// THE GRASP ASSIST (off unless asked for): once both jaws of a grasper touch the same soft peg,
// the nodes they touch are pinned to the jaw that touches them (Bullet soft-body anchors), until
// the jaws open again. It stands in for the friction that Bullet's node-based soft contacts
// cannot hold a peg with; it is triggered only by real contact on both sides, never by intent.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/world.hpp"
#include "raven/arm.hpp"

namespace scenario {

/// How close a node must be to a jaw's collision surface to count as touching it (m): the
/// peg's collision margin plus a little.
struct GraspAssistSettings {
  double touch_distance = 0.0007;
};

/// Pins a peg to a closing grasper's jaws on bilateral contact; frees it when the jaws open.
class GraspAssist {
 public:
  /// `pegs`: the soft bodies the graspers may take, by name. Jaws are found by the arms' body
  /// names (/raven2/<left|right>/jaw1_link, jaw2_link).
  GraspAssist(ambf_like::World& world, const std::vector<std::string>& pegs,
              GraspAssistSettings settings = {});

  /// Called once per manual-loop iteration with the jaws' commanded opening (jaw1 + jaw2):
  /// closing jaws that touch a peg on both sides take it; jaws opening again (0.05 rad past the
  /// tightest they closed to) let it go.
  void update(raven::Arm arm, double commanded_opening);
  /// The peg `arm` holds, if any.
  const ambf_like::SoftBody* held(raven::Arm arm) const;
  /// How many grasps the assist made so far.
  std::size_t grasps() const { return grasps_; }

  /// Nodes of `peg` within the touch distance of `jaw`.
  std::vector<int> touching(const ambf_like::SoftBody& peg, const ambf_like::RigidBody& jaw) const;

 private:
  /// One arm's grasp.
  struct Hold {
    ambf_like::SoftBody* peg = nullptr;
    std::vector<int> nodes;
    double opening = 0.0;  ///< the tightest commanded opening since the grasp
  };
  static std::size_t slot(raven::Arm arm) { return static_cast<std::size_t>(raven::index(arm)); }
  void release(raven::Arm arm);

  std::vector<ambf_like::SoftBody*> pegs_;
  GraspAssistSettings settings_;
  std::array<std::array<ambf_like::RigidBody*, 2>, 2> jaws_;
  std::array<std::optional<Hold>, 2> holds_;
  std::array<double, 2> last_opening_{};
  std::size_t grasps_ = 0;
};

}  // namespace scenario
