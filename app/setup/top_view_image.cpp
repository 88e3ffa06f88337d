#include "app/setup/top_view_image.h"

#include "core/image/image_annotation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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

std::string counted(size_t count, const std::string& noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

// A band below the view that says what each mark is, with its count, and
// a scale bar of a round length.
Rgb8Image withLegend(const Canvas& canvas, const Dataset& dataset, const ViewMesh& mesh, double dot) {
  const Rgb8Image& view = canvas.image;
  const int scale = std::max(1, view.width / 500);
  const int line = textHeight(scale), gap = 4 * scale;
  struct Entry {
    std::string label;
    glm::u8vec3 color;
    double radius;  // 0: a line (the triangles' edges), -1: a swatch (the region)
  };
  const std::vector<Entry> entries = {
      {"walkable region", glm::u8vec3(215), -1.0},
      {counted(size_t(mesh.vertexCount()), "reference"), glm::u8vec3(0), 1.4 * dot},
      {counted(mesh.triangles().size(), "view triangle"), glm::u8vec3(40, 90, 200), 0.0},
      {counted(size_t(dataset.sampleCount()), "sample"), glm::u8vec3(120), 0.6 * dot},
      {counted(size_t(dataset.probeCount()), "probe"), glm::u8vec3(220, 30, 30), dot},
  };
  // Entries wrap onto as many rows as the width needs.
  std::vector<std::pair<glm::ivec2, const Entry*>> placed;
  int x = gap, row = 0;
  for (const Entry& entry : entries) {
    const int width = line + gap + textWidth(entry.label, scale) + 3 * gap;
    if (x > gap && x + width > view.width) x = gap, ++row;
    placed.push_back({{x, row}, &entry});
    x += width;
  }
  // A scale bar of 1, 2 or 5 times a power of ten metres, about a fifth of the width.
  const double target = 0.2 * view.width / canvas.pixelsPerMetre;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  const double metres = target >= 5 * decade ? 5 * decade : target >= 2 * decade ? 2 * decade : decade;
  char scaleLabel[32];
  std::snprintf(scaleLabel, sizeof scaleLabel, "%g m", metres);
  const int rows = row + 2;
  Rgb8Image result(view.width, view.height + rows * (line + gap) + gap, glm::u8vec3(255));
  for (int y = 0; y < view.height; ++y) {
    for (int column = 0; column < view.width; ++column) result.at(column, y) = view.at(column, y);
  }
  for (const auto& [at, entry] : placed) {
    const int top = view.height + gap + at.y * (line + gap);
    const glm::ivec2 centre(at.x + line / 2, top + line / 2 - scale);
    for (int dy = -line / 2; dy < line / 2; ++dy) {
      for (int dx = -line / 2; dx < line / 2; ++dx) {
        const double r = std::hypot(dx + 0.5, dy + 0.5);
        const bool mark = entry->radius < 0.0 ? std::max(std::abs(dx), std::abs(dy)) < line / 2 - scale
                          : entry->radius == 0.0 ? std::abs(dy) < std::max(1, scale / 2 + 1)
                                                 : r <= std::max(entry->radius, 1.5);
        if (mark) result.at(centre.x + dx, centre.y + dy) = entry->color;
      }
    }
    drawText(result, {at.x + line + gap, top}, entry->label, glm::u8vec3(0), scale);
  }
  const int barTop = view.height + gap + (rows - 1) * (line + gap);
  const int barLength = int(std::lround(metres * canvas.pixelsPerMetre));
  for (int y = barTop + line / 2 - scale; y < barTop + line / 2 + scale; ++y) {
    for (int column = gap; column < gap + barLength && column < view.width; ++column) result.at(column, y) = glm::u8vec3(0);
  }
  drawText(result, {gap + barLength + gap, barTop}, scaleLabel, glm::u8vec3(0), scale);
  return result;
}

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
  return withLegend(canvas, dataset, mesh, dot);
}

}  // namespace triwalk
