#pragma once
// What a person sees of peg-transfer runs: the viewer window, before/after snapshots from named
// views, and a video of each run. An observer for PegTransferOptions::observe.

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "raven/platform_profile.hpp"
#include "scenario/run_progress.hpp"
#include "viewer/video_recorder.hpp"
#include "viewer/viewer.hpp"

namespace scenario {

/// Which pictures to make.
struct WatchOptions {
  bool window = false;          ///< a viewer window (one run only)
  std::string snapshot_prefix;  ///< PREFIX_before.png / PREFIX_after.png; empty: none
  /// Views of the snapshots: one gives PREFIX_before.png, several PREFIX_<view>_before.png.
  std::vector<std::string> snapshot_views{"overview"};
  /// One video per run; with `video_per_seed` (a batch) FILE's stem gets _seed<N>.
  std::filesystem::path video;
  bool video_per_seed = false;
  viewer::VideoOptions video_options;  ///< its file is set per run
  std::string video_view = "overview";
  /// AMBF's Raven-II meshes on our links (drawn when AMBF's mesh files are found).
  std::filesystem::path visual_skin = raven::ravenVisualSkin();
};

/// Watches one run or the runs of a batch (thread-safe: each run has its own world).
class RunWatcher {
 public:
  explicit RunWatcher(WatchOptions options) : options_(std::move(options)) {}

  /// The observer: opens what is asked at Start, feeds it every iteration, closes it at End.
  void operator()(const ambf_like::World& world, WorldMoment moment, std::uint64_t seed);
  /// The videos finished so far.
  std::vector<viewer::VideoSummary> videos() const;
  /// The file a run's video goes to.
  std::filesystem::path videoFileFor(std::uint64_t seed) const;

 private:
  void snap(const ambf_like::World& world, const char* when);

  WatchOptions options_;
  mutable std::mutex mutex_;
  std::unique_ptr<viewer::Viewer> view_;  ///< the window, or headless for snapshots
  std::map<const ambf_like::World*, std::unique_ptr<viewer::VideoRecorder>> recording_;
  std::vector<viewer::VideoSummary> videos_;
};

}  // namespace scenario
