#pragma once
// Renders equirectangular RGB-D panoramas of a scene with OpenGL: six
// 90-degree cube faces (shaded color, the plane of each fragment's
// triangle, its distance), then a resampling pass into the panorama whose
// distance is the exact ray-plane intersection along each pixel's
// direction (the Euclidean distance docs/DESIGN.md asks for, not z-buffer depth).
// Needs a current GL 4.5 context.

#include "core/image/image.h"
#include "render/capture/scene_view_drawer.h"
#include "render/gl/gl_objects.h"
#include "render/gl/shader_program.h"
#include "scene/scene.h"

#include <array>
#include <memory>

namespace triwalk {

// A face texel at the face centre spans 2 / faceSize radians, a panorama
// pixel at the equator 2 pi / width: 3/8 of the width gives 1.2 texels per
// pixel at the centre and more towards the edges; the resampling pass
// takes 2x2 samples per pixel on top of that.
int defaultCubeFaceSize(int width);

class PanoramaCapturer {
public:
  // faceSize 0 picks defaultCubeFaceSize(width).
  PanoramaCapturer(const Scene& scene, int width, int faceSize = 0);

  Panorama capture(glm::vec3 position);
  // The distance panorama alone, the same bits as capture's, faster: a
  // shader that does not shade (shaders/scene_distance.frag), and only the
  // textures an alpha test needs bound (the walkable region's probes,
  // which read distances only).
  ScalarImage captureDistance(glm::vec3 position);

  int width() const { return width_; }
  int height() const { return width_ / 2; }
  size_t sceneTriangles() const { return drawer_.sceneTriangles(); }
  // Triangles the last capture drew over its six cube faces: each only on
  // the faces it can show on (render/capture/cube_face_culling.h).
  size_t trianglesDrawn() const { return drawer_.selectedTriangles(); }
  // The linear colour of one cube face of the last capture (GL's face
  // order), top row first, as drawn before the resampling: what a truth
  // frame of the same pose must equal.
  ColorImage cubeFaceColor(int face) const;

private:
  void renderCubeFaces(glm::vec3 position, GpuScene::Outputs outputs);
  void resampleToPanorama();
  // One attachment of the panorama framebuffer, as floats.
  void readPanorama(GLenum attachment, GLenum format, void* pixels) const;

  int width_;
  int faceSize_;
  SceneViewDrawer drawer_;
  ShaderProgram equirectProgram_;
  GlTexture colorCube_, planeCube_, distanceCube_, depth_;
  std::array<GlFramebuffer, 6> faceFramebuffers_;
  GlTexture panoramaColor_, panoramaDistance_;
  GlFramebuffer panoramaFramebuffer_;
  GlVertexArray emptyVertexArray_;
  GlSampler linearSampler_;
};

}  // namespace triwalk
