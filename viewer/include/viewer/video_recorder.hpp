#pragma once
// A video of a run: one frame every 1/fps simulated seconds, so the video's duration is the
// simulated time. The physics thread copies poses and soft-body nodes when a frame is due; the
// recorder's own thread draws them headless (EGL, no display) and encodes them (FFmpeg).

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <filesystem>
#include <future>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "ambf_like/world.hpp"
#include "common/video_flags.hpp"
#include "viewer/scene_geometry.hpp"
#include "viewer/view.hpp"
#include "viewer/viewer.hpp"

namespace viewer {

/// What a video shows and how.
struct VideoOptions {
  std::filesystem::path file;  ///< .mp4 (H.264), or any container FFmpeg knows by extension
  int fps = 30;                ///< frames per simulated second
  int width = 960, height = 540;
  ViewOptions look;
  std::filesystem::path visual_skin;  ///< meshes drawn on some bodies (VisualSkin); empty: none
  std::filesystem::path first_frame;  ///< the first frame as a PNG too (a clip's poster); empty: no
  /// Frames copied ahead of the encoder; when they are all waiting, a step waits (the video
  /// keeps every frame rather than drop one).
  std::size_t queue = 16;

  /// Sets width and height from "WxH" (even, 16..7680); throws std::invalid_argument.
  void setSize(const std::string& text);
  /// The file, rate and size the command line asked for; throws std::invalid_argument.
  static VideoOptions of(const common::VideoFlags& flags);
};

/// What a finished video holds.
struct VideoSummary {
  std::filesystem::path file;
  std::int64_t frames = 0;
  double duration_s = 0.0;  ///< frames / fps
  int fps = 0;
  std::string codec;
  double physics_wait_s = 0.0;  ///< wall time steps spent waiting for the encoder

  /// "run.mp4 (2169 frames, 72.30 s at 30 fps, libx264; steps waited 18.01 s for it)".
  std::string describe() const;
};

/// Records one World; not copyable. Many may run at once (one per run of a batch).
class VideoRecorder {
 public:
  /// Starts the render thread and opens the file; without a view, the camera frames the whole
  /// scene. Throws NoDisplay without EGL, std::runtime_error naming the file if it cannot be
  /// written.
  VideoRecorder(const ambf_like::World& world, VideoOptions options, std::optional<View> view);
  ~VideoRecorder();
  VideoRecorder(const VideoRecorder&) = delete;
  VideoRecorder& operator=(const VideoRecorder&) = delete;

  /// After each step: copies the world when a frame is due (else returns at once). Rethrows what
  /// the render thread failed with.
  void capture(const ambf_like::World& world);
  /// Encodes what is queued and closes the file; rethrows a render or encoding failure.
  VideoSummary finish();

 private:
  void run(std::promise<void>* started);  ///< the render thread: draw, encode

  VideoOptions options_;
  View view_;
  std::unique_ptr<const SceneGeometry> geometry_;
  double start_time_ = 0.0;
  std::int64_t captured_ = 0;
  double physics_wait_s_ = 0.0;
  std::string codec_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<FrameState> queue_;
  bool done_ = false;      ///< no more frames will come
  bool finished_ = false;  ///< finish() has run
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace viewer
