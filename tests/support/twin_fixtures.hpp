#pragma once
// Test helpers for platforms: the physical profile, and getting a platform (or a new in-process
// twin) enabled and homed on its own clock.

#include <memory>

#include "twin/twin_platform.hpp"

namespace test_support {

/// raven_description's physical profile, loaded once.
const raven::PlatformProfile& physicalProfile();

/// Advances `platform` in 10 ms steps until `done()` holds, at most 10 s of its time.
template <typename Done>
void advanceUntil(bridge::RavenPlatform& platform, Done done) {
  for (int i = 0; i < 1000 && !done(); ++i) platform.advance(0.01);
}

/// Enables (when disabled) and homes `platform`; works on either clock, in process or over ROS.
/// Fails the test if it does not become ready.
void makeReady(bridge::RavenPlatform& platform);

/// A new in-process twin, enabled and homed.
std::unique_ptr<twin::TwinPlatform> readyTwin(const twin::TwinOptions& options = {});

}  // namespace test_support
