#pragma once
// A window onto a running World (GLFW, OpenGL) and PNG snapshots of it, or snapshots alone with no
// display at all (EGL). The viewer renders on its own thread from copies the physics thread hands
// over at the render rate, so drawing never holds up a physics step; a World without a viewer
// pays nothing.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "ambf_like/world.hpp"
#include "viewer/camera.hpp"
#include "viewer/view.hpp"

namespace viewer {

/// What a frame shows.
struct ViewOptions {
  bool collision = false;  ///< Bullet's collision shapes (wireframed) instead of the visuals
  bool contacts = false;   ///< contact points and normals
};

/// How the viewer runs.
struct ViewerOptions {
  bool window = true;  ///< false: no window, snapshots only (headless: EGL, no display needed)
  int width = 1280;
  int height = 800;
  double render_hz = 30.0;  ///< frames per second of the window
  ViewOptions view;
  std::optional<Camera> camera;       ///< unset: framed on the scene's bounds
  std::filesystem::path visual_skin;  ///< meshes drawn on some bodies (VisualSkin); empty: none
  std::string title = "ambf_like";
};

/// Thrown when no OpenGL context can be made: no display for a window, or no EGL for headless.
class NoDisplay : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SceneGeometry;
struct FrameState;

/// The window (or headless context) and its render thread; one window per process at a time
/// (GLFW's state is global), headless viewers as many as wanted. Not copyable. Keys in the window:
/// C collision view, K contacts, S snapshot to ./snapshot_<n>.png, Esc closes. Mouse: left drag
/// orbits, right or middle drag pans, wheel zooms.
class Viewer {
 public:
  /// Builds the drawing data from `world` and opens the window. Throws NoDisplay without a
  /// display, ambf_like::LoadError if a visual mesh cannot be read, std::logic_error while
  /// another viewer is open.
  Viewer(const ambf_like::World& world, ViewerOptions options);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  /// From the physics thread after a step: hands over a copy only when the window is due a
  /// frame (at most render_hz times a second); otherwise returns at once.
  void publish(const ambf_like::World& world);
  /// Renders `world` as it is now to a PNG (blocks until written). Throws std::runtime_error.
  void snapshot(const ambf_like::World& world, const std::filesystem::path& file);
  /// Renders with other view options (e.g. the collision view) without changing the window's.
  void snapshot(const ambf_like::World& world, const std::filesystem::path& file,
                const ViewOptions& view);
  /// Renders from a named camera (its body, if it follows one, as it is now).
  void snapshot(const ambf_like::World& world, const std::filesystem::path& file,
                const ViewOptions& view, const View& camera);

  /// The user closed the window.
  bool closed() const { return closed_; }
  /// Frames drawn in the window so far.
  std::uint64_t framesDrawn() const { return frames_; }
  const Camera& initialCamera() const { return initial_camera_; }
  const ViewerOptions& options() const { return options_; }

 private:
  struct Request;
  void run(std::promise<void>* started);
  void runWindow(std::promise<void>* started);    ///< GLFW: the window and its frames
  void runHeadless(std::promise<void>* started);  ///< EGL: snapshots only
  void renderLoop();
  void take(std::unique_ptr<Request> request);  ///< hands a snapshot over and waits for it
  void serve(Request& request, int width, int height, const Camera& current);

  ViewerOptions options_;
  std::unique_ptr<const SceneGeometry> geometry_;
  Camera initial_camera_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::unique_ptr<FrameState> latest_;  ///< the last frame handed over
  std::unique_ptr<Request> request_;    ///< a pending snapshot
  std::atomic<bool> wants_frame_{false};
  std::atomic<bool> stop_{false};
  std::atomic<bool> closed_{false};
  std::atomic<std::uint64_t> frames_{0};
  std::string start_error_;
  std::thread thread_;
  // The physics rate shown in the title: steps per wall second between hand-overs.
  std::uint64_t last_steps_ = 0;
  std::chrono::steady_clock::time_point last_publish_{};
  std::atomic<double> physics_hz_{0.0};
};

}  // namespace viewer
