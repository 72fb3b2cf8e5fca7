#include "headless_context.hpp"

#include <EGL/eglext.h>
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <fmt/format.h>

#include "viewer/viewer.hpp"

namespace viewer::detail {

namespace {

std::string eglError(const char* what) {
  return fmt::format(
      "headless rendering: {} failed (EGL error 0x{:x}); Mesa's EGL (libegl-mesa0) "
      "is needed",
      what, eglGetError());
}

}  // namespace

HeadlessContext::HeadlessContext(int width, int height) : width_(width), height_(height) {
  const auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) throw NoDisplay(eglError("eglGetPlatformDisplayEXT"));
  display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
    throw NoDisplay(eglError("eglInitialize on the surfaceless platform"));
  }
  try {
    makeCurrent();
  } catch (...) {
    release();
    throw;
  }
}

void HeadlessContext::bind() {
  if (eglGetCurrentContext() == context_) return;
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
    throw NoDisplay(eglError("eglMakeCurrent without a surface"));
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
}

void HeadlessContext::makeCurrent() {
  if (!eglBindAPI(EGL_OPENGL_API)) throw NoDisplay(eglError("eglBindAPI(OpenGL)"));
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 2, EGL_CONTEXT_MINOR_VERSION, 1,
                               EGL_NONE};
  context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context_ == EGL_NO_CONTEXT) throw NoDisplay(eglError("eglCreateContext (OpenGL 2.1)"));
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
    throw NoDisplay(eglError("eglMakeCurrent without a surface"));
  }
  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glGenRenderbuffers(2, renderbuffers_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            renderbuffers_[0]);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_, height_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                            renderbuffers_[1]);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw NoDisplay(fmt::format("headless rendering: no {}x{} framebuffer", width_, height_));
  }
}

HeadlessContext::~HeadlessContext() {
  release();
}

void HeadlessContext::release() {
  if (context_ != EGL_NO_CONTEXT) {
    // The framebuffer's names are this context's: deleted with another context current (a newer
    // camera's), they would delete that one's framebuffer, and it would draw black.
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_);
    glDeleteRenderbuffers(2, renderbuffers_);
    glDeleteFramebuffers(1, &framebuffer_);
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    context_ = EGL_NO_CONTEXT;
  }
  // The display is Mesa's one surfaceless display, shared by every headless context of the
  // process: eglTerminate here would pull it from under another thread's context.
}

}  // namespace viewer::detail
