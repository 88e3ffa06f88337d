#pragma once
// A Scene uploaded to the GPU: one vertex buffer, one draw range per mesh,
// every texture as mipmapped sRGB, and per eye the triangles each cube
// face can show (render/capture/cube_face_culling.h).

#include "render/capture/cube_face_culling.h"
#include "render/gl/gl_objects.h"
#include "scene/scene.h"

#include <array>
#include <vector>

namespace triwalk {

class ShaderProgram;

class GpuScene {
public:
  explicit GpuScene(const Scene& scene);

  // Chooses and uploads, for an eye, the triangles each face of a cube map
  // around it can show (GL's face order), in the scene's draw order.
  void selectCubeFaceTriangles(glm::vec3 eye);

  // What a draw must get right: everything, or the distances only (the
  // planes and distances of the surfaces, where only an alpha-tested
  // material's texture can change which surface is there).
  enum class Outputs { ColorAndDistance, Distance };

  // Draws the triangles of one face chosen by the last selectCubeFaceTriangles
  // with a scene shader (shaders/scene.vert with scene.frag, or with
  // scene_distance.frag for distances only), which must be in use; sets
  // the per-material uniforms and the textures the outputs need.
  void drawCubeFace(ShaderProgram& program, int face, Outputs outputs) const;

  size_t triangleCount() const { return triangleCount_; }
  // What the last selectCubeFaceTriangles chose, summed over the six faces.
  size_t selectedTriangles() const;

private:
  struct DrawRange {
    int material = 0;
    size_t firstIndex = 0;
    GLsizei indexCount = 0;
  };

  // What can discard a material's fragments (shaders/scene.frag's alpha
  // test), so what its distances depend on. A texture whose every alpha is
  // 255 filters to exactly 1 at every level and never discards.
  enum class Discard { Never, ByVertexAlpha, ByTexture };

  std::vector<SceneMaterial> materials_;
  std::vector<Discard> discards_;  // per material
  std::vector<GlTexture> textures_;
  std::vector<DrawRange> ranges_;  // by material: few texture binds
  std::vector<glm::vec3> positions_;
  std::vector<uint32_t> indices_;  // ranges_ index into these
  GlBuffer vertices_;
  GlVertexArray vertexArray_;
  size_t triangleCount_ = 0;

  // The last eye's selection: per face, one draw per material (into
  // faceIndexBuffer_), and the buffer's contents before upload.
  std::array<std::vector<DrawRange>, kCubeFaces> faceRanges_;
  std::array<std::vector<uint32_t>, kCubeFaces> faceIndices_;
  std::vector<uint32_t> outcodes_;
  GlBuffer faceIndexBuffer_;
};

}  // namespace triwalk
