#pragma once
// Forward 3D warp of an equirectangular RGB-D panorama into another camera
// (docs/DESIGN.md, "Warp and blend"). This CPU warp is the reference: decimation
// costs, evaluation and the GPU renderer's check all rest on it.
//
// Mesh warp: every source pixel is the world point p_s + d * omega; the
// pixels form two triangles per 2x2 quad, wrapping across the source seam,
// plus a fan at each pole. Triangles spanning a depth discontinuity
// ("rubber sheets") are dropped by a stretch test. The rest are rasterized
// into the destination (equirectangular: screen-linear interpolation,
// triangles crossing the seam split in two; pinhole: perspective-correct)
// with a z-buffer on destination distance. Points at infinity (sky) warp
// as directions.
//
// Vertices whose triangles were all dropped (thin structures one pixel
// wide, surfaces seen edge-on) would vanish; the mesh warp splats them as
// single points that compete in the z-buffer. Every other finite vertex is
// splatted too, but only into pixels no triangle covered: a pixel centre
// that falls just outside the kept triangles by rounding (at a silhouette,
// at the destination's poles) still gets the sample that landed there.
//
// Point warp: the paper's literal method, each source pixel splatted into
// the one destination pixel its centre lands in (leaves cracks).
//
// Determinism: the z-buffer keeps, per destination pixel, the minimum of
// (distance bits, triangle id) with atomic min, which does not depend on
// the order threads reach it; results are identical for any thread count.

#include "core/geometry/projection.h"
#include "core/image/image.h"
#include "core/support/option_range.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace triwalk {

enum class StretchTest {
  None,
  GrazingAngle,  // drop triangles seen at less than a threshold angle from the source
  DepthRatio,    // drop triangles whose farthest/nearest vertex distance exceeds a threshold
};

enum class WarpMethod { Mesh, Point };

// The triangles a source warps: its grid (two per pixel quad, the exact
// reference) or the grid simplified within a bound (docs/DESIGN.md,
// "Simplified source meshes"): far fewer triangles, the colour looked up in
// the source panorama along the ray to each covered point, so texture
// detail is kept wherever the geometry is. Panorama destinations only.
enum class SourceMesh { Grid, Simplified };

struct WarpOptions {
  WarpMethod method = WarpMethod::Mesh;
  StretchTest stretchTest = StretchTest::GrazingAngle;
  float grazingAngleDegrees = 4.0f;  // GrazingAngle: minimum angle between surface and source ray
  float maxDepthRatio = 1.15f;       // DepthRatio: maximum farthest / nearest distance
  SourceMesh mesh = SourceMesh::Grid;
  // Simplified: how far the surface may move, in source pixels at the
  // distance nearer than which 5% of the surface lies.
  float meshTolerancePixels = 0.25f;
};

inline constexpr OptionRange kGrazingAngleRange{0.0f, 89.0f};    // degrees
inline constexpr OptionRange kDepthRatioRange{1.0f, 1000.0f};
inline constexpr OptionRange kMeshToleranceRange{0.0f, 8.0f};   // source pixels

// Parses "none", "grazing-angle", "depth-ratio"; throws InputError.
StretchTest parseStretchTest(const std::string& name);
const char* stretchTestName(StretchTest test);
// Parses "grid" or "simplified"; throws InputError.
SourceMesh parseSourceMesh(const std::string& name);
const char* sourceMeshName(SourceMesh mesh);

// A source's simplified triangles in its grid's vertex numbering, surface
// and sky apart: what meshoptimizer computes (the costly part of preparing
// a simplified source) and what a data set's mesh store keeps
// (core/synthesis/simplified_mesh_store.h). With them, the source's orphans
// (WarpSource::orphan), ascending: the grid's stretch test finds them, so
// a source made from stored triangles needs no stretch test.
struct SimplifiedTriangles {
  std::vector<uint32_t> surface, sky;
  std::vector<uint32_t> orphans;
};

// A source panorama prepared for warping: world points of its pixels and
// pole vertices, and which triangles survive the stretch test (optionally
// simplified). Depends only on the source, so decimation prepares each
// sample once.
class WarpSource {
public:
  // With a simplified mesh, `stored` (when given) are the triangles and
  // orphans an earlier simplification of this same source computed; they
  // are used as they are instead of simplifying again, and only the
  // vertices they use are made.
  WarpSource(const Panorama& panorama, glm::vec3 position, float yawRadians, const WarpOptions& options,
             std::optional<SimplifiedTriangles> stored = std::nullopt);

