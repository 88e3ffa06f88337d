#pragma once
// A walkable region from a grid of square cells on the floor plane (the
// automatic search's probe grid): the union of the marked cells' squares,
// traced into polygons with holes.

#include "core/geometry/walkable_region.h"

#include <cstdint>
#include <string>
#include <vector>

namespace triwalk {

struct CellGrid {
  glm::dvec2 origin{0.0};  // lower corner of cell (0, 0), metres
  double cellSize = 1.0;   // metres
  int columns = 0;
  int rows = 0;
  std::vector<uint8_t> marked;  // row-major, 1 = inside

  CellGrid() = default;
  CellGrid(glm::dvec2 lowerCorner, double size, int columnCount, int rowCount);
  bool at(int x, int y) const {
    return x >= 0 && y >= 0 && x < columns && y < rows && marked[size_t(y) * size_t(columns) + size_t(x)];
  }
  void set(int x, int y, bool value) { marked[size_t(y) * size_t(columns) + size_t(x)] = value; }
  glm::dvec2 centre(int x, int y) const { return origin + (glm::dvec2(x, y) + 0.5) * cellSize; }
  int count() const;
};

// Unmarks cells until no two marked cells meet only at a corner (a 2 x 2
// block marked like a chessboard), where the traced boundary would touch
// itself, which a WalkableRegion may not. Of the two, the cell with fewer
// marked 4-neighbours goes (the first in row-major order on a tie), so a
// one-cell diagonal chain is cut rather than a room trimmed. Returns how
// many went.
int removeCornerContacts(CellGrid& grid);

// The 4-connected parts of the marked cells, as labels 0.. per cell (-1
// unmarked), numbered in row-major order of their first cell.
std::vector<int> connectedParts(const CellGrid& grid, int& partCount);

// The union of the marked cells' squares: counter-clockwise outer rings
// with clockwise holes, straight runs of cell edges merged into one edge.
// Needs marked cells and no corner contacts (removeCornerContacts).
WalkableRegion regionFromCells(const CellGrid& grid, const std::string& subject);

}  // namespace triwalk
