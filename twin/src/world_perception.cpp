#include "twin/world_perception.hpp"

#include <stdexcept>

namespace twin {

const WorldPerception::Object& WorldPerception::find(const std::string& name) const {
  if (const auto it = found_.find(name); it != found_.end()) return it->second;
  for (std::size_t i = 0; i < world_.softBodyCount(); ++i) {
    const ambf_like::SoftBody& soft = world_.softBody(i);
    if (soft.name() == name || soft.qualifiedName() == name) return found_[name] = &soft;
  }
  try {
    return found_[name] = &world_.body(name);
  } catch (const std::out_of_range& e) {
    throw bridge::PerceptionError("the world has no soft body '" + name + "'; " + e.what());
  }
}

bridge::Sighting WorldPerception::sight(const std::string& name) const {
  bridge::Sighting s;
  s.time = now_;
  if (const auto* soft = std::get_if<const ambf_like::SoftBody*>(&find(name))) {
    s.pose = bridge::asReported((*soft)->pose());
    if ((*soft)->restVolume() > 0.0) s.volume_ratio = (*soft)->volume() / (*soft)->restVolume();
  } else {
    s.pose = bridge::asReported(std::get<const ambf_like::RigidBody*>(find(name))->pose());
  }
  return s;
}

}  // namespace twin
