#pragma once
// Move-only owners of OpenGL object names, so every texture, buffer,
// framebuffer and vertex array is released exactly once.

#include "render/gl/gl_api.h"

#include <utility>

namespace triwalk {

template <auto& deleteFunction>
class GlObject {
public:
  GlObject() = default;
  explicit GlObject(GLuint name) : name_(name) {}
  ~GlObject() { reset(); }
  GlObject(GlObject&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;

  GLuint get() const { return name_; }
  explicit operator bool() const { return name_ != 0; }
  void reset() {
    if (name_) deleteFunction(1, &name_);
    name_ = 0;
  }

private:
  GLuint name_ = 0;
};

using GlTexture = GlObject<glDeleteTextures>;
using GlBuffer = GlObject<glDeleteBuffers>;
using GlFramebuffer = GlObject<glDeleteFramebuffers>;
using GlVertexArray = GlObject<glDeleteVertexArrays>;
using GlSampler = GlObject<glDeleteSamplers>;

GlTexture createTexture(GLenum target);
GlBuffer createBuffer();
GlFramebuffer createFramebuffer();
GlVertexArray createVertexArray();
// A sampler object with the given min/mag filter, clamped to edge.
GlSampler createSampler(GLenum filter);

// Throws GlUnavailable with the status if the framebuffer is incomplete.
void requireCompleteFramebuffer(const GlFramebuffer& framebuffer, const char* what);

}  // namespace triwalk
