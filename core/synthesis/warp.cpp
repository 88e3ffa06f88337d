#include "core/synthesis/warp.h"

#include "core/support/errors.h"
#include "core/synthesis/mesh_simplification.h"
#include "core/synthesis/silhouette_fringe.h"
#include "core/synthesis/warp_reliability.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>

namespace triwalk {

StretchTest parseStretchTest(const std::string& name) {
  if (name == "none") return StretchTest::None;
  if (name == "grazing-angle") return StretchTest::GrazingAngle;
  if (name == "depth-ratio") return StretchTest::DepthRatio;
  throw InputError("stretch_test", "unknown stretch test '" + name + "' (use grazing-angle, depth-ratio or none)");
}

const char* stretchTestName(StretchTest test) {
  switch (test) {
    case StretchTest::None: return "none";
    case StretchTest::GrazingAngle: return "grazing-angle";
    case StretchTest::DepthRatio: return "depth-ratio";
  }
  return "?";
}

SourceMesh parseSourceMesh(const std::string& name) {
  if (name == "grid") return SourceMesh::Grid;
  if (name == "simplified") return SourceMesh::Simplified;
  throw InputError("source_mesh", "unknown source mesh '" + name + "' (use simplified or grid)");
}

const char* sourceMeshName(SourceMesh mesh) { return mesh == SourceMesh::Grid ? "grid" : "simplified"; }

// ---------------------------------------------------------------- source --

namespace {

struct SourceVertex {
  glm::vec3 point;  // world point, or unit direction when at infinity
  glm::vec3 color;
  bool infinite = false;
};

SourceVertex pixelVertex(const Panorama& panorama, const EquirectProjection& projection, glm::vec3 position, int u,
                         int v) {
  const size_t i = size_t(v) * size_t(panorama.width()) + size_t(u);
  const glm::vec3 direction = projection.pixelDirection(u, v);
  const float d = panorama.distance.pixels[i];
  const bool infinite = std::isinf(d);
  return {infinite ? direction : position + d * direction, panorama.color.pixels[i], infinite};
}

// Pole vertices close the caps above the first and below the last row:
// the mean of that row's points and colors, at infinity if any is.
SourceVertex poleVertex(const Panorama& panorama, glm::vec3 position, int pole) {
  const int width = panorama.width();
  const size_t first = size_t(pole == 0 ? 0 : panorama.height() - 1) * size_t(width);
  bool anyInfinite = false;
  double distanceSum = 0.0;
  glm::dvec3 colorSum(0.0);
  for (int u = 0; u < width; ++u) {
    const float d = panorama.distance.pixels[first + size_t(u)];
    anyInfinite |= std::isinf(d);
    distanceSum += anyInfinite ? 0.0 : double(d);
    colorSum += glm::dvec3(panorama.color.pixels[first + size_t(u)]);
  }
  const glm::vec3 up(0.0f, 0.0f, pole == 0 ? 1.0f : -1.0f);
  return {anyInfinite ? up : position + float(distanceSum / width) * up, glm::vec3(colorSum / double(width)),
          anyInfinite};
}

}  // namespace

WarpSource::WarpSource(const Panorama& panorama, glm::vec3 position, float yawRadians, const WarpOptions& options,
                       std::optional<SimplifiedTriangles> stored)
    : width_(panorama.width()),
      height_(panorama.height()),
      position_(position),
      projection_{panorama.width(), panorama.height(), yawRadians} {
  TRIWALK_CHECK(width_ >= 2 && height_ >= 2, "panorama too small to warp");
  fringe_ = silhouetteFringe(panorama.distance);
  if (options.mesh == SourceMesh::Simplified && stored) {
    // A stored mesh names its orphans too: the grid's points and stretch
    // test, most of a reference's preparation in the viewer's loader
    // (docs/history/BENCHMARKS-2026-11.md, 2026-11-28), are not needed.
    adoptSimplified(panorama, std::move(*stored));
    return;
  }
  const size_t pixels = size_t(width_) * size_t(height_);
  points_.resize(pixels + 2);
  infinite_.resize(pixels + 2);
  colors_.resize(pixels + 2);
  const auto setVertex = [&](size_t i, const SourceVertex& vertex) {
    points_[i] = vertex.point;
    infinite_[i] = vertex.infinite;
    colors_[i] = vertex.color;
  };
  tbb::parallel_for(tbb::blocked_range<int>(0, height_), [&](const tbb::blocked_range<int>& rows) {
    for (int v = rows.begin(); v != rows.end(); ++v) {
      for (int u = 0; u < width_; ++u) {
        setVertex(size_t(v) * size_t(width_) + size_t(u), pixelVertex(panorama, projection_, position, u, v));
      }
    }
  });
  for (int pole = 0; pole < 2; ++pole) setVertex(pixels + size_t(pole), poleVertex(panorama, position, pole));

  const uint32_t triangles = 2 * uint32_t(width_) * uint32_t(height_ - 1) + 2 * uint32_t(width_);
  kept_.resize(triangles);
  const float minimumSine = std::sin(degreesToRadians(options.grazingAngleDegrees));
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, triangles, 4096), [&](const tbb::blocked_range<uint32_t>& range) {
    for (uint32_t t = range.begin(); t != range.end(); ++t) {
      uint32_t v[3];
      triangleVertices(t, v);
      const int infiniteCount = infinite_[v[0]] + infinite_[v[1]] + infinite_[v[2]];
      bool keep = false;
      if (infiniteCount == 3) {
        keep = true;  // sky: a triangle of directions
      } else if (infiniteCount > 0) {
        keep = false;  // stretched from a surface to infinity
      } else {
        const glm::vec3 a = points_[v[0]], b = points_[v[1]], c = points_[v[2]];
        switch (options.stretchTest) {
          case StretchTest::None: keep = true; break;
          case StretchTest::GrazingAngle: {
            const glm::vec3 normal = glm::cross(b - a, c - a);
            const glm::vec3 ray = (a + b + c) / 3.0f - position;
            const float scale = glm::length(normal) * glm::length(ray);
            keep = scale > 0.0f && std::abs(glm::dot(normal, ray)) >= minimumSine * scale;
            break;
          }
          case StretchTest::DepthRatio: {
            const float da = glm::length(a - position), db = glm::length(b - position), dc = glm::length(c - position);
            keep = std::max({da, db, dc}) <= options.maxDepthRatio * std::min({da, db, dc});
            break;
          }
        }
      }
      kept_[t] = keep;
    }
  });
  keptCount_ = uint32_t(std::count(kept_.begin(), kept_.end(), uint8_t(1)));

  orphan_.assign(points_.size(), 1);
  for (uint32_t t = 0; t < triangles; ++t) {
    if (!kept_[t]) continue;
    uint32_t v[3];
    triangleVertices(t, v);
    orphan_[v[0]] = orphan_[v[1]] = orphan_[v[2]] = 0;
  }
  for (size_t i = 0; i < points_.size(); ++i) orphan_[i] &= uint8_t(!infinite_[i]);
  pixelVertexCount_ = uint32_t(pixels);
  if (options.mesh == SourceMesh::Simplified) {
    SimplifiedTriangles simplified = simplifyKept(panorama, options.meshTolerancePixels);
    for (uint32_t v = 0; v < uint32_t(orphan_.size()); ++v) {
      if (orphan_[v]) simplified.orphans.push_back(v);
    }
    adoptSimplified(panorama, std::move(simplified));
  }
}

