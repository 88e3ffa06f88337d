#pragma once
// A Scene uploaded to the GPU: one vertex buffer, one index buffer, one
// draw range per mesh, and every texture as mipmapped sRGB.

#include "render/gl/gl_objects.h"
#include "render/scene/scene.h"

#include <vector>

namespace triwalk {

class ShaderProgram;

class GpuScene {
public:
  explicit GpuScene(const Scene& scene);

  // Draws every mesh with the scene shader (shaders/scene.*), which must
  // be in use; sets the per-material uniforms and textures.
  void draw(ShaderProgram& program) const;

  size_t triangleCount() const { return triangleCount_; }

private:
  struct DrawRange {
    int material = 0;
    size_t firstIndex = 0;
    GLsizei indexCount = 0;
  };

  std::vector<SceneMaterial> materials_;
  std::vector<GlTexture> textures_;
  std::vector<DrawRange> ranges_;
  GlBuffer vertices_;
  GlBuffer indices_;
  GlVertexArray vertexArray_;
  size_t triangleCount_ = 0;
};

}  // namespace triwalk
