#pragma once
// The walkthrough space: a region of any shape on the floor plane (x, y in
// metres), the union of polygons with holes (rooms joined through
// doorways, corridors, holes around pillars). Stored in a manifest, or
// given by the user, as
//   "walkable": {"polygons": [{"outer": [[x, y], ...], "holes": [[[x, y], ...], ...]}, ...]}
// with counter-clockwise outer rings and clockwise holes (either order is
// accepted on reading and normalized). Samples and probes lie inside it;
// it weighs how much of the walkthrough each dense sample stands for.

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace triwalk {

using Ring = std::vector<glm::dvec2>;

struct RegionPolygon {
  Ring outer;               // counter-clockwise
  std::vector<Ring> holes;  // clockwise
};

class WalkableRegion {
public:
  WalkableRegion() = default;
  // Normalizes ring orientation. Throws InputError naming subject for a
  // ring with fewer than 3 points, non-finite or repeated points, zero
  // area, self-intersections, or rings that cross each other.
  WalkableRegion(std::vector<RegionPolygon> polygons, const std::string& subject);
  static WalkableRegion rectangle(glm::dvec2 lower, glm::dvec2 upper);

  const std::vector<RegionPolygon>& polygons() const { return polygons_; }
  bool empty() const { return polygons_.empty(); }
  // Inside or on the boundary.
  bool contains(glm::dvec2 point) const;
  // Whether the closed segment lies in the region (it may run along the
  // boundary, never outside it): a view edge that does not cross a wall.
  bool containsSegment(glm::dvec2 a, glm::dvec2 b) const;
  // Whether the closed triangle lies in the region: its edges do, and no
  // boundary point (a pillar's hole) lies strictly inside it.
  bool containsTriangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) const;
  // Whether a person standing at a sees b at eye height: the segment
  // between them stays in the region (a wall, a pillar or the space
  // outside the region blocks it). In one convex room, or with no region,
  // everything sees everything, positions on or just past its edge too.
  bool lineOfSight(glm::dvec2 a, glm::dvec2 b) const;
  // One polygon without holes whose outer ring is convex.
  bool convex() const { return convex_; }
  double area() const;
  void bounds(glm::dvec2& lower, glm::dvec2& upper) const;

  nlohmann::json toJson() const;
  // Reads the {"polygons": [...]} form; errors name subject and the field.
  static WalkableRegion fromJson(const nlohmann::json& value, const std::string& subject);

private:
  // The rings' edges by horizontal band, so that the point test reads the
  // few edges its height meets instead of all of them, and the segment and
  // triangle tests those of the heights they span (a level's boundary has
  // hundreds, and the decimation asks millions of times). A band lists
  // its edges ring by ring (rings numbered polygon by polygon, outer ring
  // first), each once, as its two ends in the ring's order.
  struct EdgeBands {
    double lowerY = 0.0, height = 1.0;
    int count = 1, rings = 0;
    std::vector<size_t> first;  // [band * rings + ring]: the ring's first end in the band; one more at the end
    std::vector<glm::dvec2> ends;
  };
  void indexEdges();
  int bandOf(double y) const;
  // The ends of every edge listed in the bands from lowerY's to upperY's.
  std::span<const glm::dvec2> bandEnds(double lowerY, double upperY) const;

  std::vector<RegionPolygon> polygons_;
  bool convex_ = true;
  EdgeBands bands_;
};

// A shared copy of region for meshes to keep; null for none or an empty one.
std::shared_ptr<const WalkableRegion> sharedRegion(const WalkableRegion* region);

// Each sample's share of the region: the area of the part of it nearer to
// that sample than to any other (its Voronoi cell clipped to the region),
// estimated on a raster of about 200,000 cells and scaled to average 1.
// With these weights a mean over the dense samples estimates the mean over
// the region, i.e. over uniformly placed probes and walkers: on a grid, a
// sample on the region's edge stands for half the area an interior one
// does, a corner for a quarter. Deterministic.
std::vector<double> sampleAreaWeights(std::span<const glm::dvec2> positions, const WalkableRegion& region);

}  // namespace triwalk
