#include "render/capture/scene_view_drawer.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <numeric>

namespace triwalk {

namespace {

constexpr int kMaxLights = 16;  // shaders/scene.frag

void setSkyUniforms(ShaderProgram& program, const SkyModel& sky) {
  program.set("skyZenith", sky.zenith);
  program.set("skyHorizon", sky.horizon);
  program.set("skyGround", sky.ground);
  program.set("skySunDirection", sky.sunDirection);
  program.set("skySunColor", sky.sunColor);
}

}  // namespace

SceneViewDrawer::SceneViewDrawer(const Scene& scene)
    : scene_(scene),
      gpuScene_(scene),
      sceneProgram_("scene.vert", "scene.frag"),
      distanceProgram_("scene.vert", "scene_distance.frag"),
      skyProgram_("fullscreen.vert", "capture_sky.frag"),
      emptyVertexArray_(createVertexArray()) {}

void SceneViewDrawer::setEye(glm::vec3 eye, GpuScene::Outputs outputs) {
  eye_ = eye;
  outputs_ = outputs;
  gpuScene_.selectCubeFaceTriangles(eye);
  // Distances only (the region search's probes) need no lights. A scene
  // with more lights than the shader takes (a floor of rooms, each with
  // its own) is lit by the nearest, in the scene's order among equals.
  lightPositions_.clear();
  lightColors_.clear();
  lightRanges_.clear();
  if (outputs != GpuScene::Outputs::ColorAndDistance) return;
  std::vector<size_t> lights(scene_.lights.size());
  std::iota(lights.begin(), lights.end(), size_t(0));
  if (lights.size() > size_t(kMaxLights)) {
    std::stable_sort(lights.begin(), lights.end(), [&](size_t a, size_t b) {
      return glm::length(scene_.lights[a].position - eye) < glm::length(scene_.lights[b].position - eye);
    });
    lights.resize(size_t(kMaxLights));
  }
  for (size_t i : lights) {
    lightPositions_.push_back(scene_.lights[i].position - eye);
    lightColors_.push_back(scene_.lights[i].color);
    lightRanges_.push_back(scene_.lights[i].range);
  }
}

void SceneViewDrawer::draw(const glm::mat4& viewProjection, std::span<const int> faces) {
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_GREATER);
  glClearDepth(0.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  ShaderProgram& program = outputs_ == GpuScene::Outputs::Distance ? distanceProgram_ : sceneProgram_;
  program.use();
  program.set("viewProjection", viewProjection);
  program.set("eye", eye_);
  if (outputs_ == GpuScene::Outputs::ColorAndDistance) {
    const int lightCount = int(lightPositions_.size());
    program.set("ambient", scene_.ambient);
    program.set("lightCount", lightCount);
    if (lightCount > 0) {
      program.setArray("lightPositions", lightPositions_.data(), lightCount);
      program.setArray("lightColors", lightColors_.data(), lightCount);
      program.setArray("lightRanges", lightRanges_.data(), lightCount);
    }
  }
  for (int face : faces) gpuScene_.drawCubeFace(program, face, outputs_);

  // Sky last, at depth 0 (infinity), only where no surface was drawn:
  // the depth test rejects covered pixels before they are shaded.
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  skyProgram_.use();
  skyProgram_.set("inverseViewProjection", glm::inverse(viewProjection));
  setSkyUniforms(skyProgram_, scene_.sky);
  glBindVertexArray(emptyVertexArray_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
}

}  // namespace triwalk