namespace {

// The distance nearer than which 5% of the source's finite surface lies: a
// tolerance in pixels becomes metres there, so nearer surfaces may move by
// a little more than the tolerance in pixels, farther ones by less.
float nearSurfaceDistance(const Panorama& panorama) {
  std::vector<float> distances;
  for (const float d : panorama.distance.pixels) {
    if (std::isfinite(d)) distances.push_back(d);
  }
  if (distances.empty()) return 0.0f;
  const auto nth = distances.begin() + std::ptrdiff_t(distances.size() / 20);
  std::nth_element(distances.begin(), nth, distances.end());
  return *nth;
}

// Surfaces and sky apart: sky vertices are directions, not points, and no
// triangle joins the two; pixelAngle is the source's, in radians.
SimplifiedTriangles simplifyWithin(const SimplifiedTriangles& triangles, std::span<const glm::vec3> points,
                                   float tolerancePixels, float pixelAngle, float nearDistance) {
  return {simplifyTriangles(triangles.surface, points, tolerancePixels * pixelAngle * nearDistance),
          simplifyTriangles(triangles.sky, points, tolerancePixels * pixelAngle), triangles.orphans};
}

}  // namespace

SimplifiedTriangles WarpSource::simplifyKept(const Panorama& panorama, float tolerancePixels) const {
  SimplifiedTriangles kept;
  for (uint32_t t = 0; t < uint32_t(kept_.size()); ++t) {
    if (!kept_[t]) continue;
    uint32_t v[3];
    triangleVertices(t, v);
    std::vector<uint32_t>& list = infinite_[v[0]] ? kept.sky : kept.surface;
    list.insert(list.end(), v, v + 3);
  }
  const float pixelAngle = 2.0f * float(std::numbers::pi) / float(width_);
  return simplifyWithin(kept, points_, tolerancePixels, pixelAngle, nearSurfaceDistance(panorama));
}

SimplifiedTriangles WarpSource::coarserTriangles(const Panorama& panorama, float extraTolerancePixels) const {
  TRIWALK_CHECK(mesh_ == SourceMesh::Simplified, "only a simplified mesh is simplified further");
  // triangles_ holds the surface's, then the sky's (adoptSimplified).
  const auto skyStart = triangles_.begin() + std::ptrdiff_t(simplifiedTriangles_.surface.size());
  const SimplifiedTriangles mine{{triangles_.begin(), skyStart}, {skyStart, triangles_.end()}, {}};
  const float pixelAngle = 2.0f * float(std::numbers::pi) / float(width_);
  SimplifiedTriangles coarser =
      simplifyWithin(mine, points_, extraTolerancePixels, pixelAngle, nearSurfaceDistance(panorama));
  for (std::vector<uint32_t>* list : {&coarser.surface, &coarser.sky}) {
    for (uint32_t& v : *list) v = gridVertex_[v];
  }
  return coarser;
}

std::optional<std::vector<uint32_t>> WarpSource::sourceTriangles(const SimplifiedTriangles& triangles) const {
  TRIWALK_CHECK(mesh_ == SourceMesh::Simplified, "only a simplified mesh numbers its vertices apart from the grid");
  // Each grid vertex's number here, by table: a walking mesh has a few
  // hundred thousand indices, and a search per index took half as long as
  // the grid's stretch test in the viewer's loader (docs/history/BENCHMARKS-2026-11.md,
  // 2026-11-28).
  constexpr uint32_t kNotMine = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> numberOf(size_t(width_) * size_t(height_) + 2, kNotMine);
  for (uint32_t mine = 0; mine < uint32_t(gridVertex_.size()); ++mine) numberOf[gridVertex_[mine]] = mine;
  std::vector<uint32_t> mine;
  mine.reserve(triangles.surface.size() + triangles.sky.size());
  for (const std::vector<uint32_t>* list : {&triangles.surface, &triangles.sky}) {
    for (const uint32_t v : *list) {
      if (v >= numberOf.size() || numberOf[v] == kNotMine) return std::nullopt;
      mine.push_back(numberOf[v]);
    }
  }
  return mine;
}

