#pragma once
// A soft body of the running simulation: its nodes.

#include <memory>
#include <string>
#include <vector>

#include "ambf_like/soft_body_spec.hpp"

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
  bool isFinite() const;
  /// True while the world skips this body because it rests (see SoftBodySleep).
  bool isAsleep() const;

  btSoftBody& bullet() { return *body_; }
  const btSoftBody& bullet() const { return *body_; }

 private:
  SoftBodySpec spec_;
  std::string qualified_name_;
  std::unique_ptr<btSoftBody> body_;
};

}  // namespace ambf_like
