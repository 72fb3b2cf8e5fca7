#include "viewer/snapshot_schedule.hpp"

#include <fmt/format.h>

namespace viewer {

bool SnapshotSchedule::maybeTake(Viewer& viewer, const ambf_like::World& world) {
  const double now = world.time();
  if (taken_ > 0 && now + 1e-9 < next_) return false;
  viewer.snapshot(world, fileFor(taken_));
  next_ = (taken_ == 0 || now >= next_ + every_) ? now + every_ : next_ + every_;
  ++taken_;
  return true;
}

std::filesystem::path SnapshotSchedule::fileFor(int n) const {
  auto name = fmt::format("{}_{:04d}{}", file_.stem().string(), n,
                          file_.has_extension() ? file_.extension().string() : ".png");
  return file_.parent_path() / name;
}

}  // namespace viewer
