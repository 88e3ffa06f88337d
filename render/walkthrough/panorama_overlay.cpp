#include "render/walkthrough/panorama_overlay.h"

namespace triwalk {

PanoramaOverlay::PanoramaOverlay()
    : program_("fullscreen.vert", "panorama_overlay.frag"), vertexArray_(createVertexArray()),
      sampler_(createSampler(GL_LINEAR)) {
  // Round the panorama's seam, not across it.
  glSamplerParameteri(sampler_.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
}

void PanoramaOverlay::draw(GLuint texture, glm::ivec2 size, float panoramaYawDegrees, const PinholeCamera& camera,
                           float aspect, float opacity) {
  const float tanY = camera.tanHalfFovY();
  program_.use();
  program_.set("forward", camera.forward());
  program_.set("right", camera.right() * (tanY * aspect));
  program_.set("up", camera.up() * tanY);
  program_.set("panoramaSize", glm::vec2(size));
  program_.set("panoramaYaw", degreesToRadians(panoramaYawDegrees));
  program_.set("opacity", opacity);
  program_.set("panorama", 0);
  glBindTextureUnit(0, texture);
  glBindSampler(0, sampler_.get());
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBindVertexArray(vertexArray_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDisable(GL_BLEND);
  glBindSampler(0, 0);
}

}  // namespace triwalk
