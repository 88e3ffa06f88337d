#pragma once
// The GPU warp (docs/DESIGN.md, "Rendering"): the view of a pinhole camera from
// up to three reference panoramas. Each reference is drawn as its grid mesh
// into its own layer with a depth test (its nearest surface per pixel, as
// the CPU reference keeps one layer per source); a full-screen resolve pass
// then blends the layers within epsilon * z_front with the inverse-distance
// weights and marks holes. One geometry pass per reference (not two over
// all references) halves the triangles llvmpipe sets up, and matches the
// CPU reference exactly where a reference overlaps itself. Tiles of the
// reference grids outside the view frustum are not drawn.

#include "core/geometry/projection.h"
#include "core/image/image.h"
#include "core/synthesis/blend.h"
#include "render/gl/gl_objects.h"
#include "render/gl/shader_program.h"
#include "render/walkthrough/gpu_panorama.h"

#include <array>
#include <span>

namespace triwalk {

struct GpuWarpSettings {
  BlendOptions blend;
  glm::vec3 holeColor{1.0f, 0.0f, 1.0f};  // display color; black to hide holes
  bool showSources = false;               // red, green, blue: which references contributed
};

struct GpuFrameStatistics {
  size_t tilesDrawn = 0, tilesCulled = 0;
  size_t trianglesDrawn = 0;
  // With timing requested (glFinish after each pass): milliseconds.
  std::array<double, 3> layerMilliseconds{};
  double resolveMilliseconds = 0.0;
};

class GpuWarper {
public:
  GpuWarper(int width, int height);
  void resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }

  // Renders into the output framebuffer; references: 1 to 3.
  GpuFrameStatistics render(const PinholeCamera& camera, std::span<const GpuPanorama* const> references,
                            const GpuWarpSettings& settings, bool timePasses = false);

  // The last frame, top row first.
  Rgb8Image readPixels() const;
  GLuint outputFramebuffer() const { return outputFramebuffer_.get(); }
  GLuint outputTexture() const { return output_.get(); }

private:
  void drawLayer(const PinholeCamera& camera, const GpuPanorama& reference, int layer, GpuFrameStatistics& statistics);

  int width_ = 0, height_ = 0;
  ShaderProgram layerProgram_;
  ShaderProgram resolveProgram_;
  std::array<GlTexture, 3> layers_;
  GlTexture depth_;
  std::array<GlFramebuffer, 3> layerFramebuffers_;
  GlTexture output_;
  GlFramebuffer outputFramebuffer_;
  GlVertexArray vertexArray_;
};

// World -> clip for a pinhole camera, reversed depth (1 at the near plane,
// 0 at infinity) with glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE).
glm::mat4 pinholeViewProjection(const PinholeCamera& camera, float near);

}  // namespace triwalk
