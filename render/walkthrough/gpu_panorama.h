#pragma once
// One reference panorama on the GPU, ready for the warp: color (RGBA16F)
// and distance (R32F) textures, and the warp mesh of the CPU reference
// (core/synthesis/warp.h) as index buffers: the triangles that survive the stretch
// test, grouped in tiles of 32 x 32 pixels so that tiles outside the view
// are never drawn, plus the orphan vertices drawn as points. Vertex
// positions are not stored: the vertex shader displaces the grid by the
// distance texture (gl_VertexID is the pixel index).
//
// With a simplified source mesh (WarpOptions::mesh, docs/DESIGN.md,
// "Simplified source meshes") the vertices are stored explicitly (a world
// point, or a direction at infinity) and the layer shader looks the colour
// up in the colour texture along the source ray, as the CPU warp does;
// triangles are tiled by their centroid's pixel, with bounds over all
// their vertices.
//
// Walking frames are drawn at a share s of the window's side
// (render/walkthrough/frame_scale.h), where a reference pixel spans s times
// fewer of the frame's pixels than in the still frame: a surface moved by
// t / s reference pixels moves by as many of the walking frame's pixels as
// the still frame's t does of its own. So a simplified reference also
// keeps a walking mesh, its mesh simplified further to t / s_walk, which
// frames at or below the scale s_walk draw instead; on llvmpipe a small
// frame's time is the setup of its triangles (docs/history/BENCHMARKS-2026-11.md).
//
// Preparing (decoding, the stretch test, simplifying or reading the
// stored simplification, tiling) is CPU work that a loader thread does
// (PreparedPanorama); uploading it is the GL thread's.

#include "core/synthesis/warp.h"
#include "render/gl/gl_objects.h"

#include <cstdint>
#include <vector>

namespace triwalk {

struct PanoramaTile {
  GLsizei indexCount = 0;
  size_t firstIndex = 0;
  glm::vec3 lower{0.0f}, upper{0.0f};                    // bounds of its finite points
  glm::vec3 directionLower{0.0f}, directionUpper{0.0f};  // bounds of its directions at infinity
  bool hasFinite = false, hasInfinite = false;
};

struct PreparedPanorama {
  int width = 0, height = 0;
  glm::vec3 position{0.0f};
  float yaw = 0.0f;
  std::vector<uint16_t> colorHalf;  // RGBA, half floats
  std::vector<float> distance;
  // Simplified mesh: xyz a world point (w = 1) or a direction (w = 0);
  // empty for the grid.
  std::vector<glm::vec4> vertices;
  std::vector<uint32_t> triangleIndices;  // the tiles' and then the walking tiles'
  std::vector<PanoramaTile> tiles;
  // The walking mesh (empty for the grid or without one), and the largest
  // frame scale that draws it.
  std::vector<PanoramaTile> walkingTiles;
  float walkingScale = 0.0f;
  std::vector<uint32_t> orphanIndices;
  glm::vec2 poleDistances{0.0f};  // +inf at infinity
  glm::vec3 poleColors[2];

  size_t bytes() const;
};

// The walking mesh of a simplified reference: its triangles as indices
// into the source's vertices (core/synthesis/simplified_mesh_store.h keeps them),
// and the largest frame scale that draws them.
struct WalkingMesh {
  std::vector<uint32_t> triangles;
  float scale = 0.0f;
};

// source is panorama's warp source (core/synthesis/simplified_mesh_store.h makes
// it from a data set, with stored simplified triangles); walking, if
// given, a simplified source's walking mesh.
PreparedPanorama preparePanorama(const Panorama& panorama, float yawRadians, const WarpSource& source,
                                 const WalkingMesh* walking = nullptr);

class GpuPanorama {
public:
  explicit GpuPanorama(const PreparedPanorama& prepared);

  int width() const { return width_; }
  int height() const { return height_; }
  glm::vec3 position() const { return position_; }
  float yaw() const { return yaw_; }
  GLuint colorTexture() const { return color_.get(); }
  GLuint distanceTexture() const { return distance_.get(); }
  GLuint triangleIndices() const { return triangles_.get(); }
  // 0 for the grid (vertices displaced by the distance texture).
  GLuint vertexBuffer() const { return vertices_.get(); }
  GLuint orphanIndices() const { return orphans_.get(); }
  GLsizei orphanCount() const { return orphanCount_; }
  const std::vector<PanoramaTile>& tiles() const { return tiles_; }
  // The tiles a frame at `scale` of the window's side draws: the walking
  // mesh's at or below its scale, else the mesh's.
  const std::vector<PanoramaTile>& tilesAt(float scale) const;
  glm::vec2 poleDistances() const { return poleDistances_; }
  glm::vec3 poleColor(int pole) const { return poleColors_[pole]; }
  size_t bytes() const { return bytes_; }

private:
  int width_ = 0, height_ = 0;
  glm::vec3 position_{0.0f};
  float yaw_ = 0.0f;
  GlTexture color_, distance_;
  GlBuffer triangles_, orphans_, vertices_;
  GLsizei orphanCount_ = 0;
  std::vector<PanoramaTile> tiles_, walkingTiles_;
  float walkingScale_ = 0.0f;
  glm::vec2 poleDistances_{0.0f};
  glm::vec3 poleColors_[2];
  size_t bytes_ = 0;
};

}  // namespace triwalk
