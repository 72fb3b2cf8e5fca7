#include "bridge/throttled_log.hpp"

#include <spdlog/spdlog.h>

#include "common/printable.hpp"

namespace bridge {

std::string ThrottledLog::kindOf(const std::string& own_message) {
  return own_message.substr(0, own_message.find_first_of("0123456789'"));
}

void ThrottledLog::warn(const std::string& kind, const std::string& message, double now) {
  constexpr std::size_t kLongestMessage = 300;
  auto [it, first] = seen_.try_emplace(kind, Seen{now, 0});
  if (first) {
    spdlog::warn("{}", common::printable(message, kLongestMessage));
    return;
  }
  Seen& seen = it->second;
  if (now - seen.last_logged < interval_) {
    ++seen.suppressed;
    return;
  }
  spdlog::warn("{} ({} more like it since the last report)",
               common::printable(message, kLongestMessage), seen.suppressed);
  seen = {now, 0};
}

}  // namespace bridge
