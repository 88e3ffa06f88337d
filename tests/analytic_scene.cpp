#include "tests/analytic_scene.h"

#include "core/projection.h"

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

Panorama renderPanorama(const AnalyticScene& scene, glm::vec3 position, int width) {
  const EquirectProjection projection{width, width / 2, 0.0f};
  Panorama panorama{ColorImage(width, width / 2), ScalarImage(width, width / 2)};
  for (int v = 0; v < projection.height; ++v) {
    for (int u = 0; u < width; ++u) {
      const AnalyticHit hit = scene.trace(position, projection.pixelDirection(u, v));
      panorama.color.at(u, v) = hit.color;
      panorama.distance.at(u, v) = hit.distance;
    }
  }
  return panorama;
}

}  // namespace triwalk::testing

#include "core/dataset.h"
#include "core/exr_io.h"

namespace triwalk::testing {

void writeAnalyticDataset(const std::filesystem::path& directory, int paths, int steps, int width, int probes) {
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
  for (int path = 0; path < paths; ++path) {
    for (int step = 0; step < steps; ++step) {
      ViewRecord sample;
      sample.id = int(manifest.samples.size());
      sample.file = "samples/s" + std::to_string(sample.id) + ".exr";
      sample.position = {4.0f * float(path) / float(paths - 1), 2.0f * float(step) / float(steps - 1), 1.5f};
      sample.path = path;
      sample.step = step;
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