void WarpSource::adoptSimplified(const Panorama& panorama, SimplifiedTriangles triangles) {
  // Keep the vertices the triangles and the orphan splats use, pixels
  // first in pixel order, then the poles, each made from the panorama.
  const uint32_t pixels = uint32_t(width_) * uint32_t(height_);
  std::vector<uint8_t> used(pixels + 2, 0), orphan(pixels + 2, 0);
  for (const std::vector<uint32_t>* list : {&triangles.surface, &triangles.sky}) {
    for (const uint32_t v : *list) used[v] = 1;
  }
  for (const uint32_t v : triangles.orphans) used[v] = orphan[v] = 1;
  constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> compact(pixels + 2, kUnused);
  points_.clear();
  colors_.clear();
  infinite_.clear();
  orphan_.clear();
  gridVertex_.clear();
  for (uint32_t v = 0; v < pixels + 2; ++v) {
    if (!used[v]) continue;
    compact[v] = uint32_t(points_.size());
    gridVertex_.push_back(v);
    const SourceVertex vertex =
        v < pixels ? pixelVertex(panorama, projection_, position_, int(v % uint32_t(width_)), int(v / uint32_t(width_)))
                   : poleVertex(panorama, position_, int(v - pixels));
    points_.push_back(vertex.point);
    colors_.push_back(vertex.color);
    infinite_.push_back(vertex.infinite);
    orphan_.push_back(orphan[v]);
  }
  pixelVertexCount_ = uint32_t(std::count(used.begin(), used.begin() + pixels, uint8_t(1)));
  triangles_.clear();
  for (const std::vector<uint32_t>* list : {&triangles.surface, &triangles.sky}) {
    for (const uint32_t v : *list) triangles_.push_back(compact[v]);
  }
  kept_.clear();
  keptCount_ = uint32_t(triangles_.size() / 3);
  mesh_ = SourceMesh::Simplified;
  texture_ = panorama.color;
  simplifiedTriangles_ = std::move(triangles);
}

void WarpSource::colorsAlong(std::span<const glm::vec3> directions, std::span<glm::vec2> imagePoints,
                             std::span<glm::vec3> colors) const {
  projection_.imagePoints(directions, imagePoints);
  for (size_t i = 0; i < directions.size(); ++i) colors[i] = colorAt(imagePoints[i]);
}

namespace {

// Bilinear interpolation of per-pixel values value(pixel index) at an image
// point of a width x height panorama, wrapping across the seam as the GPU's
// colour texture does.
template <typename Value>
auto bilinearAt(glm::vec2 p, int width, int height, Value value) {
  const float fx = p.x - 0.5f, fy = std::clamp(p.y - 0.5f, 0.0f, float(height - 1));
  const int x0 = int(std::floor(fx)), y0 = int(fy);
  const float tx = fx - float(x0), ty = fy - float(y0);
  // imagePoint's x lies in [0, W), so x0 is -1 to W - 1: wrap by a compare,
  // not a division (this runs for every pixel a simplified warp covers).
  const int xa = x0 < 0 ? x0 + width : x0, xb = xa + 1 == width ? 0 : xa + 1;
  const int ya = y0, yb = std::min(y0 + 1, height - 1);
  auto at = [&](int x, int y) { return value(size_t(y) * size_t(width) + size_t(x)); };
  return (1.0f - ty) * ((1.0f - tx) * at(xa, ya) + tx * at(xb, ya)) + ty * ((1.0f - tx) * at(xa, yb) + tx * at(xb, yb));
}

}  // namespace

glm::vec3 WarpSource::colorAt(glm::vec2 p) const {
  return bilinearAt(p, width_, height_, [&](size_t i) { return texture_.pixels[i]; });
}

float WarpSource::fringeAt(glm::vec2 p) const {
  return bilinearAt(p, width_, height_, [&](size_t i) { return float(fringe_[i]); });
}

float WarpSource::fringe(uint32_t vertex) const {
  const uint32_t pixel = mesh_ == SourceMesh::Simplified ? gridVertex_[vertex] : vertex;
  return pixel < fringe_.size() ? float(fringe_[pixel]) : 0.0f;
}

DestinationCamera DestinationCamera::panorama(glm::vec3 position, int width, int height, float yawRadians) {
  DestinationCamera camera;
  camera.kind = Kind::Equirect;
  camera.position = position;
  camera.equirect = {width, height, yawRadians};
  return camera;
}

DestinationCamera DestinationCamera::panoramaLattice(glm::vec3 position, int width, int height, int stride,
                                                     float yawRadians) {
  TRIWALK_CHECK(std::has_single_bit(unsigned(stride)) && width % stride == 0 && height % stride == 0,
                "a lattice's stride must be a power of two dividing the panorama");
  DestinationCamera camera = panorama(position, width, height, yawRadians);
  camera.stride = stride;
  return camera;
}

DestinationCamera DestinationCamera::camera(const PinholeCamera& pinhole) {
  DestinationCamera camera;
  camera.kind = Kind::Pinhole;
  camera.position = pinhole.position;
  camera.pinhole = pinhole;
  return camera;
}

// ------------------------------------------------------------------ warp --

