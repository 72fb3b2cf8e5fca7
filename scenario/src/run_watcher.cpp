#include "scenario/run_watcher.hpp"

#include <spdlog/spdlog.h>

#include "scenario/task_views.hpp"

namespace scenario {

std::filesystem::path RunWatcher::videoFileFor(std::uint64_t seed) const {
  if (!options_.video_per_seed) return options_.video;
  std::filesystem::path file = options_.video;
  file.replace_filename(file.stem().string() + "_seed" + std::to_string(seed) +
                        file.extension().string());
  return file;
}

void RunWatcher::operator()(const ambf_like::World& world, WorldMoment moment, std::uint64_t seed) {
  const bool pictures = options_.window || !options_.snapshot_prefix.empty();
  if (moment == WorldMoment::Start) {
    const auto views = pegTransferViews(world);
    if (pictures) {
      viewer::ViewerOptions view;
      view.window = options_.window;
      view.title = "raven_peg_transfer";
      view.camera = viewer::findView(views, "overview").camera;
      view.visual_skin = options_.visual_skin;
      const std::lock_guard lock(mutex_);
      view_.reset();  // one window at a time
      view_ = std::make_unique<viewer::Viewer>(world, view);
    }
    if (!options_.video.empty()) {
      viewer::VideoOptions video = options_.video_options;
      video.file = videoFileFor(seed);
      video.visual_skin = options_.visual_skin;
      auto recorder = std::make_unique<viewer::VideoRecorder>(
          world, video, viewer::findView(views, options_.video_view));
      const std::lock_guard lock(mutex_);
      recording_[&world] = std::move(recorder);
    }
  }
  if (!options_.snapshot_prefix.empty() && moment != WorldMoment::Iteration) {
    snap(world, moment == WorldMoment::Start ? "before" : "after");
  }
  if (view_ && pictures) view_->publish(world);
  if (options_.video.empty()) return;
  viewer::VideoRecorder* recorder = nullptr;
  {
    const std::lock_guard lock(mutex_);
    recorder = recording_.at(&world).get();
  }
  recorder->capture(world);
  if (moment != WorldMoment::End) return;
  const viewer::VideoSummary summary = recorder->finish();
  spdlog::info("video: {}", summary.describe());
  const std::lock_guard lock(mutex_);
  videos_.push_back(summary);
  recording_.erase(&world);
}

void RunWatcher::snap(const ambf_like::World& world, const char* when) {
  const auto views = pegTransferViews(world);
  for (const std::string& name : options_.snapshot_views) {
    const std::string file =
        options_.snapshot_views.size() == 1
            ? fmt::format("{}_{}.png", options_.snapshot_prefix, when)
            : fmt::format("{}_{}_{}.png", options_.snapshot_prefix, name, when);
    view_->snapshot(world, file, view_->options().view, viewer::findView(views, name));
    spdlog::info("snapshot: {} ({})", file, name);
  }
}

std::vector<viewer::VideoSummary> RunWatcher::videos() const {
  const std::lock_guard lock(mutex_);
  return videos_;
}

}  // namespace scenario
