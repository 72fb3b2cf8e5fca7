#pragma once
// Snapshots every N simulated seconds during a run: name_0000.png, name_0001.png, ...

#include <filesystem>

#include "viewer/viewer.hpp"

namespace viewer {

/// Takes a snapshot at the first call, then each time the world's clock has advanced `every`
/// seconds more.
class SnapshotSchedule {
 public:
  /// `file` names the series (its stem gets _NNNN); `every` > 0.
  SnapshotSchedule(std::filesystem::path file, double every)
      : file_(std::move(file)), every_(every) {}
  /// Call after each step; returns true when it took one.
  bool maybeTake(Viewer& viewer, const ambf_like::World& world);
  /// The file of snapshot number `n`.
  std::filesystem::path fileFor(int n) const;

 private:
  std::filesystem::path file_;
  double every_;
  int taken_ = 0;
  double next_ = 0.0;  ///< simulated time of the next snapshot (after the first)
};

}  // namespace viewer
