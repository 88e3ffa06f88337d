#include "core/geometry/cell_region.h"

#include "core/support/errors.h"

#include <algorithm>
#include <limits>
#include <map>

namespace triwalk {

namespace {

double twiceArea(const Ring& ring) {
  double twice = 0.0;
  for (size_t i = 0; i < ring.size(); ++i) twice += ring[i].x * ring[(i + 1) % ring.size()].y - ring[(i + 1) % ring.size()].x * ring[i].y;
  return twice;
}

// Crossing-number test for a point that is on no edge of the ring (rings
// of one cell grid never touch each other).
bool encloses(const Ring& ring, glm::dvec2 p) {
  bool inside = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const glm::dvec2 a = ring[j], b = ring[i];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

}  // namespace

CellGrid::CellGrid(glm::dvec2 lowerCorner, double size, int columnCount, int rowCount)
    : origin(lowerCorner), cellSize(size), columns(columnCount), rows(rowCount),
      marked(size_t(columnCount) * size_t(rowCount), 0) {}

int CellGrid::count() const { return int(std::count(marked.begin(), marked.end(), uint8_t(1))); }

int removeCornerContacts(CellGrid& grid) {
  const auto markedNeighbours = [&](int x, int y) {
    return int(grid.at(x - 1, y)) + int(grid.at(x + 1, y)) + int(grid.at(x, y - 1)) + int(grid.at(x, y + 1));
  };
  int removed = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (int y = 0; y + 1 < grid.rows; ++y) {
      for (int x = 0; x + 1 < grid.columns; ++x) {
        const bool a = grid.at(x, y), b = grid.at(x + 1, y), c = grid.at(x, y + 1), d = grid.at(x + 1, y + 1);
        glm::ivec2 first, second;
        if (a && d && !b && !c) {
          first = {x, y}, second = {x + 1, y + 1};
        } else if (b && c && !a && !d) {
          first = {x + 1, y}, second = {x, y + 1};
        } else {
          continue;
        }
        // Row-major order: the lower row comes first.
        if (second.y < first.y || (second.y == first.y && second.x < first.x)) std::swap(first, second);
        const glm::ivec2 drop = markedNeighbours(second.x, second.y) < markedNeighbours(first.x, first.y) ? second : first;
        grid.set(drop.x, drop.y, false);
        ++removed;
        changed = true;
      }
    }
  }
  return removed;
}

std::vector<int> connectedParts(const CellGrid& grid, int& partCount) {
  std::vector<int> labels(grid.marked.size(), -1);
  partCount = 0;
  std::vector<glm::ivec2> stack;
  for (int y = 0; y < grid.rows; ++y) {
    for (int x = 0; x < grid.columns; ++x) {
      if (!grid.at(x, y) || labels[size_t(y) * size_t(grid.columns) + size_t(x)] >= 0) continue;
      const int label = partCount++;
      labels[size_t(y) * size_t(grid.columns) + size_t(x)] = label;
      stack.push_back({x, y});
      while (!stack.empty()) {
        const glm::ivec2 cell = stack.back();
        stack.pop_back();
        for (const glm::ivec2 step : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
          const glm::ivec2 next = cell + step;
          if (!grid.at(next.x, next.y)) continue;
          int& nextLabel = labels[size_t(next.y) * size_t(grid.columns) + size_t(next.x)];
          if (nextLabel >= 0) continue;
          nextLabel = label;
          stack.push_back(next);
        }
      }
    }
  }
  return labels;
}

WalkableRegion regionFromCells(const CellGrid& grid, const std::string& subject) {
  // Directed boundary edges with the region on their left: each marked
  // cell contributes the sides it shares with unmarked cells, walked
  // counter-clockwise around it. Without corner contacts every grid
  // corner starts at most one such edge, so the edges chain into rings.
  const int stride = grid.columns + 1;
  const auto corner = [&](int x, int y) { return y * stride + x; };
  std::map<int, int> next;  // corner -> the corner its boundary edge leads to
  for (int y = 0; y < grid.rows; ++y) {
    for (int x = 0; x < grid.columns; ++x) {
      if (!grid.at(x, y)) continue;
      if (!grid.at(x, y - 1)) next[corner(x, y)] = corner(x + 1, y);
      if (!grid.at(x + 1, y)) next[corner(x + 1, y)] = corner(x + 1, y + 1);
      if (!grid.at(x, y + 1)) next[corner(x + 1, y + 1)] = corner(x, y + 1);
      if (!grid.at(x - 1, y)) next[corner(x, y + 1)] = corner(x, y);
    }
  }
  TRIWALK_CHECK(!next.empty(), "a region needs marked cells");
  const auto point = [&](int c) { return grid.origin + glm::dvec2(c % stride, c / stride) * grid.cellSize; };

  std::vector<Ring> outers, holes;
  while (!next.empty()) {
    const int start = next.begin()->first;
    std::vector<int> corners;
    for (int c = start;;) {
      corners.push_back(c);
      const auto edge = next.find(c);
      TRIWALK_CHECK(edge != next.end(), "cell boundary does not close (corner contact left)");
      c = edge->second;
      next.erase(edge);
      if (c == start) break;
    }
    // Keep only the corners where the boundary turns.
    Ring ring;
    const size_t n = corners.size();
    for (size_t i = 0; i < n; ++i) {
      const glm::ivec2 previous(corners[(i + n - 1) % n] % stride, corners[(i + n - 1) % n] / stride);
      const glm::ivec2 here(corners[i] % stride, corners[i] / stride);
      const glm::ivec2 following(corners[(i + 1) % n] % stride, corners[(i + 1) % n] / stride);
      if (here - previous != following - here) ring.push_back(point(corners[i]));
    }
    (twiceArea(ring) > 0.0 ? outers : holes).push_back(std::move(ring));
  }

  std::vector<RegionPolygon> polygons;
  for (Ring& outer : outers) polygons.push_back({std::move(outer), {}});
  // A hole belongs to the smallest outer ring around it (an island inside
  // a hole has its own outer ring, inside the larger one).
  for (Ring& hole : holes) {
    int owner = -1;
    double ownerArea = std::numeric_limits<double>::max();
    for (size_t p = 0; p < polygons.size(); ++p) {
      const double area = twiceArea(polygons[p].outer);
      if (encloses(polygons[p].outer, hole.front()) && area < ownerArea) owner = int(p), ownerArea = area;
    }
    TRIWALK_CHECK(owner >= 0, "a hole of the cell region lies in no outer ring");
    polygons[size_t(owner)].holes.push_back(std::move(hole));
  }
  return WalkableRegion(std::move(polygons), subject);
}

}  // namespace triwalk
