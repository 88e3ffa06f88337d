#include "core/import/panorama_orientation.h"

#include "core/geometry/projection.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace triwalk {

namespace {

glm::vec3 bilinearColor(const ColorImage& image, glm::vec2 point) {
  // Pixel centres sit at +0.5; columns wrap around, rows clamp at the poles.
  const float x = point.x - 0.5f, y = std::clamp(point.y - 0.5f, 0.0f, float(image.height - 1));
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const float fx = x - float(x0), fy = y - float(y0);
  const int y1 = std::min(y0 + 1, image.height - 1);
  const auto column = [&](int c) { return ((c % image.width) + image.width) % image.width; };
  const int c0 = column(x0), c1 = column(x0 + 1);
  const glm::vec3 top = glm::mix(image.at(c0, y0), image.at(c1, y0), fx);
  const glm::vec3 bottom = glm::mix(image.at(c0, y1), image.at(c1, y1), fx);
  return glm::mix(top, bottom, fy);
}

}  // namespace

Panorama uprightPanorama(const Panorama& cameraPanorama, const glm::dmat3& cameraToWorld, float yaw) {
  const int width = cameraPanorama.width(), height = cameraPanorama.height();
  const EquirectProjection upright{width, height, yaw};
  const EquirectProjection camera{width, height, 0.0f};
  const glm::mat3 worldToCamera(glm::transpose(cameraToWorld));
  Panorama result{ColorImage(width, height), ScalarImage(width, height)};
  tbb::parallel_for(0, height, [&](int v) {
    for (int u = 0; u < width; ++u) {
      const glm::vec2 source = camera.imagePoint(worldToCamera * upright.pixelDirection(u, v));
      result.color.at(u, v) = bilinearColor(cameraPanorama.color, source);
      const int nearestX = std::min(int(source.x), width - 1);
      const int nearestY = std::clamp(int(source.y), 0, height - 1);
      result.distance.at(u, v) = cameraPanorama.distance.at(nearestX, nearestY);
    }
  });
  return result;
}

double negligibleTiltRadians(int panoramaWidth) {
  return 0.25 * 2.0 * std::numbers::pi / double(panoramaWidth);
}

}  // namespace triwalk