namespace {

using Clock = std::chrono::steady_clock;

constexpr uint64_t kEmpty = std::numeric_limits<uint64_t>::max();

// Z-buffer payload: (triangle << 2) for a triangle, (vertex << 2) | 3 for
// a splatted point.
constexpr uint32_t kPointPayload = 3;

// A source vertex as the destination sees it.
struct ProjectedVertex {
  glm::dvec3 relative{0.0};   // vector from the destination (a direction at infinity)
  glm::vec2 screen{0.0f};     // continuous image coordinates
  float inverseDistance = 0;  // 1 / metres from the destination, 0 at infinity
  float depth = 1.0f;         // pinhole: camera-frame depth, for perspective-correct interpolation
  bool valid = false;
};

ProjectedVertex projectVertex(const WarpSource& source, uint32_t vertex, const DestinationCamera& destination) {
  ProjectedVertex projected;
  const bool infinite = source.atInfinity(vertex);
  const glm::vec3 point = source.point(vertex);
  const glm::vec3 relative = infinite ? point : point - destination.position;
  const float distance = glm::length(relative);
  if (!(distance > 1e-6f)) return projected;
  projected.inverseDistance = infinite ? 0.0f : 1.0f / distance;
  projected.relative = glm::dvec3(relative);
  if (destination.kind == DestinationCamera::Kind::Equirect) {
    projected.screen = destination.equirect.imagePoint(relative);
    projected.valid = true;
  } else {
    const glm::vec3 camera = destination.pinhole.toCameraFrame(glm::vec4(point, infinite ? 0.0f : 1.0f));
    const float near = infinite ? 1e-4f : kPinholeNearPlane;
    if (!(camera.z > near)) return projected;
    projected.screen = destination.pinhole.imagePoint(camera);
    projected.depth = camera.z;
    projected.valid = true;
  }
  return projected;
}

// Which pixel centres a triangle covers, with the weights that interpolate
// its vertex attributes there and the inverse distance of the surface.
struct Coverage {
  double weights[3];
  float inverseDistance;
};

// An unwrapped column (at most a turn beyond the panorama's) as a column
// of a panorama `width` columns wide.
int wrappedColumn(int column, int width) {
  return column < 0 ? column + width : column >= width ? column - width : column;
}

// Per-column and per-row factors of the destination's pixel directions.
struct DirectionTable {
  std::vector<double> cosTheta, sinTheta, cosPhi, sinPhi;
  std::vector<double> tanLatitude;  // |tan| of the latitude k rows from a pole, k <= H / 2
  int width;
  double yaw;
  explicit DirectionTable(const EquirectProjection& projection) : width(projection.width), yaw(projection.yaw) {
    for (int u = 0; u < projection.width; ++u) {
      const glm::vec3 d = projection.pixelDirection(u, projection.height / 2);
      const double theta = std::atan2(double(d.y), double(d.x));
      cosTheta.push_back(std::cos(theta));
      sinTheta.push_back(std::sin(theta));
    }
    for (int v = 0; v < projection.height; ++v) {
      const double phi = 0.5 * std::numbers::pi - std::numbers::pi * (v + 0.5) / projection.height;
      cosPhi.push_back(std::cos(phi));
      sinPhi.push_back(std::sin(phi));
    }
    for (int k = 0; k <= projection.height / 2; ++k) {
      tanLatitude.push_back(k == 0 ? 1e30 : 1.0 / std::tan(std::numbers::pi * k / projection.height));
    }
  }
  glm::dvec3 at(int u, int v) const { return {cosPhi[size_t(v)] * cosTheta[size_t(u)], cosPhi[size_t(v)] * sinTheta[size_t(u)], sinPhi[size_t(v)]}; }
  // The (fractional) column whose centre looks at longitude theta, up to whole turns.
  double columnAt(double theta) const {
    return (theta + std::numbers::pi - yaw) * width / (2.0 * std::numbers::pi) - 0.5;
  }
};

// Panorama destinations: exact coverage on the sphere. A pixel's ray
// direction w lies in the triangle's cone when the three triple products
// det(r_i+1, r_i+2, w) share the sign of det(r0, r1, r2); normalized, they
// are the barycentric weights of the ray's hit on the triangle's plane
// (perspective-correct), and t = det(r0, r1, r2) / sum is its distance.
// No seam or pole is special: a triangle across the seam covers columns
// on both sides, one around a pole covers whole rows. Neighbours share
// edges exactly (swapping the two vertices negates the cross product), so
// there are no cracks.
class SphericalTriangle {
public:
  SphericalTriangle(const ProjectedVertex* v[3], bool atInfinity) : atInfinity_(atInfinity) {
    for (int i = 0; i < 3; ++i) normals_[i] = glm::cross(v[(i + 1) % 3]->relative, v[(i + 2) % 3]->relative);
    volume_ = glm::dot(v[0]->relative, normals_[0]);
  }

  bool degenerate() const { return volume_ == 0.0; }

  // The normal of edge i's plane on the triangle's side: covers() needs
  // dot(inwardNormal(i), direction) >= 0 for all three.
  glm::dvec3 inwardNormal(int i) const { return volume_ > 0.0 ? normals_[i] : -normals_[i]; }

  bool covers(glm::dvec3 direction, Coverage& coverage) const {
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
      coverage.weights[i] = glm::dot(normals_[i], direction);
      if (coverage.weights[i] * volume_ < 0.0) return false;
      sum += coverage.weights[i];
    }
    if (!(sum * volume_ > 0.0)) return false;
    for (double& w : coverage.weights) w /= sum;
    coverage.inverseDistance = atInfinity_ ? 0.0f : float(sum / volume_);
    return true;
  }

  // The raster's inner loop: row y's columns first..last (unwrapped: a
  // whole turn beyond the panorama's, every stride-th), calling
  // hit(x, inverseDistance) at each pixel centre covers() accepts. The
  // same products and sums as covers() at directions.at(x, y), in the
  // same order, so the same pixels and bits; what is constant along the
  // row (its factors, the three z terms) is read and multiplied once, not
  // again after every z-buffer update, which the compiler must assume
  // could change it.
  template <class Hit>
  void scanRow(const DirectionTable& directions, int y, int first, int last, int stride, Hit&& hit) const {
    const double cosPhi = directions.cosPhi[size_t(y)], sinPhi = directions.sinPhi[size_t(y)];
    const double* cosTheta = directions.cosTheta.data();
    const double* sinTheta = directions.sinTheta.data();
    const int width = directions.width;
    const double volume = volume_;
    double nx[3], ny[3], zTerm[3];
    for (int i = 0; i < 3; ++i) nx[i] = normals_[i].x, ny[i] = normals_[i].y, zTerm[i] = normals_[i].z * sinPhi;
    for (int column = first; column <= last; column += stride) {
      const int x = wrappedColumn(column, width);
      const double dx = cosPhi * cosTheta[x], dy = cosPhi * sinTheta[x];
      const double w0 = nx[0] * dx + ny[0] * dy + zTerm[0];
      if (w0 * volume < 0.0) continue;
      const double w1 = nx[1] * dx + ny[1] * dy + zTerm[1];
      if (w1 * volume < 0.0) continue;
      const double w2 = nx[2] * dx + ny[2] * dy + zTerm[2];
      if (w2 * volume < 0.0) continue;
      double sum = 0.0;
      sum += w0;
      sum += w1;
      sum += w2;
      if (!(sum * volume > 0.0)) continue;
      hit(x, atInfinity_ ? 0.0f : float(sum / volume));
    }
  }

private:
  glm::dvec3 normals_[3];
  double volume_ = 0.0;
  bool atInfinity_;
};

