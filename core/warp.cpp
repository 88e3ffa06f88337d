#include "core/warp.h"

#include "core/errors.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>

namespace triwalk {

StretchTest parseStretchTest(const std::string& name) {
  if (name == "none") return StretchTest::None;
  if (name == "grazing-angle") return StretchTest::GrazingAngle;
  if (name == "depth-ratio") return StretchTest::DepthRatio;
  throw InputError("--stretch-test", "unknown stretch test '" + name + "' (use grazing-angle, depth-ratio or none)");
}

const char* stretchTestName(StretchTest test) {
  switch (test) {
    case StretchTest::None: return "none";
    case StretchTest::GrazingAngle: return "grazing-angle";
    case StretchTest::DepthRatio: return "depth-ratio";
  }
  return "?";
}

// ---------------------------------------------------------------- source --

void WarpSource::triangleVertices(uint32_t triangle, uint32_t vertices[3]) const {
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

WarpSource::WarpSource(const Panorama& panorama, glm::vec3 position, float yawRadians, const WarpOptions& options)
    : width_(panorama.width()), height_(panorama.height()), position_(position) {
  TRIWALK_CHECK(width_ >= 2 && height_ >= 2, "panorama too small to warp");
  const EquirectProjection projection{width_, height_, yawRadians};
  const size_t pixels = size_t(width_) * size_t(height_);
  points_.resize(pixels + 2);
  infinite_.resize(pixels + 2);
  colors_.resize(pixels + 2);
  tbb::parallel_for(tbb::blocked_range<int>(0, height_), [&](const tbb::blocked_range<int>& rows) {
    for (int v = rows.begin(); v != rows.end(); ++v) {
      for (int u = 0; u < width_; ++u) {
        const size_t i = size_t(v) * size_t(width_) + size_t(u);
        const glm::vec3 direction = projection.pixelDirection(u, v);
        const float d = panorama.distance.pixels[i];
        infinite_[i] = std::isinf(d);
        points_[i] = std::isinf(d) ? direction : position + d * direction;
        colors_[i] = panorama.color.pixels[i];
      }
    }
  });

  // Pole vertices close the caps above the first and below the last row:
  // the mean of that row's points and colors, at infinity if any is.
  for (int pole = 0; pole < 2; ++pole) {
    const int row = pole == 0 ? 0 : height_ - 1;
    const size_t first = size_t(row) * size_t(width_);
    bool anyInfinite = false;
    double distanceSum = 0.0;
    glm::dvec3 colorSum(0.0);
    for (int u = 0; u < width_; ++u) {
      anyInfinite |= infinite_[first + size_t(u)] != 0;
      distanceSum += anyInfinite ? 0.0 : double(panorama.distance.pixels[first + size_t(u)]);
      colorSum += glm::dvec3(colors_[first + size_t(u)]);
    }
    const glm::vec3 up(0.0f, 0.0f, pole == 0 ? 1.0f : -1.0f);
    const size_t vertex = pixels + size_t(pole);
    infinite_[vertex] = anyInfinite;
    points_[vertex] = anyInfinite ? up : position + float(distanceSum / width_) * up;
    colors_[vertex] = glm::vec3(colorSum / double(width_));
  }

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
}

DestinationCamera DestinationCamera::panorama(glm::vec3 position, int width, int height, float yawRadians) {
  DestinationCamera camera;
  camera.kind = Kind::Equirect;
  camera.position = position;
  camera.equirect = {width, height, yawRadians};
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

constexpr uint64_t kEmpty = std::numeric_limits<uint64_t>::max();
constexpr float kPinholeNear = 0.01f;  // metres

// A source vertex as the destination sees it.
struct ProjectedVertex {
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
  if (destination.kind == DestinationCamera::Kind::Equirect) {
    projected.screen = destination.equirect.imagePoint(relative);
    projected.valid = true;
  } else {
    const glm::vec3 camera = destination.pinhole.toCameraFrame(glm::vec4(point, infinite ? 0.0f : 1.0f));
    const float near = infinite ? 1e-4f : kPinholeNear;
    if (!(camera.z > near)) return projected;
    projected.screen = destination.pinhole.imagePoint(camera);
    projected.depth = camera.z;
    projected.valid = true;
  }
  return projected;
}

// Edge function of p against the directed edge a -> b, computed the same
// way whichever way the edge is directed, so that triangles sharing an
// edge agree exactly on which side a pixel centre lies (no cracks).
double edgeFunction(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  const bool swapped = b.x < a.x || (b.x == a.x && b.y < a.y);
  const glm::dvec2 from = swapped ? b : a, to = swapped ? a : b;
  const double value = (to.x - from.x) * (p.y - from.y) - (to.y - from.y) * (p.x - from.x);
  return swapped ? -value : value;
}

// Screen positions of a triangle's copy: copy 0 as projected, copies 1
// and 2 for a triangle crossing the equirectangular seam (vertices on the
// left moved right by W, then copy 2 moved left by W).
void copyScreens(const ProjectedVertex* vertex[3], int copy, int width, glm::dvec2 screen[3]) {
  for (int i = 0; i < 3; ++i) screen[i] = glm::dvec2(vertex[i]->screen);
  if (copy == 0) return;
  for (int i = 0; i < 3; ++i) {
    if (screen[i].x < 0.5 * width) screen[i].x += width;
    if (copy == 2) screen[i].x -= width;
  }
}

struct Barycentric {
  double weights[3];
};

bool barycentricAt(const glm::dvec2 screen[3], glm::dvec2 p, Barycentric& result) {
  const double area = edgeFunction(screen[0], screen[1], screen[2]);
  if (area == 0.0) return false;
  const double w0 = edgeFunction(screen[1], screen[2], p);
  const double w1 = edgeFunction(screen[2], screen[0], p);
  const double w2 = edgeFunction(screen[0], screen[1], p);
  if (area > 0.0 ? (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) : (w0 > 0.0 || w1 > 0.0 || w2 > 0.0)) return false;
  result.weights[0] = w0 / area;
  result.weights[1] = w1 / area;
  result.weights[2] = w2 / area;
  return true;
}

// Interpolated 1 / distance: screen-linear for panoramas,
// perspective-correct for pinhole cameras (as the GPU interpolates).
struct Interpolator {
  bool perspective;
  double weights[3];
  Interpolator(const Barycentric& b, const ProjectedVertex* v[3], bool isPerspective) : perspective(isPerspective) {
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
      weights[i] = perspective ? b.weights[i] / double(v[i]->depth) : b.weights[i];
      sum += weights[i];
    }
    for (double& w : weights) w /= sum;
  }
  template <typename T>
  T operator()(T a, T b, T c) const {
    return T(a * float(weights[0]) + b * float(weights[1]) + c * float(weights[2]));
  }
};

// Z-buffer payload: (triangle << 2) | copy for triangles (copy 0..2, see
// copyScreens), (vertex << 2) | 3 for a splatted point.
constexpr uint32_t kPointPayload = 3;

// Splats a vertex into the destination pixel its position falls in.

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

void splatPoint(const ProjectedVertex& p, uint32_t vertex, int width, int height, bool wrap, std::vector<uint64_t>& zBuffer) {
  if (!p.valid) return;
  int x = int(std::floor(p.screen.x)), y = int(std::floor(p.screen.y));
  if (wrap) x = (x % width + width) % width;
  if (x < 0 || y < 0 || x >= width || y >= height) return;
  atomicMin(zBuffer[size_t(y) * size_t(width) + size_t(x)],
            makeKey(distanceFromInverse(p.inverseDistance), (vertex << 2) | kPointPayload));
}

}  // namespace

WarpLayer warpToCamera(const WarpSource& source, const DestinationCamera& destination, WarpMethod method) {
  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); };
  WarpTimings timings;
  auto stageStart = Clock::now();
  const int width = destination.width(), height = destination.height();
  const bool equirect = destination.kind == DestinationCamera::Kind::Equirect;
  const uint32_t vertexCount = uint32_t(source.width()) * uint32_t(source.height()) + 2;
  std::vector<ProjectedVertex> projected(vertexCount);
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, vertexCount, 4096), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t v = r.begin(); v != r.end(); ++v) projected[v] = projectVertex(source, v, destination);
  });

  timings.projectSeconds = since(stageStart);
  stageStart = Clock::now();
  std::vector<uint64_t> zBuffer(size_t(width) * size_t(height), kEmpty);
  std::atomic<uint64_t> rasterized{0};
  const uint32_t pointCount = vertexCount - 2;

  // Points: every pixel in the point warp; in the mesh warp, orphans
  // compete with the triangles and the other vertices only fill gaps.
  std::vector<uint64_t> gapBuffer(method == WarpMethod::Mesh ? zBuffer.size() : 0, kEmpty);
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, pointCount, 4096), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t v = r.begin(); v != r.end(); ++v) {
      const bool competes = method == WarpMethod::Point || source.orphan(v);
      splatPoint(projected[v], v, width, height, equirect, competes ? zBuffer : gapBuffer);
    }
  });
  if (method == WarpMethod::Mesh) {
    const uint32_t triangleCount = source.triangleCount();
    TRIWALK_CHECK(triangleCount < (1u << 30), "source too large for the z-buffer payload");
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, triangleCount, 2048), [&](const tbb::blocked_range<uint32_t>& r) {
      uint64_t localRasterized = 0;
      for (uint32_t t = r.begin(); t != r.end(); ++t) {
        if (!source.triangleKept(t)) continue;
        uint32_t indices[3];
        source.triangleVertices(t, indices);
        const ProjectedVertex* v[3] = {&projected[indices[0]], &projected[indices[1]], &projected[indices[2]]};
        if (!v[0]->valid || !v[1]->valid || !v[2]->valid) continue;
        int firstCopy = 0, lastCopy = 0;
        if (equirect) {
          const float minX = std::min({v[0]->screen.x, v[1]->screen.x, v[2]->screen.x});
          const float maxX = std::max({v[0]->screen.x, v[1]->screen.x, v[2]->screen.x});
          if (maxX - minX > 0.5f * float(width)) {
            // Crosses the seam: split into two copies. One still wider
            // than half the panorama surrounds the destination's pole.
            glm::dvec2 moved[3];
            copyScreens(v, 1, width, moved);
            const double span = std::max({moved[0].x, moved[1].x, moved[2].x}) - std::min({moved[0].x, moved[1].x, moved[2].x});
            if (span > 0.5 * width) continue;
            firstCopy = 1, lastCopy = 2;
          }
        }
        ++localRasterized;
        for (int copy = firstCopy; copy <= lastCopy; ++copy) {
          glm::dvec2 screen[3];
          copyScreens(v, copy, width, screen);
          const double minX = std::min({screen[0].x, screen[1].x, screen[2].x});
          const double maxX = std::max({screen[0].x, screen[1].x, screen[2].x});
          const double minY = std::min({screen[0].y, screen[1].y, screen[2].y});
          const double maxY = std::max({screen[0].y, screen[1].y, screen[2].y});
          const int x0 = std::max(0, int(std::ceil(minX - 0.5))), x1 = std::min(width - 1, int(std::floor(maxX - 0.5)));
          const int y0 = std::max(0, int(std::ceil(minY - 0.5))), y1 = std::min(height - 1, int(std::floor(maxY - 0.5)));
          for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
              Barycentric b;
              if (!barycentricAt(screen, {x + 0.5, y + 0.5}, b)) continue;
              const Interpolator interpolate(b, v, !equirect);
              const float inverseDistance = interpolate(v[0]->inverseDistance, v[1]->inverseDistance, v[2]->inverseDistance);
              atomicMin(zBuffer[size_t(y) * size_t(width) + size_t(x)],
                        makeKey(distanceFromInverse(inverseDistance), (t << 2) | uint32_t(copy)));
            }
          }
        }
      }
      rasterized += localRasterized;
    });
  }

  timings.rasterSeconds = since(stageStart);
  stageStart = Clock::now();
  // Resolve: interpolate the winner's attributes at each pixel centre.
  WarpLayer layer{ColorImage(width, height), ScalarImage(width, height, std::numeric_limits<float>::infinity()),
                  std::vector<uint8_t>(size_t(width) * size_t(height), 0), rasterized.load(), WarpTimings{}};
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y) {
      for (int x = 0; x < width; ++x) {
        const size_t i = size_t(y) * size_t(width) + size_t(x);
        const uint64_t key = zBuffer[i] != kEmpty || gapBuffer.empty() ? zBuffer[i] : gapBuffer[i];
        if (key == kEmpty) continue;
        const uint32_t payload = uint32_t(key & 0xFFFFFFFFu);
        layer.covered[i] = 1;
        layer.distance.pixels[i] = std::bit_cast<float>(uint32_t(key >> 32));
        if ((payload & 3u) == kPointPayload) {
          layer.color.pixels[i] = source.color(payload >> 2);
          continue;
        }
        uint32_t indices[3];
        source.triangleVertices(payload >> 2, indices);
        const ProjectedVertex* v[3] = {&projected[indices[0]], &projected[indices[1]], &projected[indices[2]]};
        glm::dvec2 screen[3];
        copyScreens(v, int(payload & 3u), width, screen);
        Barycentric b;
        // The same arithmetic as in rasterization, so the winner contains the centre.
        const bool inside = barycentricAt(screen, {x + 0.5, y + 0.5}, b);
        TRIWALK_CHECK(inside, "z-buffer winner does not cover its pixel");
        const Interpolator interpolate(b, v, !equirect);
        layer.color.pixels[i] = interpolate(source.color(indices[0]), source.color(indices[1]), source.color(indices[2]));
      }
    }
  });
  timings.resolveSeconds = since(stageStart);
  layer.timings = timings;
  return layer;
}

}  // namespace triwalk
