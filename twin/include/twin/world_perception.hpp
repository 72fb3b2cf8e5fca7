#pragma once
// The in-process ScenePerception: objects' poses read straight from the twin's world (rigid
// bodies' frames, soft bodies' shape-matched frames and volumes), at the world's own time.

#include <map>
#include <string>
#include <variant>

#include "ambf_like/world.hpp"
#include "bridge/scene_perception.hpp"

namespace twin {

/// Sees every body of one world, as it is when asked.
class WorldPerception final : public bridge::ScenePerception {
 public:
  explicit WorldPerception(const ambf_like::World& world) : world_(world) {}

  void update(double now) override { now_ = now; }
  /// A soft or rigid body by its name (as World::softBody / World::body take it).
  bridge::Sighting sight(const std::string& name) const override;

 private:
  using Object = std::variant<const ambf_like::RigidBody*, const ambf_like::SoftBody*>;
  const Object& find(const std::string& name) const;

  const ambf_like::World& world_;
  double now_ = 0.0;
  mutable std::map<std::string, Object, std::less<>> found_;  ///< names looked up once
};

}  // namespace twin