// The candidate pixels of a spherical triangle: its rows and columns from
// the vertices' image points, whole rows when it contains a pole, columns
// across the seam when it straddles it (iterated modulo the width).
struct PixelRange {
  int x0, x1, y0, y1;
};

// floor and ceil as ints without a library call, for the bounded image
// coordinates of a panorama (exact wherever the int can hold the result).
int floorToInt(double x) {
  const int truncated = int(x);
  return truncated - int(x < double(truncated));
}

int ceilToInt(double x) {
  const int truncated = int(x);
  return truncated + int(x > double(truncated));
}

PixelRange sphericalRange(const ProjectedVertex* v[3], bool atInfinity, const DirectionTable& directions, int width,
                          int height) {
  double minY = 1e30, maxY = -1e30;
  for (int i = 0; i < 3; ++i) {
    minY = std::min(minY, double(v[i]->screen.y));
    maxY = std::max(maxY, double(v[i]->screen.y));
  }
  // Longitudes unwrapped along the edges: an edge is an arc shorter than
  // half a turn, so it takes the shorter way round unless it passes over a
  // pole; then the steps add up to a whole turn instead of none. This holds
  // for triangles of any size, not only the grid's pixel-sized ones.
  const auto shortestStep = [width](double from, double to) {
    // fmod is the identity below the width (and exact), the common case.
    const double difference = to - from;
    const double step = std::abs(difference) < double(width) ? difference : std::fmod(difference, double(width));
    return step >= 0.5 * width ? step - width : step < -0.5 * width ? step + width : step;
  };
  double xs[3] = {v[0]->screen.x, 0.0, 0.0};
  for (int i = 1; i < 3; ++i) xs[i] = xs[i - 1] + shortestStep(xs[i - 1], v[i]->screen.x);
  const bool turnsAround = std::abs(xs[2] + shortestStep(xs[2], xs[0]) - xs[0]) > 0.5 * width;
  double minX = std::min({xs[0], xs[1], xs[2]}), maxX = std::max({xs[0], xs[1], xs[2]});
  // Great-circle edges bulge towards the poles between their vertices:
  // an edge spanning dtheta of longitude at latitude phi bulges by about
  // dtheta^2 / 8 * tan(phi). Only where twice that could reach the next
  // row of pixel centres beyond the vertices (or near a pole) do the rows
  // come from each edge's exact extreme latitude; a margin of 1/100 pixel
  // covers the image points' rounding.
  const double pi = std::numbers::pi;
  const int rowsFromPole = int(std::min(minY, height - maxY));
  const double longitudeSpan = (maxX - minX) * 2.0 * pi / width;
  const double bulgeRows = longitudeSpan * longitudeSpan / 4.0 *
                           directions.tanLatitude[size_t(std::clamp(rowsFromPole, 0, height / 2))] * height / pi;
  const double slackAbove = minY - (double(floorToInt(minY - 0.5)) + 0.5);  // to the row centre above the vertices
  const double slackBelow = (double(ceilToInt(maxY - 0.5)) + 0.5) - maxY;   // to the row centre below them
  if (rowsFromPole < 2 || bulgeRows >= std::min(slackAbove, slackBelow) - 0.01) {
    for (int i = 0; i < 3; ++i) {
      const glm::dvec3 a = glm::normalize(v[i]->relative), b = glm::normalize(v[(i + 1) % 3]->relative);
      const glm::dvec3 normal = glm::cross(a, b);
      const double length = glm::length(normal);
      if (length < 1e-12) continue;
      const glm::dvec3 n = normal / length;
      for (const double pole : {1.0, -1.0}) {
        // The point of the edge's great circle nearest the pole, if it lies on the edge.
        const glm::dvec3 toward = glm::dvec3(0.0, 0.0, pole) - pole * n.z * n;
        if (glm::length(toward) < 1e-12) continue;
        const glm::dvec3 p = glm::normalize(toward);
        if (glm::dot(glm::cross(a, p), n) < 0.0 || glm::dot(glm::cross(p, b), n) < 0.0) continue;
        const double y = (0.5 * pi - std::asin(std::clamp(p.z, -1.0, 1.0))) * height / pi;
        minY = std::min(minY, y);
        maxY = std::max(maxY, y);
      }
    }
  }
  const double margin = 0.01;
  // Only a triangle whose edges turn around, or whose vertices spread over
  // more than half the longitudes, can contain a pole.
  if (turnsAround || maxX - minX > 0.5 * width) {
    const SphericalTriangle triangle(v, atInfinity);
    Coverage ignored;
    const bool north = triangle.covers({0.0, 0.0, 1.0}, ignored);
    const bool south = triangle.covers({0.0, 0.0, -1.0}, ignored);
    if (north) minY = 0.0;
    if (south) maxY = height;
    if (north || south) minX = 0.0, maxX = width;
  }
  PixelRange range;
  range.x0 = ceilToInt(minX - 0.5 - margin);
  range.x1 = floorToInt(maxX - 0.5 + margin);
  if (range.x1 - range.x0 >= width) range.x0 = 0, range.x1 = width - 1;
  range.y0 = std::max(0, ceilToInt(minY - 0.5 - margin));
  range.y1 = std::min(height - 1, floorToInt(maxY - 0.5 + margin));
  return range;
}

// Panorama destinations: the columns of a row a spherical triangle can
// cover. On the row of latitude phi, edge i admits the directions w with
// dot(n, w) >= 0 (n its inward normal): R cos(theta - alpha) + c >= 0 with
// R = cos(phi) |n_xy|, alpha the longitude of n_xy and c = sin(phi) n_z,
// which is one arc of longitudes, none or all. A row's span is the
// intersection of the three arcs with the triangle's range, widened by a
// column on each side (far beyond any rounding), so the exact test still
// decides every pixel and the layer is the one a scan of the whole range
// gives. Worth its three arc cosines a row only for wide triangles: a
// simplified mesh's walls and floors span tens of columns and cover a few
// percent of their range (docs/history/BENCHMARKS-2026-11.md).
class RowSpans {
public:
  RowSpans(const SphericalTriangle& triangle, const DirectionTable& directions, const PixelRange& range)
      : directions_(directions), range_(range) {
    const double middle = 0.5 * (range.x0 + range.x1), width = directions.width;
    for (int i = 0; i < 3; ++i) {
      const glm::dvec3 n = triangle.inwardNormal(i);
      Edge& edge = edges_[i];
      edge.horizontal = std::hypot(n.x, n.y);
      edge.vertical = n.z;
      edge.tolerance = 1e-9 * glm::length(n);
      edge.centre = directions.columnAt(std::atan2(n.y, n.x));
      edge.centre += width * std::round((middle - edge.centre) / width);
    }
  }

