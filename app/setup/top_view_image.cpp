#include "app/setup/top_view_image.h"

#include <algorithm>
#include <cmath>

namespace triwalk {

namespace {

struct Canvas {
  Rgb8Image image;
  glm::dvec2 lower{0.0};
  double pixelsPerMetre = 1.0;

  glm::dvec2 toPixel(glm::dvec2 p) const {
    return {(p.x - lower.x) * pixelsPerMetre, double(image.height) - (p.y - lower.y) * pixelsPerMetre};
  }
  void plot(int x, int y, glm::u8vec3 color) {
    if (x >= 0 && y >= 0 && x < image.width && y < image.height) image.at(x, y) = color;
  }
  void disc(glm::dvec2 centre, double radius, glm::u8vec3 color) {
    const glm::dvec2 c = toPixel(centre);
    for (int y = int(c.y - radius) - 1; y <= int(c.y + radius) + 1; ++y) {
      for (int x = int(c.x - radius) - 1; x <= int(c.x + radius) + 1; ++x) {
        if (glm::length(glm::dvec2(x + 0.5, y + 0.5) - c) <= radius) plot(x, y, color);
      }
    }
  }
  void line(glm::dvec2 from, glm::dvec2 to, glm::u8vec3 color) {
    const glm::dvec2 a = toPixel(from), b = toPixel(to);
    const int steps = std::max(1, int(std::ceil(glm::length(b - a))));
    for (int i = 0; i <= steps; ++i) {
      const glm::dvec2 p = a + (b - a) * (double(i) / steps);
      plot(int(std::floor(p.x)), int(std::floor(p.y)), color);
    }
  }
  // Even-odd scanline fill over every ring: holes stay white.
  void fillRegion(const WalkableRegion& region, glm::u8vec3 color) {
    for (int y = 0; y < image.height; ++y) {
      const double worldY = lower.y + (double(image.height - y) - 0.5) / pixelsPerMetre;
      std::vector<double> crossings;
      for (const RegionPolygon& polygon : region.polygons()) {
        std::vector<const Ring*> rings{&polygon.outer};
        for (const Ring& hole : polygon.holes) rings.push_back(&hole);
        for (const Ring* ring : rings) {
          for (size_t i = 0; i < ring->size(); ++i) {
            const glm::dvec2 a = (*ring)[i], b = (*ring)[(i + 1) % ring->size()];
            if ((a.y > worldY) != (b.y > worldY)) crossings.push_back(a.x + (worldY - a.y) * (b.x - a.x) / (b.y - a.y));
          }
        }
      }
      std::sort(crossings.begin(), crossings.end());
      for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
        const int first = int(std::ceil((crossings[k] - lower.x) * pixelsPerMetre - 0.5));
        const int last = int(std::floor((crossings[k + 1] - lower.x) * pixelsPerMetre - 0.5));
        for (int x = first; x <= last; ++x) plot(x, y, color);
      }
    }
  }
};

}  // namespace

Rgb8Image topViewImage(const Dataset& dataset, const ViewMesh& mesh, int longSide) {
  const WalkableRegion region = dataset.walkableRegion();
  glm::dvec2 lower, upper;
  region.bounds(lower, upper);
  for (const ViewRecord& view : dataset.manifest().samples) {
    lower = glm::min(lower, glm::dvec2(view.position)), upper = glm::max(upper, glm::dvec2(view.position));
  }
  const double margin = 0.03 * std::max(upper.x - lower.x, upper.y - lower.y) + 1e-6;
  lower -= margin, upper += margin;
  Canvas canvas;
  canvas.lower = lower;
  canvas.pixelsPerMetre = double(longSide) / std::max(upper.x - lower.x, upper.y - lower.y);
  canvas.image = Rgb8Image(std::max(1, int(std::ceil((upper.x - lower.x) * canvas.pixelsPerMetre))),
                           std::max(1, int(std::ceil((upper.y - lower.y) * canvas.pixelsPerMetre))), glm::u8vec3(255));
  canvas.fillRegion(region, glm::u8vec3(215));
  for (const RegionPolygon& polygon : region.polygons()) {
    std::vector<const Ring*> rings{&polygon.outer};
    for (const Ring& hole : polygon.holes) rings.push_back(&hole);
    for (const Ring* ring : rings) {
      for (size_t i = 0; i < ring->size(); ++i) canvas.line((*ring)[i], (*ring)[(i + 1) % ring->size()], glm::u8vec3(60));
    }
  }
  for (const Triangle& t : mesh.triangles()) {
    for (int e = 0; e < 3; ++e) canvas.line(mesh.position(t[size_t(e)]), mesh.position(t[size_t((e + 1) % 3)]), {40, 90, 200});
  }
  const double dot = std::max(1.5, 0.004 * longSide);
  for (const ViewRecord& view : dataset.manifest().samples) canvas.disc(glm::dvec2(view.position), 0.6 * dot, {120, 120, 120});
  for (int v : mesh.vertices()) canvas.disc(mesh.position(v), 1.4 * dot, {0, 0, 0});
  for (const ViewRecord& view : dataset.manifest().probes) canvas.disc(glm::dvec2(view.position), dot, {220, 30, 30});
  return canvas.image;
}

}  // namespace triwalk
