// Headless OpenGL 4.5 core through EGL on Mesa's surfaceless platform: no
// window system, no surface (rendering goes to framebuffer objects).

#include "render/gl/gl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>

namespace triwalk {

namespace {

class EglContext final : public GlContext {
public:
  EglContext() {
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) throw GlUnavailable("EGL: eglGetPlatformDisplayEXT is not available");
    display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY) throw GlUnavailable("EGL: no surfaceless display");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display_, &major, &minor)) throw GlUnavailable("EGL: eglInitialize failed");
    if (!eglBindAPI(EGL_OPENGL_API)) {
      eglTerminate(display_);
      throw GlUnavailable("EGL: desktop OpenGL API not available");
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) {
      eglTerminate(display_);
      throw GlUnavailable("EGL: cannot create an OpenGL 4.5 core context");
    }
    makeCurrent();
    initializeGlFunctions(reinterpret_cast<GlResolver>(eglGetProcAddress), "EGL");
  }

  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

  std::string backendName() const override { return "EGL surfaceless"; }

  void makeCurrent() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      throw GlUnavailable("EGL: eglMakeCurrent without surface failed");
    }
  }

private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> createEglContext() { return std::make_unique<EglContext>(); }

}  // namespace triwalk