  // The columns of row y (unwrapped, within the range) left to test, or
  // false when no edge-admitted pixel centre is left in the row.
  bool span(int y, int& first, int& last) const {
    const double width = directions_.width, columnsPerRadian = width / (2.0 * std::numbers::pi);
    double low = range_.x0, high = range_.x1;
    for (const Edge& edge : edges_) {
      const double r = directions_.cosPhi[size_t(y)] * edge.horizontal;
      const double c = directions_.sinPhi[size_t(y)] * edge.vertical;
      if (c >= r) continue;                       // admits every longitude
      if (-c > r + edge.tolerance) return false;  // admits none: dot(n, w) <= r + c < 0
      if (r <= edge.tolerance) continue;          // too close to call: no narrowing
      const double half = std::acos(std::clamp(-c / r, -1.0, 1.0)) * columnsPerRadian + 1.0;
      if (half >= 0.5 * width) continue;
      // The arc's copies a turn apart that meet [low, high]; their hull.
      double newLow = high + 1.0, newHigh = low - 1.0;
      for (const double turn : {-width, 0.0, width}) {
        const double from = std::max(low, edge.centre + turn - half), to = std::min(high, edge.centre + turn + half);
        if (from > to) continue;
        newLow = std::min(newLow, from);
        newHigh = std::max(newHigh, to);
      }
      if (newLow > newHigh) return false;
      low = newLow, high = newHigh;
    }
    first = ceilToInt(low);
    last = floorToInt(high);
    return first <= last;
  }

private:
  struct Edge {
    double horizontal, vertical;  // |n_xy| and n_z
    double tolerance;             // below which a value of dot(n, w) is rounding
    double centre;                // column of alpha, the nearest copy to the range
  };
  const DirectionTable& directions_;
  PixelRange range_;
  Edge edges_[3];
};

// Triangles at least this many columns wide get row spans; narrower ones
// test their few columns directly.
constexpr int kRowSpanMinimumColumns = 32;

// Pinhole destinations: edge functions in the image plane, computed the
// same way whichever way an edge is directed so that neighbours agree
// exactly on which side a pixel centre lies (no cracks); attributes are
// interpolated perspective-correctly, as the GPU does.
double edgeFunction(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  const bool swapped = b.x < a.x || (b.x == a.x && b.y < a.y);
  const glm::dvec2 from = swapped ? b : a, to = swapped ? a : b;
  const double value = (to.x - from.x) * (p.y - from.y) - (to.y - from.y) * (p.x - from.x);
  return swapped ? -value : value;
}

class PlanarTriangle {
public:
  explicit PlanarTriangle(const ProjectedVertex* v[3]) : vertices_(v) {
    for (int i = 0; i < 3; ++i) screen_[i] = glm::dvec2(v[i]->screen);
    area_ = edgeFunction(screen_[0], screen_[1], screen_[2]);
  }

  bool degenerate() const { return area_ == 0.0; }

  PixelRange range(int width, int height) const {
    const double minX = std::min({screen_[0].x, screen_[1].x, screen_[2].x});
    const double maxX = std::max({screen_[0].x, screen_[1].x, screen_[2].x});
    const double minY = std::min({screen_[0].y, screen_[1].y, screen_[2].y});
    const double maxY = std::max({screen_[0].y, screen_[1].y, screen_[2].y});
    return {std::max(0, int(std::ceil(minX - 0.5))), std::min(width - 1, int(std::floor(maxX - 0.5))),
            std::max(0, int(std::ceil(minY - 0.5))), std::min(height - 1, int(std::floor(maxY - 0.5)))};
  }

  bool covers(int x, int y, Coverage& coverage) const {
    const glm::dvec2 p(x + 0.5, y + 0.5);
    const double e[3] = {edgeFunction(screen_[1], screen_[2], p), edgeFunction(screen_[2], screen_[0], p),
                         edgeFunction(screen_[0], screen_[1], p)};
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
      if (e[i] * area_ < 0.0) return false;
      coverage.weights[i] = e[i] / area_ / double(vertices_[i]->depth);
      sum += coverage.weights[i];
    }
    for (double& w : coverage.weights) w /= sum;
    // The distance of the interpolated point, exact on the triangle's
    // plane; interpolated 1 / distance is not, and across a simplified
    // triangle metres wide it was off by several percent, more than the
    // blend interval (as the GPU's layers, shaders/warp_layer.glsl).
    coverage.inverseDistance = 0.0f;
    if (vertices_[0]->inverseDistance > 0.0f) {
      glm::dvec3 point(0.0);
      for (int i = 0; i < 3; ++i) point += coverage.weights[i] * vertices_[i]->relative;
      coverage.inverseDistance = float(1.0 / glm::length(point));
    }
    return true;
  }

private:
  const ProjectedVertex* const* vertices_;
  glm::dvec2 screen_[3];
  double area_ = 0.0;
};

uint64_t makeKey(float distance, uint32_t payload) {
  return (uint64_t(std::bit_cast<uint32_t>(distance)) << 32) | payload;
}

void atomicMin(uint64_t& slot, uint64_t key) {
  std::atomic_ref<uint64_t> atomicSlot(slot);
  uint64_t current = atomicSlot.load(std::memory_order_relaxed);
  while (key < current && !atomicSlot.compare_exchange_weak(current, key, std::memory_order_relaxed)) {
  }
}

float distanceFromInverse(float inverseDistance) {
  return inverseDistance > 0.0f ? 1.0f / inverseDistance : std::numeric_limits<float>::infinity();
}