  int width() const { return width_; }
  int height() const { return height_; }
  glm::vec3 position() const { return position_; }
  SourceMesh mesh() const { return mesh_; }
  // Grid: vertex i < W*H is pixel (i % W, i / W); W*H and W*H+1 are the
  // poles. Simplified: the pixels the simplified triangles and the orphans
  // use, in pixel order, then the poles they use. Vertices below
  // pixelVertexCount() are pixels (splatted as points), the rest poles.
  uint32_t vertexCount() const { return uint32_t(points_.size()); }
  uint32_t pixelVertexCount() const { return pixelVertexCount_; }
  glm::vec3 point(uint32_t vertex) const { return points_[vertex]; }
  bool atInfinity(uint32_t vertex) const { return infinite_[vertex] != 0; }
  glm::vec3 color(uint32_t vertex) const { return colors_[vertex]; }
  // Grid triangle ids: quads (v * W + u) * 2 + {0, 1} for v < H - 1, then
  // the top fan (W triangles), then the bottom fan (W triangles); those the
  // stretch test dropped are not kept. Simplified: a list, all kept.
  uint32_t triangleCount() const { return mesh_ == SourceMesh::Grid ? uint32_t(kept_.size()) : keptCount_; }
  bool triangleKept(uint32_t triangle) const { return mesh_ != SourceMesh::Grid || kept_[triangle] != 0; }
  void triangleVertices(uint32_t triangle, uint32_t vertices[3]) const;
  uint32_t keptTriangleCount() const { return keptCount_; }
  // A finite vertex none of whose grid triangles was kept.
  bool orphan(uint32_t vertex) const { return orphan_[vertex] != 0; }
  // 1 for a vertex whose pixel lies in the silhouette fringe
  // (core/synthesis/silhouette_fringe.h), 0 elsewhere and at the poles.
  float fringe(uint32_t vertex) const;
  // The fringe flags per pixel, row-major.
  const std::vector<uint8_t>& fringeFlags() const { return fringe_; }
  // Simplified: the fringe flags interpolated bilinearly at an image point
  // of colorsAlong, as its colour is.
  float fringeAt(glm::vec2 imagePoint) const;
  // Simplified: the source's colour along each ray from its centre
  // (bilinear, wrapping across the seam), through the rays' image points
  // (scratch space the caller keeps).
  void colorsAlong(std::span<const glm::vec3> directions, std::span<glm::vec2> imagePoints,
                   std::span<glm::vec3> colors) const;
  // Simplified: the triangles in grid numbering, for the mesh store.
  const SimplifiedTriangles& simplifiedTriangles() const { return simplifiedTriangles_; }
  // Simplified: this mesh simplified further, so that the surface may move
  // by up to extraTolerancePixels more (the same bound as the mesh's own),
  // in grid numbering like simplifiedTriangles(); the viewer's walking
  // frames draw it (render/walkthrough/gpu_panorama.h).
  SimplifiedTriangles coarserTriangles(const Panorama& panorama, float extraTolerancePixels) const;
  // Simplified: triangles in grid numbering as indices into this source's
  // vertices, surface then sky; nothing if one of their vertices is not
  // one of this source's.
  std::optional<std::vector<uint32_t>> sourceTriangles(const SimplifiedTriangles& triangles) const;

private:
  glm::vec3 colorAt(glm::vec2 imagePoint) const;  // bilinear, for colorsAlong
  SimplifiedTriangles simplifyKept(const Panorama& panorama, float tolerancePixels) const;
  void adoptSimplified(const Panorama& panorama, SimplifiedTriangles triangles);

  int width_ = 0;
  int height_ = 0;
  glm::vec3 position_{0.0f};
  EquirectProjection projection_;
  SourceMesh mesh_ = SourceMesh::Grid;
  std::vector<glm::vec3> points_;   // world point, or unit direction when at infinity
  std::vector<uint8_t> infinite_;
  std::vector<glm::vec3> colors_;   // linear
  std::vector<uint8_t> kept_;       // grid: per triangle
  std::vector<uint32_t> triangles_; // simplified: three vertices per triangle
  std::vector<uint32_t> gridVertex_;  // simplified: each vertex's grid number, ascending
  std::vector<uint8_t> orphan_;
  std::vector<uint8_t> fringe_;     // per pixel
  uint32_t pixelVertexCount_ = 0;
  uint32_t keptCount_ = 0;
  ColorImage texture_;              // simplified: the source's colours, for colorsAlong
  SimplifiedTriangles simplifiedTriangles_;
};

