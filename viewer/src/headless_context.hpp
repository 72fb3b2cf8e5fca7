#pragma once
// An OpenGL context with no display server: EGL's surfaceless platform (Mesa; llvmpipe when there
// is no GPU) drawing into a framebuffer object of a fixed size. No X server, no Xvfb.

#include <EGL/egl.h>

namespace viewer::detail {

/// A headless OpenGL 2.1-compatible context, current on the thread that made it, with a
/// width x height colour and depth target bound for drawing and reading back.
class HeadlessContext {
 public:
  /// Throws viewer::NoDisplay saying what EGL lacked.
  HeadlessContext(int width, int height);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  /// Makes the context current on the calling thread (one thread at a time draws with it).
  void bind();
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void makeCurrent();  ///< the context and its framebuffer, bound on this thread
  void release();

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  unsigned framebuffer_ = 0;
  unsigned renderbuffers_[2] = {0, 0};
  int width_, height_;
};

}  // namespace viewer::detail
