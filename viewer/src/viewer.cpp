#include "viewer/viewer.hpp"

#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <cstdlib>

#include "headless_context.hpp"
#include "renderer.hpp"
#include "viewer/scene_geometry.hpp"

namespace viewer {

/// A snapshot asked for by another thread.
struct Viewer::Request {
  FrameState frame;
  std::filesystem::path file;
  ViewOptions view;
  std::optional<View> camera;  ///< unset: the window's (or the initial) camera
  std::promise<void> done;
};

namespace {

/// GLFW is one library-wide state (glfwTerminate closes every window): one window at a time.
std::atomic<bool> g_window_alive{false};

/// What the window's input callbacks change (render thread only).
struct WindowState {
  Camera camera;
  ViewOptions view;
  double x = 0.0, y = 0.0;
  int button = -1;
  bool snapshot = false;
};

WindowState& stateOf(GLFWwindow* w) {
  return *static_cast<WindowState*>(glfwGetWindowUserPointer(w));
}

void installCallbacks(GLFWwindow* window) {
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
    if (action != GLFW_PRESS) return;
    auto& s = stateOf(w);
    if (key == GLFW_KEY_C) s.view.collision = !s.view.collision;
    if (key == GLFW_KEY_K) s.view.contacts = !s.view.contacts;
    if (key == GLFW_KEY_S) s.snapshot = true;
    if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(w, GLFW_TRUE);
  });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
    stateOf(w).button = action == GLFW_PRESS ? button : -1;
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
    auto& s = stateOf(w);
    int height = 0;
    glfwGetFramebufferSize(w, nullptr, &height);
    if (s.button == GLFW_MOUSE_BUTTON_LEFT) s.camera.orbit(x - s.x, y - s.y);
    if (s.button == GLFW_MOUSE_BUTTON_RIGHT || s.button == GLFW_MOUSE_BUTTON_MIDDLE) {
      s.camera.pan(x - s.x, y - s.y, height);
    }
    s.x = x;
    s.y = y;
  });
  glfwSetScrollCallback(window,
                        [](GLFWwindow* w, double, double dy) { stateOf(w).camera.zoom(dy); });
}

}  // namespace

Viewer::Viewer(const ambf_like::World& world, ViewerOptions options)
    : options_(std::move(options)) {
  if (options_.window && g_window_alive.exchange(true)) {
    throw std::logic_error("another viewer window is open: GLFW allows one per process");
  }
  struct Release {  // gives the slot back if the constructor throws
    bool armed;
    ~Release() {
      if (armed) g_window_alive = false;
    }
  } release{options_.window};
  geometry_ = std::make_unique<const SceneGeometry>(SceneGeometry::of(world, options_.visual_skin));
  initial_camera_ = options_.camera.value_or(Camera::framing(geometry_->bounds));
  latest_ = std::make_unique<FrameState>(FrameState::of(world, true));
  last_steps_ = world.stepCount();
  last_publish_ = std::chrono::steady_clock::now();
  std::promise<void> started;
  auto ready = started.get_future();
  thread_ = std::thread([this, &started] { run(&started); });
  ready.wait();
  if (!start_error_.empty()) {
    thread_.join();
    throw NoDisplay(start_error_);
  }
  release.armed = false;
}

Viewer::~Viewer() {
  stop_ = true;
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  if (options_.window) g_window_alive = false;
}

void Viewer::publish(const ambf_like::World& world) {
  if (!wants_frame_.load(std::memory_order_relaxed)) return;
  // With contacts always: the window's K key may show them at any frame.
  auto frame = std::make_unique<FrameState>(FrameState::of(world, true));
  const auto now = std::chrono::steady_clock::now();
  const double wall = std::chrono::duration<double>(now - last_publish_).count();
  if (wall > 0.0) physics_hz_ = static_cast<double>(frame->steps - last_steps_) / wall;
  last_steps_ = frame->steps;
  last_publish_ = now;
  {
    std::lock_guard lock(mutex_);
    latest_ = std::move(frame);
    wants_frame_ = false;
  }
  wake_.notify_one();
}

void Viewer::snapshot(const ambf_like::World& world, const std::filesystem::path& file) {
  snapshot(world, file, options_.view);
}

void Viewer::snapshot(const ambf_like::World& world, const std::filesystem::path& file,
                      const ViewOptions& view) {
  take(std::make_unique<Request>(Request{FrameState::of(world, view.contacts), file, view,
                                         std::nullopt, std::promise<void>()}));
}

void Viewer::snapshot(const ambf_like::World& world, const std::filesystem::path& file,
                      const ViewOptions& view, const View& camera) {
  take(std::make_unique<Request>(
      Request{FrameState::of(world, view.contacts), file, view, camera, std::promise<void>()}));
}

