#include "render/capture/truth_frame_renderer.h"

#include "core/support/errors.h"

#include <vector>

namespace triwalk {

TruthFrameRenderer::TruthFrameRenderer(const Scene& scene, int width, int height, int supersampling)
    : drawer_(scene), width_(width), height_(height), supersampling_(supersampling) {
  TRIWALK_CHECK(width > 0 && height > 0 && supersampling >= 1, "a truth frame needs a size and a sample count");
  const int samplesWide = width * supersampling, samplesHigh = height * supersampling;
  // The colour format of the capture's cube faces, so that a truth frame
  // of a face's pose equals the face.
  color_ = createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(color_.get(), 1, GL_RGBA16F, samplesWide, samplesHigh);
  depth_ = createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(depth_.get(), 1, GL_DEPTH_COMPONENT32F, samplesWide, samplesHigh);
  framebuffer_ = createFramebuffer();
  glNamedFramebufferTexture(framebuffer_.get(), GL_COLOR_ATTACHMENT0, color_.get(), 0);
  glNamedFramebufferTexture(framebuffer_.get(), GL_DEPTH_ATTACHMENT, depth_.get(), 0);
  // The scene shaders also write a plane and a distance; without buffers
  // for them those outputs are dropped.
  const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
  glNamedFramebufferDrawBuffers(framebuffer_.get(), 1, &drawBuffer);
  requireCompleteFramebuffer(framebuffer_, "truth frame");
}

ColorImage TruthFrameRenderer::render(const PinholeCamera& camera) {
  TRIWALK_CHECK(camera.width == width_ && camera.height == height_, "a truth frame of another size");
  const int samplesWide = width_ * supersampling_, samplesHigh = height_ * supersampling_;
  PinholeCamera eyeRelative = camera;  // the scene shader subtracts the eye
  eyeRelative.position = glm::vec3(0.0f);
  eyeRelative.width = samplesWide;
  eyeRelative.height = samplesHigh;
  const int faces[6] = {0, 1, 2, 3, 4, 5};
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glViewport(0, 0, samplesWide, samplesHigh);
  drawer_.setEye(camera.position, GpuScene::Outputs::ColorAndDistance);
  drawer_.draw(pinholeViewProjection(eyeRelative, kSceneNearPlane), faces);

  std::vector<glm::vec4> rgba(size_t(samplesWide) * size_t(samplesHigh));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glNamedFramebufferReadBuffer(framebuffer_.get(), GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.get());
  glReadPixels(0, 0, samplesWide, samplesHigh, GL_RGBA, GL_FLOAT, rgba.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  // The mean of each pixel's samples; OpenGL's first row is the bottom one.
  ColorImage frame(width_, height_);
  const float weight = 1.0f / float(supersampling_ * supersampling_);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      glm::vec3 sum(0.0f);
      for (int sy = 0; sy < supersampling_; ++sy) {
        const size_t row = size_t(samplesHigh - 1 - (y * supersampling_ + sy));
        for (int sx = 0; sx < supersampling_; ++sx) {
          sum += glm::max(glm::vec3(rgba[row * size_t(samplesWide) + size_t(x * supersampling_ + sx)]), 0.0f);
        }
      }
      frame.at(x, y) = sum * weight;
    }
  }
  return frame;
}

}  // namespace triwalk