// The z-buffer of a destination's lattice (every pixel but for a
// panorama lattice): pixel (x, y) of the destination, if on the lattice,
// is entry (y / stride, x / stride). Strides are powers of two, so the
// raster's inner loop shifts instead of dividing.
class LatticeBuffer {
public:
  explicit LatticeBuffer(const DestinationCamera& destination)
      : shift_(std::countr_zero(unsigned(destination.stride))), mask_(destination.stride - 1),
        width_(destination.layerWidth()),
        keys_(size_t(destination.layerWidth()) * size_t(destination.layerHeight()), kEmpty) {
    TRIWALK_CHECK(std::has_single_bit(unsigned(destination.stride)), "a lattice's stride must be a power of two");
  }
  bool onLattice(int x, int y) const { return ((x | y) & mask_) == 0; }
  uint64_t& at(int x, int y) { return keys_[size_t(y >> shift_) * size_t(width_) + size_t(x >> shift_)]; }
  // The first lattice row or column at or after `from`, which may be
  // negative (an unwrapped column): two's complement rounds it up too.
  int firstOnLattice(int from) const { return (from + mask_) & ~mask_; }
  int stride() const { return mask_ + 1; }

private:
  int shift_, mask_, width_;
  std::vector<uint64_t> keys_;
};

// Splats a vertex into the destination pixel its position falls in.
void splatPoint(const ProjectedVertex& p, uint32_t vertex, int width, int height, bool wrap, LatticeBuffer& zBuffer) {
  if (!p.valid) return;
  int x = int(std::floor(p.screen.x)), y = int(std::floor(p.screen.y));
  if (wrap) x = wrappedColumn(x, width);  // screen x lies in [0, width]
  if (x < 0 || y < 0 || x >= width || y >= height || !zBuffer.onLattice(x, y)) return;
  atomicMin(zBuffer.at(x, y), makeKey(distanceFromInverse(p.inverseDistance), (vertex << 2) | kPointPayload));
}

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

