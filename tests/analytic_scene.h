#pragma once
// Scenes whose panoramas are computed exactly by ray casting, for tests
// with known answers: an axis-aligned room seen from inside, solid boxes,
// vertical cylinders (pillars), an open top (sky). Surface colors are
// smooth functions of the hit point (so interpolation errors stay small)
// except where a test asks for a sharp stripe.

#include "core/image/image.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

namespace triwalk::testing {

struct AnalyticHit {
  float distance = 0.0f;  // +inf for sky
  glm::vec3 color{0.0f};  // linear
  int surface = -1;       // index of what was hit: 0..5 room walls, 100+i boxes, 200+i cylinders, -1 sky
};

struct AnalyticScene {
  struct Room {
    glm::vec3 lower, upper;
    bool openTop = false;  // no ceiling: the sky shows above
  };
  struct Cylinder {
    glm::vec2 center;
    float radius, bottom, top;
  };
  std::optional<Room> room;
  std::vector<std::pair<glm::vec3, glm::vec3>> boxes;  // solid boxes (min, max)
  std::vector<Cylinder> cylinders;
  // Color of a surface point; default: smooth pattern distinct per surface.
  std::function<glm::vec3(glm::vec3 point, int surface)> shade;
  glm::vec3 skyColor{0.4f, 0.6f, 0.9f};

  AnalyticHit trace(glm::vec3 origin, glm::vec3 direction) const;
};

// Smooth per-surface pattern in [0.15, 0.85].
glm::vec3 smoothPattern(glm::vec3 point, int surface);

// Each pixel's colour and distance along its centre ray; with
// colorSamplesPerSide n > 1 the colour is the mean of n x n rays spread
// evenly over the pixel while the distance stays the centre ray's, as a
// capture's anti-aliased colour is (shaders/capture_equirect.frag): pixels
// on a silhouette mix two surfaces' colours at one surface's distance.
Panorama renderPanorama(const AnalyticScene& scene, glm::vec3 position, int width, int colorSamplesPerSide = 1);

}  // namespace triwalk::testing

namespace triwalk::testing {

// A 10 x 10 x 3 m room centred on the origin whose walls carry fine
// sinusoidal stripes: a reference that saw a wall obliquely sampled them
// coarsely, one that saw it face-on did not.
AnalyticScene stripedRoom();

// A room with a pillar and boxes, captured on a grid of paths x steps
// (analytic rendering) plus probes, written as a data set in directory.
// With jitter > 0 the samples leave the grid: each moves by up to jitter x
// the grid's spacing (seeded), and the manifest knows no paths.
void writeAnalyticDataset(const std::filesystem::path& directory, int paths, int steps, int width, int probes,
                          float jitter = 0.0f);

// A long room whose half x < 4 m is bare with plain walls (any view
// reconstructs it well) and whose half x > 4 m is cluttered with striped
// pillars and boxes (disocclusions and parallax everywhere). Samples on a
// grid of paths x steps over x in [0, 8], y in [0, 3]; probes at seeded
// random positions in the same rectangle.
void writeWallAndClutterDataset(const std::filesystem::path& directory, int paths, int steps, int width, int probes);

}  // namespace triwalk::testing
