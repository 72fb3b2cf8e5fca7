#include "viewer/video_recorder.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>

#include "headless_context.hpp"
#include "renderer.hpp"
#include "video_encoder.hpp"

namespace viewer {

std::string VideoSummary::describe() const {
  return fmt::format("{} ({} frames, {:.2f} s at {} fps, {}; steps waited {:.2f} s for it)",
                     file.string(), frames, duration_s, fps, codec, physics_wait_s);
}

void VideoOptions::setSize(const std::string& text) {
  int w = 0, h = 0;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || x != 'x' || w < 16 ||
      h < 16 || w > 7680 || h > 7680 || w % 2 || h % 2) {
    throw std::invalid_argument("video size '" + text +
                                "': want WIDTHxHEIGHT, both even, 16 to 7680 (e.g. 960x540)");
  }
  width = w;
  height = h;
}

VideoOptions VideoOptions::of(const common::VideoFlags& flags) {
  VideoOptions options;
  options.file = flags.file;
  options.fps = flags.fps;
  options.setSize(flags.size);
  return options;
}

VideoRecorder::VideoRecorder(const ambf_like::World& world, VideoOptions options,
                             std::optional<View> view)
    : options_(std::move(options)), start_time_(world.time()) {
  if (options_.fps <= 0) throw std::invalid_argument("video frame rate must be positive");
  if (options_.queue == 0) throw std::invalid_argument("video queue must hold a frame");
  geometry_ = std::make_unique<const SceneGeometry>(SceneGeometry::of(world, options_.visual_skin));
  view_ = view.value_or(View{"overview", Camera::framing(geometry_->bounds), std::nullopt});
  std::promise<void> started;
  auto ready = started.get_future();
  thread_ = std::thread([this, &started] { run(&started); });
  try {
    ready.get();
  } catch (...) {
    thread_.join();
    throw;
  }
}

VideoRecorder::~VideoRecorder() {
  try {
    finish();
  } catch (...) {  // finish() reports it to a caller who asks
  }
}

void VideoRecorder::capture(const ambf_like::World& world) {
  const double due = start_time_ + static_cast<double>(captured_) / options_.fps;
  if (world.time() + 1e-9 < due) return;
  FrameState frame = FrameState::of(world, options_.look.contacts);
  std::unique_lock lock(mutex_);
  if (error_) std::rethrow_exception(error_);
  if (queue_.size() >= options_.queue) {
    const auto waited_from = std::chrono::steady_clock::now();
    changed_.wait(lock, [&] { return queue_.size() < options_.queue || error_; });
    physics_wait_s_ +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - waited_from).count();
    if (error_) std::rethrow_exception(error_);
  }
  // A step longer than a frame shows the same world in each frame it spans.
  while (world.time() + 1e-9 >= start_time_ + static_cast<double>(captured_) / options_.fps) {
    queue_.push_back(frame);
    ++captured_;
  }
  changed_.notify_all();
}

VideoSummary VideoRecorder::finish() {
  {
    std::lock_guard lock(mutex_);
    done_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
  if (error_ && !finished_) {
    finished_ = true;
    std::rethrow_exception(error_);
  }
  finished_ = true;
  return VideoSummary{options_.file, captured_, static_cast<double>(captured_) / options_.fps,
                      options_.fps,  codec_,    physics_wait_s_};
}

void VideoRecorder::run(std::promise<void>* started) {
  // Mesa's software rasteriser on this thread only, so drawing keeps off the physics core.
  setenv("LP_NUM_THREADS", "0", 0);
  std::unique_ptr<detail::HeadlessContext> context;
  std::unique_ptr<detail::VideoEncoder> encoder;
  try {
    context = std::make_unique<detail::HeadlessContext>(options_.width, options_.height);
    encoder = std::make_unique<detail::VideoEncoder>(options_.file, options_.width, options_.height,
                                                     options_.fps);
    codec_ = encoder->codecName();
  } catch (...) {
    started->set_exception(std::current_exception());
    return;
  }
  started->set_value();
  try {
    std::vector<std::uint8_t> pixels;
    for (;;) {
      FrameState frame;
      {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return !queue_.empty() || done_; });
        if (queue_.empty()) break;
        frame = std::move(queue_.front());
        queue_.pop_front();
      }
      changed_.notify_all();
      detail::draw(*geometry_, frame, view_.at(frame.body_poses), options_.width, options_.height,
                   options_.look);
      detail::readPixelsRgba(options_.width, options_.height, pixels);
      encoder->write(pixels);
      if (encoder->framesWritten() == 1 && !options_.first_frame.empty()) {
        detail::writePng(options_.first_frame, detail::readPixels(options_.width, options_.height),
                         options_.width, options_.height);
      }
    }
    encoder->close();
  } catch (...) {
    std::lock_guard lock(mutex_);
    error_ = std::current_exception();
    queue_.clear();
  }
  changed_.notify_all();
}

}  // namespace viewer