// Defined here so that the warp's raster loop, which calls it for every
// triangle, can inline it.
inline void WarpSource::triangleVertices(uint32_t triangle, uint32_t vertices[3]) const {
  if (mesh_ == SourceMesh::Simplified) {
    for (int k = 0; k < 3; ++k) vertices[k] = triangles_[3 * size_t(triangle) + size_t(k)];
    return;
  }
  const uint32_t width = uint32_t(width_);
  const uint32_t quadTriangles = 2 * width * uint32_t(height_ - 1);
  const uint32_t pixels = width * uint32_t(height_);
  if (triangle < quadTriangles) {
    const uint32_t quad = triangle / 2;
    const uint32_t u = quad % width, v = quad / width;
    const uint32_t u1 = (u + 1) % width;  // wraps across the source seam
    const uint32_t a = v * width + u, b = v * width + u1, c = a + width, d = b + width;
    if (triangle % 2 == 0) {
      vertices[0] = a, vertices[1] = b, vertices[2] = d;
    } else {
      vertices[0] = a, vertices[1] = d, vertices[2] = c;
    }
    return;
  }
  const uint32_t fan = triangle - quadTriangles;
  const uint32_t u = fan % width, u1 = (u + 1) % width;
  if (fan < width) {
    vertices[0] = pixels, vertices[1] = u, vertices[2] = u1;
  } else {
    const uint32_t lastRow = (uint32_t(height_) - 1) * width;
    vertices[0] = pixels + 1, vertices[1] = lastRow + u1, vertices[2] = lastRow + u;
  }
}

// A pinhole destination shows no surface nearer to its camera than this;
// the GPU warp clips at the same plane, so that the two agree.
inline constexpr float kPinholeNearPlane = 0.01f;  // metres

// A destination camera: an equirectangular panorama at a position, or a
// pinhole camera. A panorama may be warped on a lattice of its pixels:
// every stride-th row and column, pixel (x, y) of the layer being pixel
// (stride x, stride y) of the panorama, with exactly the values the whole
// panorama's warp has there (the same pixel centres, the same tests), for
// errors estimated on a quarter of the pixels at the same resolution.
struct DestinationCamera {
  enum class Kind { Equirect, Pinhole };
  Kind kind = Kind::Equirect;
  glm::vec3 position{0.0f};
  EquirectProjection equirect;
  PinholeCamera pinhole;
  int stride = 1;  // panoramas: the lattice's spacing in pixels, dividing the width and the height

  static DestinationCamera panorama(glm::vec3 position, int width, int height, float yawRadians = 0.0f);
  // The lattice of every stride-th pixel of a width x height panorama.
  static DestinationCamera panoramaLattice(glm::vec3 position, int width, int height, int stride,
                                           float yawRadians = 0.0f);
  static DestinationCamera camera(const PinholeCamera& pinhole);
  int width() const { return kind == Kind::Equirect ? equirect.width : pinhole.width; }
  int height() const { return kind == Kind::Equirect ? equirect.height : pinhole.height; }
  // The warped layer's size: the lattice's.
  int layerWidth() const { return width() / stride; }
  int layerHeight() const { return height() / stride; }
};

// What one source contributes to the destination.
// Where a warp's time went (wall clock), for `triwalk bench`.
struct WarpTimings {
  double projectSeconds = 0.0;
  double rasterSeconds = 0.0;
  double resolveSeconds = 0.0;
};

// A layer holds destination.layerWidth() x layerHeight() pixels.
struct WarpLayer {
  ColorImage color;           // linear
  ScalarImage distance;       // metres from the destination centre; +inf = sky
  std::vector<uint8_t> covered;  // 1 where the source put something
  uint64_t trianglesRasterized = 0;
  uint64_t pixelsTested = 0;  // pixel centres tested against a triangle in the raster
  WarpTimings timings;
  // Per pixel, how well the source sampled what the destination sees there
  // (core/synthesis/warp_reliability.h); empty means 1 everywhere.
  std::vector<float> reliability;

  // The per-pixel view the blend reads (see blendPixelOf).
  bool coveredAt(size_t pixel) const { return covered[pixel] != 0; }
  float distanceAt(size_t pixel) const { return distance.pixels[pixel]; }
  glm::vec3 colorAt(size_t pixel) const { return color.pixels[pixel]; }
  float reliabilityAt(size_t pixel) const { return reliability.empty() ? 1.0f : reliability[pixel]; }
};

// Whether a layer carries its per-pixel reliability: only the blend by
// reliability reads it (a tenth of a warp's time to compute).
enum class LayerReliability { Computed, Omitted };

// Which pixel centres of a panorama destination the raster tests against a
// triangle, and how: those of each row's span in the row loop (the
// default), or every one of the triangle's range by the resolve's own
// per-pixel test (the plain scan, kept to measure the spans and the row
// loop against). Both give the same layer, bit for bit: the span only
// leaves out centres no triangle edge admits, and the row loop does each
// pixel's arithmetic as the per-pixel test does.
enum class PanoramaRaster { RowSpans, BoundingBox };

WarpLayer warpToCamera(const WarpSource& source, const DestinationCamera& destination, WarpMethod method,
                       LayerReliability reliability = LayerReliability::Computed,
                       PanoramaRaster raster = PanoramaRaster::RowSpans);

}  // namespace triwalk
