#pragma once
// Draws a Scene as the capture sees it from one eye: the shaded surfaces
// (shaders/scene.vert with scene.frag: colour, plane and distance, or
// scene_distance.frag for distances alone) and the sky where no surface
// is, with reversed depth and no far plane, into the bound framebuffer.
// The capture's cube faces and the truth frames of `render --truth` are
// both drawn through it, so a truth frame is what a capture there would
// have seen. Needs a current GL 4.5 context.

#include "render/capture/gpu_scene.h"
#include "render/gl/gl_objects.h"
#include "render/gl/shader_program.h"
#include "scene/scene.h"

#include <span>
#include <vector>

namespace triwalk {

// The near plane of every view of a scene, metres.
constexpr float kSceneNearPlane = 0.01f;

class SceneViewDrawer {
public:
  explicit SceneViewDrawer(const Scene& scene);

  // Chooses what is drawn from `eye`: the triangles each cube face around
  // it can show and, for colour, the lights nearest it.
  void setEye(glm::vec3 eye, GpuScene::Outputs outputs);

  // Clears the bound framebuffer's depth and draws into its viewport the
  // triangles the given cube faces of the eye can show (all six for a view
  // that is not a cube face: a triangle on two faces is drawn twice, the
  // second time rejected by the depth test), then the sky behind them.
  // viewProjection maps eye-relative positions to clip space.
  void draw(const glm::mat4& viewProjection, std::span<const int> faces);

  size_t sceneTriangles() const { return gpuScene_.triangleCount(); }
  size_t selectedTriangles() const { return gpuScene_.selectedTriangles(); }

private:
  const Scene& scene_;
  GpuScene gpuScene_;
  ShaderProgram sceneProgram_;
  ShaderProgram distanceProgram_;  // no shading: distances alone
  ShaderProgram skyProgram_;
  GlVertexArray emptyVertexArray_;
  glm::vec3 eye_{0.0f};
  GpuScene::Outputs outputs_ = GpuScene::Outputs::ColorAndDistance;
  std::vector<glm::vec3> lightPositions_, lightColors_;  // eye-relative positions
  std::vector<float> lightRanges_;
};

}  // namespace triwalk
