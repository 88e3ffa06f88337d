#include "render/capture/panorama_capturer.h"

#include "core/support/errors.h"
#include "core/synthesis/warp_layer_cache.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <optional>
#include <string>

namespace triwalk {

namespace {

// The orientation OpenGL expects for each cube face when it is rendered
// through a framebuffer and then sampled by direction, in GL's face order
// (+X, -X, +Y, -Y, +Z, -Z), which the face culling shares.
struct FaceView {
  glm::vec3 forward, up;
};
constexpr FaceView kFaceViews[6] = {{{1, 0, 0}, {0, -1, 0}},  {{-1, 0, 0}, {0, -1, 0}}, {{0, 1, 0}, {0, 0, 1}},
                                    {{0, -1, 0}, {0, 0, -1}}, {{0, 0, 1}, {0, -1, 0}},  {{0, 0, -1}, {0, -1, 0}}};

// 90-degree square frustum with reversed depth and no far plane: depth is
// near / view distance, 1 at the near plane, 0 at infinity.
glm::mat4 cubeFaceProjection() {
  glm::mat4 projection(0.0f);
  projection[0][0] = 1.0f;
  projection[1][1] = 1.0f;
  projection[2][3] = -1.0f;
  projection[3][2] = kSceneNearPlane;
  return projection;
}

void setNearestClamp(const GlTexture& texture) {
  glTextureParameteri(texture.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace

namespace {

// The cube faces and the panorama must fit the GL implementation and the
// memory left, or the capture fails later as an incomplete framebuffer
// (or is killed) without naming what was asked.
void checkCaptureSize(int width, int faceSize, const char* option) {
  GLint largestCube = 0;
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &largestCube);
  if (faceSize > largestCube) {
    throw InputError(option, "cube faces of " + std::to_string(faceSize) + " pixels; this OpenGL allows at most " +
                                 std::to_string(largestCube));
  }
  // Colour (RGBA16F), plane (RGBA32F), distance and depth (32-bit) on six
  // faces, and the panorama's colour and distance targets.
  const double bytes = 6.0 * double(faceSize) * double(faceSize) * (8 + 16 + 4 + 4) + double(width) * double(width / 2) * 24;
  if (const std::optional<size_t> available = availableMemoryBytes(); available && bytes > double(*available)) {
    throw InputError(option, "a capture at this size needs about " + std::to_string(int(bytes / double(1 << 20))) +
                                 " MiB of memory; " + std::to_string(*available >> 20) + " MiB are available");
  }
}

}  // namespace

int defaultCubeFaceSize(int width) { return std::max(16, (width * 3 / 8 + 7) / 8 * 8); }

PanoramaCapturer::PanoramaCapturer(const Scene& scene, int width, int faceSize)
    : width_(width),
      faceSize_(faceSize > 0 ? faceSize : defaultCubeFaceSize(width)),
      drawer_(scene),
      equirectProgram_("fullscreen.vert", "capture_equirect.frag") {
  checkCaptureSize(width_, faceSize_, faceSize > 0 ? "--face-size" : "--width");
  colorCube_ = createTexture(GL_TEXTURE_CUBE_MAP);
  glTextureStorage2D(colorCube_.get(), 1, GL_RGBA16F, faceSize_, faceSize_);
  glTextureParameteri(colorCube_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(colorCube_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  planeCube_ = createTexture(GL_TEXTURE_CUBE_MAP);
  glTextureStorage2D(planeCube_.get(), 1, GL_RGBA32F, faceSize_, faceSize_);
  setNearestClamp(planeCube_);
  distanceCube_ = createTexture(GL_TEXTURE_CUBE_MAP);
  glTextureStorage2D(distanceCube_.get(), 1, GL_R32F, faceSize_, faceSize_);
  setNearestClamp(distanceCube_);
  depth_ = createTexture(GL_TEXTURE_CUBE_MAP);
  glTextureStorage2D(depth_.get(), 1, GL_DEPTH_COMPONENT32F, faceSize_, faceSize_);

  const GLenum drawBuffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  for (int face = 0; face < 6; ++face) {
    GlFramebuffer& framebuffer = faceFramebuffers_[size_t(face)];
    framebuffer = createFramebuffer();
    glNamedFramebufferTextureLayer(framebuffer.get(), GL_COLOR_ATTACHMENT0, colorCube_.get(), 0, face);
    glNamedFramebufferTextureLayer(framebuffer.get(), GL_COLOR_ATTACHMENT1, planeCube_.get(), 0, face);
    glNamedFramebufferTextureLayer(framebuffer.get(), GL_COLOR_ATTACHMENT2, distanceCube_.get(), 0, face);
    glNamedFramebufferTextureLayer(framebuffer.get(), GL_DEPTH_ATTACHMENT, depth_.get(), 0, face);
    glNamedFramebufferDrawBuffers(framebuffer.get(), 3, drawBuffers);
    requireCompleteFramebuffer(framebuffer, "capture cube face");
  }

  panoramaColor_ = createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(panoramaColor_.get(), 1, GL_RGBA32F, width_, height());
  panoramaDistance_ = createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(panoramaDistance_.get(), 1, GL_R32F, width_, height());
  panoramaFramebuffer_ = createFramebuffer();
  glNamedFramebufferTexture(panoramaFramebuffer_.get(), GL_COLOR_ATTACHMENT0, panoramaColor_.get(), 0);
  glNamedFramebufferTexture(panoramaFramebuffer_.get(), GL_COLOR_ATTACHMENT1, panoramaDistance_.get(), 0);
  glNamedFramebufferDrawBuffers(panoramaFramebuffer_.get(), 2, drawBuffers);
  requireCompleteFramebuffer(panoramaFramebuffer_, "capture panorama");

  emptyVertexArray_ = createVertexArray();
  linearSampler_ = createSampler(GL_LINEAR);
}

void PanoramaCapturer::renderCubeFaces(glm::vec3 position, GpuScene::Outputs outputs) {
  const glm::mat4 projection = cubeFaceProjection();
  glViewport(0, 0, faceSize_, faceSize_);
  drawer_.setEye(position, outputs);
  for (int face = 0; face < 6; ++face) {
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f), kFaceViews[face].forward, kFaceViews[face].up);
    glBindFramebuffer(GL_FRAMEBUFFER, faceFramebuffers_[size_t(face)].get());
    drawer_.draw(projection * view, std::span<const int>(&face, 1));
  }
}

ColorImage PanoramaCapturer::cubeFaceColor(int face) const {
  std::vector<glm::vec4> rgba(size_t(faceSize_) * size_t(faceSize_));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureSubImage(colorCube_.get(), 0, 0, 0, face, faceSize_, faceSize_, 1, GL_RGBA, GL_FLOAT,
                       GLsizei(rgba.size() * sizeof(glm::vec4)), rgba.data());
  // The face was drawn through a framebuffer: its first row is the bottom one.
  ColorImage image(faceSize_, faceSize_);
  for (int y = 0; y < faceSize_; ++y) {
    for (int x = 0; x < faceSize_; ++x) {
      image.at(x, y) = glm::vec3(rgba[size_t(faceSize_ - 1 - y) * size_t(faceSize_) + size_t(x)]);
    }
  }
  return image;
}

void PanoramaCapturer::resampleToPanorama() {
  glBindFramebuffer(GL_FRAMEBUFFER, panoramaFramebuffer_.get());
  glViewport(0, 0, width_, height());
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  equirectProgram_.use();
  equirectProgram_.set("colorCube", 0);
  equirectProgram_.set("planeCube", 1);
  equirectProgram_.set("distanceCube", 2);
  equirectProgram_.set("distanceCubeLinear", 3);
  equirectProgram_.set("panoramaSize", glm::vec2(float(width_), float(height())));
  glBindTextureUnit(0, colorCube_.get());
  glBindTextureUnit(1, planeCube_.get());
  glBindTextureUnit(2, distanceCube_.get());
  glBindTextureUnit(3, distanceCube_.get());
  glBindSampler(3, linearSampler_.get());
  glBindVertexArray(emptyVertexArray_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(3, 0);
}

void PanoramaCapturer::readPanorama(GLenum attachment, GLenum format, void* pixels) const {
  // Framebuffer row 0 holds panorama row v = 0 (the pass maps it so), so
  // the read-back is already top-down.
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, panoramaFramebuffer_.get());
  glNamedFramebufferReadBuffer(panoramaFramebuffer_.get(), attachment);
  glReadPixels(0, 0, width_, height(), format, GL_FLOAT, pixels);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

Panorama PanoramaCapturer::capture(glm::vec3 position) {
  renderCubeFaces(position, GpuScene::Outputs::ColorAndDistance);
  resampleToPanorama();
  Panorama panorama{ColorImage(width_, height()), ScalarImage(width_, height())};
  std::vector<glm::vec4> rgba(panorama.color.pixelCount());
  readPanorama(GL_COLOR_ATTACHMENT0, GL_RGBA, rgba.data());
  readPanorama(GL_COLOR_ATTACHMENT1, GL_RED, panorama.distance.pixels.data());
  for (size_t i = 0; i < rgba.size(); ++i) panorama.color.pixels[i] = glm::max(glm::vec3(rgba[i]), 0.0f);
  return panorama;
}

ScalarImage PanoramaCapturer::captureDistance(glm::vec3 position) {
  renderCubeFaces(position, GpuScene::Outputs::Distance);
  resampleToPanorama();
  ScalarImage distance(width_, height());
  readPanorama(GL_COLOR_ATTACHMENT1, GL_RED, distance.pixels.data());
  return distance;
}

}  // namespace triwalk