WarpLayer warpToCamera(const WarpSource& source, const DestinationCamera& destination, WarpMethod method,
                       LayerReliability reliability, PanoramaRaster raster) {
  WarpTimings timings;
  auto stageStart = Clock::now();
  const int width = destination.width(), height = destination.height();
  const bool equirect = destination.kind == DestinationCamera::Kind::Equirect;
  TRIWALK_CHECK(equirect || source.mesh() == SourceMesh::Grid, "a simplified source warps to panoramas only");
  TRIWALK_CHECK(equirect || destination.stride == 1, "only a panorama warps on a lattice");
  const uint32_t vertexCount = source.vertexCount();
  std::vector<ProjectedVertex> projected(vertexCount);
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, vertexCount, 4096), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t v = r.begin(); v != r.end(); ++v) projected[v] = projectVertex(source, v, destination);
  });
  const std::unique_ptr<DirectionTable> directions =
      equirect ? std::make_unique<DirectionTable>(destination.equirect) : nullptr;
  timings.projectSeconds = secondsSince(stageStart);
  stageStart = Clock::now();

  LatticeBuffer zBuffer(destination);
  const int stride = zBuffer.stride();
  std::atomic<uint64_t> rasterized{0}, tested{0};
  const uint32_t pointCount = source.pixelVertexCount();

  // Points: every pixel in the point warp; in the mesh warp, orphans
  // compete with the triangles and the other vertices only fill gaps.
  std::optional<LatticeBuffer> gapBuffer;
  if (method == WarpMethod::Mesh) gapBuffer.emplace(destination);
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, pointCount, 4096), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t v = r.begin(); v != r.end(); ++v) {
      const bool competes = method == WarpMethod::Point || source.orphan(v);
      splatPoint(projected[v], v, width, height, equirect, competes ? zBuffer : *gapBuffer);
    }
  });

  if (method == WarpMethod::Mesh) {
    const uint32_t triangleCount = source.triangleCount();
    TRIWALK_CHECK(triangleCount < (1u << 30), "source too large for the z-buffer payload");
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, triangleCount, 2048), [&](const tbb::blocked_range<uint32_t>& r) {
      uint64_t localRasterized = 0, localTested = 0;
      for (uint32_t t = r.begin(); t != r.end(); ++t) {
        if (!source.triangleKept(t)) continue;
        uint32_t indices[3];
        source.triangleVertices(t, indices);
        const ProjectedVertex* v[3] = {&projected[indices[0]], &projected[indices[1]], &projected[indices[2]]};
        if (!v[0]->valid || !v[1]->valid || !v[2]->valid) continue;
        ++localRasterized;
        const uint32_t payload = t << 2;
        Coverage coverage;
        if (equirect) {
          // Most triangles are about a pixel large: those whose range holds
          // no pixel centre are dropped before the exact test is set up.
          const PixelRange range = sphericalRange(v, source.atInfinity(indices[0]), *directions, width, height);
          if (range.x0 > range.x1 || range.y0 > range.y1) continue;
          const SphericalTriangle triangle(v, source.atInfinity(indices[0]));
          if (triangle.degenerate()) continue;
          // Columns are unwrapped, a whole turn (a multiple of the stride) apart.
          const auto scanRow = [&](int y, int first, int last) {
            first = zBuffer.firstOnLattice(first);
            if (first <= last) localTested += uint64_t((last - first) / stride + 1);
            const auto hit = [&](int x, float inverseDistance) {
              atomicMin(zBuffer.at(x, y), makeKey(distanceFromInverse(inverseDistance), payload));
            };
            if (raster == PanoramaRaster::RowSpans) {
              triangle.scanRow(*directions, y, first, last, stride, hit);
              return;
            }
            // The plain scan tests each pixel with covers() itself: the
            // reference the row loop is checked against, bit for bit.
            for (int column = first; column <= last; column += stride) {
              const int x = wrappedColumn(column, width);
              if (triangle.covers(directions->at(x, y), coverage)) hit(x, coverage.inverseDistance);
            }
          };
          const int firstRow = zBuffer.firstOnLattice(range.y0);
          if (raster == PanoramaRaster::RowSpans && range.x1 - range.x0 + 1 >= kRowSpanMinimumColumns) {
            const RowSpans spans(triangle, *directions, range);
            for (int y = firstRow; y <= range.y1; y += stride) {
              int first, last;
              if (spans.span(y, first, last)) scanRow(y, first, last);
            }
          } else {
            for (int y = firstRow; y <= range.y1; y += stride) scanRow(y, range.x0, range.x1);
          }
        } else {
          const PlanarTriangle triangle(v);
          if (triangle.degenerate()) continue;
          const PixelRange range = triangle.range(width, height);
          localTested +=
              uint64_t(std::max(0, range.x1 - range.x0 + 1)) * uint64_t(std::max(0, range.y1 - range.y0 + 1));
          for (int y = range.y0; y <= range.y1; ++y) {
            for (int x = range.x0; x <= range.x1; ++x) {
              if (!triangle.covers(x, y, coverage)) continue;
              atomicMin(zBuffer.at(x, y), makeKey(distanceFromInverse(coverage.inverseDistance), payload));
            }
          }
        }
      }
      rasterized += localRasterized;
      tested += localTested;
    });
  }
  timings.rasterSeconds = secondsSince(stageStart);
  stageStart = Clock::now();

  // Resolve: interpolate the winner's attributes at each pixel centre of the lattice.
  const int layerWidth = destination.layerWidth(), layerHeight = destination.layerHeight();
  const size_t layerPixels = size_t(layerWidth) * size_t(layerHeight);
  WarpLayer layer{
      ColorImage(layerWidth, layerHeight),
      ScalarImage(layerWidth, layerHeight, std::numeric_limits<float>::infinity()),
      std::vector<uint8_t>(layerPixels, 0),
      rasterized.load(),
      tested.load(),
      WarpTimings{},
      std::vector<float>(reliability == LayerReliability::Computed ? layerPixels : 0, 1.0f)};
  tbb::parallel_for(tbb::blocked_range<int>(0, layerHeight), [&](const tbb::blocked_range<int>& rows) {
    // A simplified source's colours are looked up along the rays to the
    // covered points, a row's at once (the projections run four at a time).
    std::vector<glm::vec3> rays;
    std::vector<size_t> rayPixels;
    std::vector<glm::vec2> rayImagePoints;
    std::vector<glm::vec3> rayColors;
    // Neighbouring pixels mostly share their winner: its spherical
    // triangle is set up once for the run of them.
    std::optional<SphericalTriangle> winner;
    uint32_t winnerPayload = kPointPayload;  // no triangle's payload
    for (int row = rows.begin(); row != rows.end(); ++row) {
      rays.clear();
      rayPixels.clear();
      const int y = row * stride;
      for (int x = 0; x < width; x += stride) {
        const size_t i = size_t(row) * size_t(layerWidth) + size_t(x / stride);
        const uint64_t key =
            zBuffer.at(x, y) != kEmpty || !gapBuffer ? zBuffer.at(x, y) : gapBuffer->at(x, y);
        if (key == kEmpty) continue;
        const uint32_t payload = uint32_t(key & 0xFFFFFFFFu);
        layer.covered[i] = 1;
        layer.distance.pixels[i] = std::bit_cast<float>(uint32_t(key >> 32));
        if ((payload & 3u) == kPointPayload) {
          layer.color.pixels[i] = source.color(payload >> 2);
          if (reliability == LayerReliability::Computed) {
            layer.reliability[i] = fringeReliability(1.0f, source.fringe(payload >> 2));
          }
          continue;
        }
        uint32_t indices[3];
        source.triangleVertices(payload >> 2, indices);
        const ProjectedVertex* v[3] = {&projected[indices[0]], &projected[indices[1]], &projected[indices[2]]};
        Coverage coverage;
        // The same arithmetic as in rasterization, so the winner covers the centre.
        if (equirect && payload != winnerPayload) {
          winner.emplace(v, source.atInfinity(indices[0]));
          winnerPayload = payload;
        }
        const bool covered = equirect ? winner->covers(directions->at(x, y), coverage) : PlanarTriangle(v).covers(x, y, coverage);
        TRIWALK_CHECK(covered, "z-buffer winner does not cover its pixel");
        const glm::vec3 a = source.point(indices[0]), b = source.point(indices[1]), c = source.point(indices[2]);
        // The covered point (a direction at infinity).
        const glm::vec3 point =
            float(coverage.weights[0]) * a + float(coverage.weights[1]) * b + float(coverage.weights[2]) * c;
        const bool atInfinity = source.atInfinity(indices[0]);
        if (source.mesh() == SourceMesh::Simplified) {
          rays.push_back(atInfinity ? point : point - source.position());
          rayPixels.push_back(i);
        } else {
          glm::vec3 color(0.0f);
          for (int k = 0; k < 3; ++k) color += float(coverage.weights[k]) * source.color(indices[k]);
          layer.color.pixels[i] = color;
        }
        if (reliability == LayerReliability::Computed) {
          const float stretched =
              atInfinity ? 1.0f
                         : warpReliability(point, glm::cross(b - a, c - a), source.position(), destination.position);
          // A simplified source's fringe is looked up along the ray with its colour, below.
          float fringe = 0.0f;
          if (source.mesh() == SourceMesh::Grid) {
            for (int k = 0; k < 3; ++k) fringe += float(coverage.weights[k]) * source.fringe(indices[k]);
          }
          layer.reliability[i] = fringeReliability(stretched, fringe);
        }
      }
      rayImagePoints.resize(rays.size());
      rayColors.resize(rays.size());
      source.colorsAlong(rays, rayImagePoints, rayColors);
      for (size_t k = 0; k < rays.size(); ++k) {
        layer.color.pixels[rayPixels[k]] = rayColors[k];
        if (reliability == LayerReliability::Computed) {
          float& trust = layer.reliability[rayPixels[k]];
          trust = fringeReliability(trust, source.fringeAt(rayImagePoints[k]));
        }
      }
    }
  });
  timings.resolveSeconds = secondsSince(stageStart);
  layer.timings = timings;
  return layer;
}

}  // namespace triwalk
