#include "bridge/throttled_log.hpp"

#include <spdlog/spdlog.h>

namespace bridge {

void ThrottledLog::warn(const std::string& key, const std::string& message, double now) {
  auto [it, first] = seen_.try_emplace(key, Seen{now, 0});
  if (first) {
    spdlog::warn("{}", message);
    return;
  }
  Seen& seen = it->second;
  if (now - seen.last_logged < interval_) {
    ++seen.suppressed;
    return;
  }
  spdlog::warn("{} ({} more refusals of {} since the last report)", message, seen.suppressed, key);
  seen = {now, 0};
}

}  // namespace bridge
