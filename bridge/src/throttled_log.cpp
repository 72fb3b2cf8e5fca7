#include "bridge/throttled_log.hpp"

#include <spdlog/spdlog.h>

namespace bridge {

void ThrottledLog::warn(const std::string& message, double now) {
  const std::string key = message.substr(0, message.find_first_of("0123456789"));
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
  spdlog::warn("{} ({} more like it since the last report)", message, seen.suppressed);
  seen = {now, 0};
}

}  // namespace bridge
