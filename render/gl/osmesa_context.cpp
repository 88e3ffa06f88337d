// Headless OpenGL 4.5 core through OSMesa (Mesa's off-screen renderer),
// the fallback when EGL is unavailable. Rendering goes to framebuffer
// objects; the 1x1 default buffer only satisfies OSMesaMakeCurrent.

#include "render/gl/gl_context.h"

#include <GL/osmesa.h>

#include <array>

namespace triwalk {

namespace {

class OsMesaContext final : public GlContext {
public:
  OsMesaContext() {
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_ACCUM_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              4,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              5,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) throw GlUnavailable("OSMesa: cannot create an OpenGL 4.5 core context");
    makeCurrent();
    initializeGlFunctions(reinterpret_cast<GlResolver>(OSMesaGetProcAddress), "OSMesa");
  }

  ~OsMesaContext() override { OSMesaDestroyContext(context_); }

  std::string backendName() const override { return "OSMesa"; }

  void makeCurrent() override {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      throw GlUnavailable("OSMesa: OSMesaMakeCurrent failed");
    }
  }

private:
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> buffer_{};
};

}  // namespace

std::unique_ptr<GlContext> createOsMesaContext() { return std::make_unique<OsMesaContext>(); }

}  // namespace triwalk
