#include "twin_fixtures.hpp"

#include <gtest/gtest.h>

namespace test_support {

const raven::PlatformProfile& physicalProfile() {
  static const auto profile = raven::builtinProfile("physical");
  return profile;
}

void makeReady(bridge::RavenPlatform& platform) {
  using bridge::OperatingState;
  if (platform.operatingStatus().state != OperatingState::Enabled) {
    ASSERT_TRUE(platform.send(bridge::StateCommand::Enable));
    advanceUntil(platform,
                 [&] { return platform.operatingStatus().state == OperatingState::Enabled; });
  }
  ASSERT_TRUE(platform.send(bridge::StateCommand::Home));
  advanceUntil(platform, [&] { return platform.operatingStatus().ready(); });
  ASSERT_TRUE(platform.operatingStatus().ready())
      << bridge::wireName(platform.operatingStatus().state);
}

std::unique_ptr<twin::TwinPlatform> readyTwin(const twin::TwinOptions& options) {
  auto twin = std::make_unique<twin::TwinPlatform>(options);
  makeReady(*twin);
  return twin;
}

}  // namespace test_support
