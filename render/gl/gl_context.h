#pragma once
// One interface for the three ways triwalk gets an OpenGL 4.5 core context:
// EGL surfaceless and OSMesa (headless; no X server, no GPU needed) and a
// GLFW window (the viewer, render/gl/glfw_window_context.h). Creating a
// context makes it current and loads the GL entry points (render/gl/gl_api.h);
// only one context is used at a time in a process.

#include <memory>
#include <stdexcept>
#include <string>

namespace triwalk {

// No usable OpenGL 4.5 context could be made; the message says why.
class GlUnavailable : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

enum class HeadlessBackend { Auto, Egl, OsMesa };

// Parses "auto", "egl" or "osmesa"; throws InputError otherwise.
HeadlessBackend parseHeadlessBackend(const std::string& name);

class GlContext {
public:
  virtual ~GlContext() = default;
  virtual std::string backendName() const = 0;
  virtual void makeCurrent() = 0;

  // "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6"
  std::string description() const;
};

// Auto tries EGL surfaceless first and falls back to OSMesa.
std::unique_ptr<GlContext> createHeadlessContext(HeadlessBackend backend = HeadlessBackend::Auto);

// Loads the entry points through resolve and checks for GL 4.5 core;
// throws GlUnavailable naming the backend otherwise.
using GlResolver = void* (*)(const char* name);
void initializeGlFunctions(GlResolver resolve, const std::string& backendName);

}  // namespace triwalk
