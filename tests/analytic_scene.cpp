#include "tests/analytic_scene.h"

#include "core/geometry/projection.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace triwalk::testing {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Entry and exit distances of a ray through a box (slab method).
bool slab(glm::vec3 origin, glm::vec3 direction, glm::vec3 lower, glm::vec3 upper, float& entry, float& exit,
          int& entryAxis, int& exitAxis) {
  entry = -kInfinity;
  exit = kInfinity;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(direction[axis]) < 1e-12f) {
      if (origin[axis] < lower[axis] || origin[axis] > upper[axis]) return false;
      continue;
    }
    float t0 = (lower[axis] - origin[axis]) / direction[axis];
    float t1 = (upper[axis] - origin[axis]) / direction[axis];
    int face0 = 2 * axis, face1 = 2 * axis + 1;
    if (t0 > t1) {
      std::swap(t0, t1);
      std::swap(face0, face1);
    }
    if (t0 > entry) entry = t0, entryAxis = face0;
    if (t1 < exit) exit = t1, exitAxis = face1;
  }
  return entry <= exit;
}

}  // namespace

glm::vec3 smoothPattern(glm::vec3 p, int surface) {
  const float s = float(surface % 7) * 0.9f;
  return glm::vec3(0.5f + 0.35f * std::sin(1.3f * p.x + 0.7f * p.y + s), 0.5f + 0.35f * std::sin(1.1f * p.y - 0.9f * p.z + 2.0f * s),
                   0.5f + 0.35f * std::cos(0.8f * p.z + 1.2f * p.x - s));
}

AnalyticHit AnalyticScene::trace(glm::vec3 origin, glm::vec3 direction) const {
  AnalyticHit hit;
  hit.distance = kInfinity;
  if (room) {
    float entry, exit;
    int entryFace = -1, exitFace = -1;
    if (slab(origin, direction, room->lower, room->upper, entry, exit, entryFace, exitFace) && exit > 0.0f) {
      const bool throughOpenTop = room->openTop && exitFace == 5;
      if (!throughOpenTop) hit = {exit, {}, exitFace};
    }
  }
  for (size_t i = 0; i < boxes.size(); ++i) {
    float entry, exit;
    int entryFace = -1, exitFace = -1;
    if (slab(origin, direction, boxes[i].first, boxes[i].second, entry, exit, entryFace, exitFace) && entry > 0.0f &&
        entry < hit.distance) {
      hit = {entry, {}, 100 + int(i)};
    }
  }
  for (size_t i = 0; i < cylinders.size(); ++i) {
    const Cylinder& c = cylinders[i];
    const glm::vec2 o = glm::vec2(origin) - c.center, d(direction);
    const float a = glm::dot(d, d), b = 2.0f * glm::dot(o, d), cc = glm::dot(o, o) - c.radius * c.radius;
    const float discriminant = b * b - 4.0f * a * cc;
    if (a < 1e-12f || discriminant < 0.0f) continue;
    const float t = (-b - std::sqrt(discriminant)) / (2.0f * a);
    const float z = origin.z + t * direction.z;
    if (t > 0.0f && t < hit.distance && z >= c.bottom && z <= c.top) hit = {t, {}, 200 + int(i)};
  }
  const glm::vec3 point = origin + hit.distance * direction;
  hit.color = hit.surface < 0 ? skyColor : (shade ? shade(point, hit.surface) : smoothPattern(point, hit.surface));
  return hit;
}

Panorama renderPanorama(const AnalyticScene& scene, glm::vec3 position, int width, int colorSamplesPerSide) {
  const EquirectProjection projection{width, width / 2, 0.0f};
  Panorama panorama{ColorImage(width, width / 2), ScalarImage(width, width / 2)};
  const int n = std::max(1, colorSamplesPerSide);
  for (int v = 0; v < projection.height; ++v) {
    for (int u = 0; u < width; ++u) {
      const AnalyticHit hit = scene.trace(position, projection.pixelDirection(u, v));
      panorama.distance.at(u, v) = hit.distance;
      if (n == 1) {
        panorama.color.at(u, v) = hit.color;
        continue;
      }
      glm::vec3 sum(0.0f);
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          const glm::vec2 inside((float(i) + 0.5f) / float(n), (float(j) + 0.5f) / float(n));
          sum += scene.trace(position, projection.direction(glm::vec2(float(u), float(v)) + inside)).color;
        }
      }
      panorama.color.at(u, v) = sum / float(n * n);
    }
  }
  return panorama;
}

}  // namespace triwalk::testing

