#include "stamping_platform.hpp"

namespace bench {

bridge::CommandResult StampingPlatform::send(const bridge::PlatformCommand& command) {
  if (const auto* jr = std::get_if<bridge::ServoJr>(&command)) {
    const Stamp stamp{Clock::now(), jr->arm, !jr->increment.isZero()};
    std::lock_guard lock(mutex_);
    stamps_.push_back(stamp);
  }
  return inner_.send(command);
}

std::vector<StampingPlatform::Stamp> StampingPlatform::stamps() const {
  std::lock_guard lock(mutex_);
  return stamps_;
}

void StampingPlatform::clear() {
  std::lock_guard lock(mutex_);
  stamps_.clear();
}

}  // namespace bench
