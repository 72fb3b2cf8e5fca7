#pragma once
// A soft body of the running simulation: its nodes, and the rigid frame and volume they give.

#include <memory>
#include <string>
#include <vector>

#include "ambf_like/soft_body_spec.hpp"
#include "ambf_like/transform.hpp"

class btSoftBody;

namespace ambf_like {

/// One soft body of a World (a btSoftBody built from a mesh).
class SoftBody {
 public:
  SoftBody(SoftBodySpec spec, std::string qualified_name, std::unique_ptr<btSoftBody> body);
  ~SoftBody();
  SoftBody(const SoftBody&) = delete;
  SoftBody& operator=(const SoftBody&) = delete;

  const std::string& name() const { return spec_.name; }
  const std::string& qualifiedName() const { return qualified_name_; }
  const SoftBodySpec& spec() const { return spec_; }

  std::size_t nodeCount() const;
  Vec3 nodePosition(std::size_t index) const;
  std::vector<Vec3> nodePositions() const;
  Vec3 centerOfMass() const;
  /// The body as a rigid frame: the mean of its nodes, turned by the rotation that best maps its
  /// rest shape onto the nodes now (shape matching: the polar decomposition of the nodes'
  /// moment matrix, Mueller et al. 2005), so at rest it is the spec's location moved to the
  /// nodes' mean. What a tracker, or AMBF's object topics, report of a body.
  Transform pose() const;
  /// The volume its surface faces enclose (m^3; the divergence theorem); 0 without faces.
  double volume() const;
  /// volume() when the body was made.
  double restVolume() const { return rest_volume_; }
  bool isFinite() const;
  /// True while the world skips this body because it rests (see SoftBodySleep).
  bool isAsleep() const;

  btSoftBody& bullet() { return *body_; }
  const btSoftBody& bullet() const { return *body_; }

 private:
  SoftBodySpec spec_;
  std::string qualified_name_;
  std::unique_ptr<btSoftBody> body_;
  std::vector<Vec3> rest_shape_;  ///< per node: from the nodes' mean, in the body's own frame
  double rest_volume_ = 0.0;
};

}  // namespace ambf_like