#include "core/io/dataset.h"
#include "core/io/exr_io.h"

#include <algorithm>
#include <random>
#include <stdexcept>

namespace triwalk::testing {

namespace {

void writeDataset(const std::filesystem::path& directory, const AnalyticScene& scene, const std::string& name,
                  std::vector<ViewRecord> samples, std::vector<ViewRecord> probes, int width) {
  std::filesystem::create_directories(directory / "samples");
  std::filesystem::create_directories(directory / "probes");
  Manifest manifest;
  manifest.scene = name;
  manifest.width = width;
  manifest.height = width / 2;
  manifest.samples = std::move(samples);
  manifest.probes = std::move(probes);
  for (const auto* views : {&manifest.samples, &manifest.probes}) {
    for (const ViewRecord& view : *views) writePanoramaExr(directory / view.file, renderPanorama(scene, view.position, width));
  }
  writeManifest(directory, manifest);
}

}  // namespace

AnalyticScene stripedRoom() {
  AnalyticScene scene;
  scene.room = AnalyticScene::Room{{-5.0f, -5.0f, 0.0f}, {5.0f, 5.0f, 3.0f}, false};
  scene.shade = [](glm::vec3 point, int surface) {
    const float along = surface < 2 ? point.y : point.x;  // walls x = const run along y, the others along x
    const float stripe = 0.5f + 0.35f * std::sin(12.0f * along + 3.0f * point.z);
    return glm::vec3(stripe, 0.3f + 0.1f * float(surface % 3), 1.0f - stripe);
  };
  return scene;
}

void writeWallAndClutterDataset(const std::filesystem::path& directory, int paths, int steps, int width, int probes) {
  AnalyticScene scene;
  scene.room = AnalyticScene::Room{{-1.0f, -1.0f, 0.0f}, {9.0f, 4.0f, 2.6f}, false};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 2; ++j) {
      scene.cylinders.push_back({{5.07f + 1.065f * float(i), 0.9f + 1.2f * float(j)}, 0.15f, 0.0f, 2.6f});
    }
  }
  scene.boxes.push_back({{5.45f, 1.35f, 0.0f}, {5.75f, 1.65f, 1.1f}});
  scene.boxes.push_back({{6.8f, 0.1f, 0.0f}, {7.2f, 0.4f, 0.8f}});
  scene.boxes.push_back({{7.6f, 1.35f, 0.0f}, {7.85f, 1.65f, 1.3f}});
  scene.shade = [](glm::vec3 point, int surface) {
    if (point.x < 4.0f) return glm::vec3(0.55f, 0.5f, 0.45f);  // plain
    // Sharp stripes: any misregistration shows.
    const float stripes = std::sin(9.0f * (point.x + point.y + point.z) + float(surface));
    return stripes > 0.0f ? glm::vec3(0.9f, 0.85f, 0.2f) : glm::vec3(0.1f, 0.15f, 0.5f);
  };
  auto insideObstacle = [&](glm::vec3 position, float margin) {
    const bool pillar = std::any_of(scene.cylinders.begin(), scene.cylinders.end(), [&](const AnalyticScene::Cylinder& c) {
      return glm::length(glm::vec2(position) - c.center) < c.radius + margin;
    });
    const bool box = std::any_of(scene.boxes.begin(), scene.boxes.end(), [&](const auto& b) {
      return position.x > b.first.x - margin && position.x < b.second.x + margin && position.y > b.first.y - margin &&
             position.y < b.second.y + margin;
    });
    return pillar || box;
  };
  std::vector<ViewRecord> samples, probeViews;
  for (int path = 0; path < paths; ++path) {
    for (int step = 0; step < steps; ++step) {
      ViewRecord sample;
      sample.id = int(samples.size());
      sample.file = "samples/s" + std::to_string(sample.id) + ".exr";
      sample.position = {8.0f * float(path) / float(paths - 1), 3.0f * float(step) / float(steps - 1), 1.5f};
      sample.path = path;
      sample.step = step;
      if (insideObstacle(sample.position, 0.1f)) throw std::runtime_error("wall-and-clutter: a sample falls inside an obstacle");
      samples.push_back(sample);
    }
  }
  std::mt19937 engine(7);
  auto unit = [&] { return float(engine() >> 8) * (1.0f / 16777216.0f); };
  while (int(probeViews.size()) < probes) {
    const glm::vec3 position(8.0f * unit(), 3.0f * unit(), 1.5f);
    if (insideObstacle(position, 0.05f)) continue;
    ViewRecord probe;
    probe.id = int(probeViews.size());
    probe.file = "probes/p" + std::to_string(probe.id) + ".exr";
    probe.position = position;
    probeViews.push_back(probe);
  }
  writeDataset(directory, scene, "wall-and-clutter", std::move(samples), std::move(probeViews), width);
}