void Viewer::take(std::unique_ptr<Request> request) {
  auto done = request->done.get_future();
  {
    std::lock_guard lock(mutex_);
    if (request_) throw std::runtime_error("a snapshot is already being taken");
    request_ = std::move(request);
  }
  wake_.notify_one();
  done.get();  // rethrows what the render thread failed with
}

void Viewer::serve(Request& request, int width, int height, const Camera& current) {
  try {
    const Camera camera = request.camera ? request.camera->at(request.frame.body_poses) : current;
    detail::draw(*geometry_, request.frame, camera, width, height, request.view);
    detail::writePng(request.file, detail::readPixels(width, height), width, height);
    request.done.set_value();
  } catch (...) {
    request.done.set_exception(std::current_exception());
  }
}

void Viewer::run(std::promise<void>* started) {
  // With Mesa's software renderer (llvmpipe: no GPU, or Xvfb), rasterise on this thread only
  // instead of one worker per core, so drawing cannot take the physics thread's core. A value
  // the user set wins.
  setenv("LP_NUM_THREADS", "0", 0);
  if (options_.window) {
    runWindow(started);
  } else {
    runHeadless(started);
  }
}

void Viewer::runHeadless(std::promise<void>* started) {
  std::unique_ptr<detail::HeadlessContext> context;
  try {
    context = std::make_unique<detail::HeadlessContext>(options_.width, options_.height);
  } catch (const NoDisplay& e) {
    start_error_ = e.what();
    started->set_value();
    return;
  }
  started->set_value();
  while (!stop_) {
    std::unique_ptr<Request> request;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || request_; });
      request = std::move(request_);
    }
    if (request) serve(*request, options_.width, options_.height, initial_camera_);
  }
}

void Viewer::runWindow(std::promise<void>* started) {
  if (!glfwInit()) {
    start_error_ =
        "no display for a window (DISPLAY unset?): snapshots and videos need none, the window "
        "does";
    started->set_value();
    return;
  }
  glfwWindowHint(GLFW_VISIBLE, options_.window ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
  GLFWwindow* window =
      glfwCreateWindow(options_.width, options_.height, options_.title.c_str(), nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    start_error_ = "GLFW could not open an OpenGL 2.1 window";
    started->set_value();
    return;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(0);
  WindowState state{initial_camera_, options_.view, 0.0, 0.0, -1, false};
  glfwSetWindowUserPointer(window, &state);
  installCallbacks(window);
  started->set_value();
  renderLoop();
  glfwDestroyWindow(window);
  glfwTerminate();
}

void Viewer::renderLoop() {
  using Clock = std::chrono::steady_clock;
  GLFWwindow* window = glfwGetCurrentContext();
  WindowState& state = stateOf(window);
  const auto period = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(1.0 / options_.render_hz));
  auto next_frame = Clock::now();
  auto status_due = Clock::now();
  std::uint64_t frames_at_status = 0;
  std::string status;
  int shots = 0;
  while (!stop_) {
    std::unique_ptr<Request> request;
    FrameState frame;
    {
      std::unique_lock lock(mutex_);
      wake_.wait_until(lock, next_frame,
                       [&] { return stop_ || request_ || Clock::now() >= next_frame; });
      request = std::move(request_);
      frame = *latest_;
    }
    if (request) {
      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      serve(*request, width, height, state.camera);
      continue;
    }
    if (stop_) continue;
    next_frame += period;
    if (next_frame < Clock::now()) next_frame = Clock::now() + period;
    wants_frame_ = true;  // the physics thread hands the next one over
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    if (width > 0 && height > 0) {
      detail::draw(*geometry_, frame, state.camera, width, height, state.view);
      if (state.snapshot) {  // the scene as drawn, without the status line
        state.snapshot = false;
        const auto file = fmt::format("snapshot_{}.png", ++shots);
        detail::writePng(file, detail::readPixels(width, height), width, height);
      }
      detail::overlay(status, width, height);
      glfwSwapBuffers(window);
      ++frames_;
    }
    glfwPollEvents();
    if (glfwWindowShouldClose(window)) closed_ = true;
    if (Clock::now() >= status_due) {  // once a second, on screen and in the title
      const double render_hz = static_cast<double>(frames_ - frames_at_status);
      frames_at_status = frames_;
      status_due = Clock::now() + std::chrono::seconds(1);
      status = fmt::format(
          "physics {:.0f} Hz   render {:.0f} fps   t = {:.2f} s{}   [C] collision  [K] contacts",
          physics_hz_.load(), render_hz, frame.sim_time,
          state.view.collision ? "   (collision view)" : "");
      glfwSetWindowTitle(window, (options_.title + "  |  " + status).c_str());
    }
  }
}

}  // namespace viewer
