#include "render/gl/gl_objects.h"

#include "render/gl/gl_context.h"

#include <string>

namespace triwalk {

GlTexture createTexture(GLenum target) {
  GLuint name = 0;
  glCreateTextures(target, 1, &name);
  return GlTexture(name);
}

GlBuffer createBuffer() {
  GLuint name = 0;
  glCreateBuffers(1, &name);
  return GlBuffer(name);
}

GlFramebuffer createFramebuffer() {
  GLuint name = 0;
  glCreateFramebuffers(1, &name);
  return GlFramebuffer(name);
}

GlVertexArray createVertexArray() {
  GLuint name = 0;
  glCreateVertexArrays(1, &name);
  return GlVertexArray(name);
}

GlSampler createSampler(GLenum filter) {
  GLuint name = 0;
  glCreateSamplers(1, &name);
  glSamplerParameteri(name, GL_TEXTURE_MIN_FILTER, GLint(filter));
  glSamplerParameteri(name, GL_TEXTURE_MAG_FILTER, GLint(filter));
  glSamplerParameteri(name, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(name, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(name, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  return GlSampler(name);
}

void requireCompleteFramebuffer(const GlFramebuffer& framebuffer, const char* what) {
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer.get(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw GlUnavailable(std::string(what) + ": framebuffer incomplete (status 0x" + std::to_string(status) + ")");
  }
}

}  // namespace triwalk