void writeAnalyticDataset(const std::filesystem::path& directory, int paths, int steps, int width, int probes,
                          float jitter) {
  AnalyticScene scene;
  scene.room = AnalyticScene::Room{{-2.0f, -2.0f, 0.0f}, {6.0f, 4.0f, 2.8f}, false};
  scene.cylinders.push_back({{1.5f, 2.6f}, 0.25f, 0.0f, 2.8f});
  scene.boxes.push_back({{3.0f, -1.5f, 0.0f}, {3.8f, -0.9f, 2.0f}});
  scene.boxes.push_back({{0.4f, 0.6f, 0.0f}, {0.9f, 1.1f, 0.7f}});
  std::filesystem::create_directories(directory / "samples");
  std::filesystem::create_directories(directory / "probes");
  Manifest manifest;
  manifest.scene = "analytic-room";
  manifest.width = width;
  manifest.height = width / 2;
  // Paths along y over x in [0, 4], steps over y in [0, 2].
  const glm::vec2 spacing(4.0f / float(paths - 1), 2.0f / float(steps - 1));
  std::mt19937 engine(7);
  const auto offset = [&] { return jitter * (float(engine() >> 8) / 16777216.0f - 0.5f) * 2.0f; };
  for (int path = 0; path < paths; ++path) {
    for (int step = 0; step < steps; ++step) {
      ViewRecord sample;
      sample.id = int(manifest.samples.size());
      sample.file = "samples/s" + std::to_string(sample.id) + ".exr";
      sample.position = {spacing.x * float(path), spacing.y * float(step), 1.5f};
      sample.path = path;
      sample.step = step;
      if (jitter > 0.0f) {
        sample.position.x += offset() * spacing.x;
        sample.position.y += offset() * spacing.y;
        sample.path = sample.step = -1;
      }
      manifest.samples.push_back(sample);
    }
  }
  for (int p = 0; p < probes; ++p) {
    ViewRecord probe;
    probe.id = p;
    probe.file = "probes/p" + std::to_string(p) + ".exr";
    // Fixed, irregular positions inside the sampled rectangle.
    probe.position = {0.3f + std::fmod(1.37f * float(p + 1), 3.4f), 0.2f + std::fmod(0.71f * float(p + 1), 1.6f), 1.5f};
    manifest.probes.push_back(probe);
  }
  for (const auto* views : {&manifest.samples, &manifest.probes}) {
    for (const ViewRecord& view : *views) writePanoramaExr(directory / view.file, renderPanorama(scene, view.position, width));
  }
  writeManifest(directory, manifest);
}

}  // namespace triwalk::testing
