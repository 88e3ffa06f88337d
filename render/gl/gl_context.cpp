#include "render/gl/gl_context.h"

#include "core/support/errors.h"
#include "render/gl/gl_api.h"

#include <cstdio>

namespace triwalk {

std::unique_ptr<GlContext> createEglContext();
std::unique_ptr<GlContext> createOsMesaContext();

HeadlessBackend parseHeadlessBackend(const std::string& name) {
  if (name == "auto") return HeadlessBackend::Auto;
  if (name == "egl") return HeadlessBackend::Egl;
  if (name == "osmesa") return HeadlessBackend::OsMesa;
  throw InputError("--gl", "unknown OpenGL backend '" + name + "' (use auto, egl or osmesa)");
}

std::string GlContext::description() const {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "?") + ", " + (version ? version : "?") + " via " + backendName();
}

void initializeGlFunctions(GlResolver resolve, const std::string& backendName) {
  const char* missing = loadGlFunctions(resolve);
  if (*missing) throw GlUnavailable(backendName + ": OpenGL entry point " + missing + " is missing");
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 45) {
    throw GlUnavailable(backendName + ": OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
                        " context, 4.5 core is needed");
  }
}

std::unique_ptr<GlContext> createHeadlessContext(HeadlessBackend backend) {
  if (backend == HeadlessBackend::Egl) return createEglContext();
  if (backend == HeadlessBackend::OsMesa) return createOsMesaContext();
  try {
    return createEglContext();
  } catch (const GlUnavailable& eglFailure) {
    std::fprintf(stderr, "triwalk: %s; falling back to OSMesa\n", eglFailure.what());
    return createOsMesaContext();
  }
}

}  // namespace triwalk
