#include "core/geometry/walkable_region.h"

#include "core/geometry/planar_geometry.h"
#include "core/support/errors.h"
#include "core/support/input_limits.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace triwalk {

namespace {

double signedArea(const Ring& ring) {
  double twice = 0.0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const glm::dvec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

// Whether p lies in the closed box of segment ab.
bool inBox(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// Whether segments ab and cd share a point (exact predicates).
bool segmentsMeet(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d), o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  // A collinear end point meets the other segment where it lies in its box.
  return (o1 == 0 && inBox(a, b, c)) || (o2 == 0 && inBox(a, b, d)) || (o3 == 0 && inBox(c, d, a)) ||
         (o4 == 0 && inBox(c, d, b));
}

// Crossing-number test over a ring's edges (ends, two by two) that meet
// the height of p: the others neither cross its ray nor hold it.
// Boundary points count as inside. The box test comes before the exact
// predicate, which is the costly part.
bool insideRing(std::span<const glm::dvec2> ends, glm::dvec2 p, bool& onBoundary) {
  bool inside = false;
  onBoundary = false;
  for (size_t e = 0; e + 1 < ends.size(); e += 2) {
    const glm::dvec2 a = ends[e], b = ends[e + 1];
    if (inBox(a, b, p) && orientation(a, b, p) == 0) {
      onBoundary = true;
      return true;
    }
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

bool convexRegion(const std::vector<RegionPolygon>& polygons) {
  if (polygons.size() != 1 || !polygons[0].holes.empty()) return false;
  const Ring& ring = polygons[0].outer;  // counter-clockwise
  for (size_t i = 0; i < ring.size(); ++i) {
    if (orientation(ring[i], ring[(i + 1) % ring.size()], ring[(i + 2) % ring.size()]) < 0) return false;
  }
  return true;
}

std::vector<const Ring*> ringsOf(const std::vector<RegionPolygon>& polygons) {
  std::vector<const Ring*> rings;
  for (const RegionPolygon& polygon : polygons) {
    rings.push_back(&polygon.outer);
    for (const Ring& hole : polygon.holes) rings.push_back(&hole);
  }
  return rings;
}

}  // namespace

WalkableRegion::WalkableRegion(std::vector<RegionPolygon> polygons, const std::string& subject)
    : polygons_(std::move(polygons)) {
  if (polygons_.empty()) throw InputError(subject, "the walkable region has no polygons");
  for (size_t p = 0; p < polygons_.size(); ++p) {
    RegionPolygon& polygon = polygons_[p];
    auto check = [&](Ring& ring, const std::string& name, bool counterClockwise) {
      const std::string where = "polygons[" + std::to_string(p) + "]." + name;
      if (ring.size() < 3) throw InputError(subject, where + ": a ring needs at least 3 points");
      for (size_t i = 0; i < ring.size(); ++i) {
        if (!std::isfinite(ring[i].x) || !std::isfinite(ring[i].y)) {
          throw InputError(subject, where + "[" + std::to_string(i) + "]: not a finite point");
        }
        if (ring[i] == ring[(i + 1) % ring.size()]) {
          throw InputError(subject, where + "[" + std::to_string(i) + "]: repeats the next point");
        }
      }
      const double area = signedArea(ring);
      if (area == 0.0) throw InputError(subject, where + ": encloses no area");
      if ((area > 0.0) != counterClockwise) std::reverse(ring.begin(), ring.end());
      const size_t n = ring.size();
      for (size_t i = 0; i < n; ++i) {
        for (size_t j = i + 1; j < n; ++j) {
          if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // neighbours share a point
          if (segmentsMeet(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n])) {
            throw InputError(subject, where + ": the ring intersects itself (edges " + std::to_string(i) + " and " +
                                          std::to_string(j) + ")");
          }
        }
      }
    };
    check(polygon.outer, "outer", true);
    for (size_t h = 0; h < polygon.holes.size(); ++h) check(polygon.holes[h], "holes[" + std::to_string(h) + "]", false);
  }
  const std::vector<const Ring*> rings = ringsOf(polygons_);
  for (size_t r = 0; r < rings.size(); ++r) {
    for (size_t s = r + 1; s < rings.size(); ++s) {
      const Ring &a = *rings[r], &b = *rings[s];
      for (size_t i = 0; i < a.size(); ++i) {
        for (size_t j = 0; j < b.size(); ++j) {
          if (segmentsMeet(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()])) {
            throw InputError(subject, "the walkable region's rings cross or touch each other");
          }
        }
      }
    }
  }
  convex_ = convexRegion(polygons_);
  indexEdges();
}

WalkableRegion WalkableRegion::rectangle(glm::dvec2 lower, glm::dvec2 upper) {
  WalkableRegion region;
  region.polygons_.push_back({{lower, {upper.x, lower.y}, upper, {lower.x, upper.y}}, {}});
  region.indexEdges();
  return region;
}

int WalkableRegion::bandOf(double y) const {
  // Monotone in y, so an edge whose y-range holds y is listed in y's band.
  const double band = (y - bands_.lowerY) / bands_.height;
  if (!(band >= 0.0)) return 0;
  return band >= double(bands_.count) ? bands_.count - 1 : int(band);
}

void WalkableRegion::indexEdges() {
  const std::vector<const Ring*> rings = ringsOf(polygons_);
  size_t edges = 0;
  double lowerY = std::numeric_limits<double>::max(), upperY = std::numeric_limits<double>::lowest();
  for (const Ring* ring : rings) {
    edges += ring->size();
    for (glm::dvec2 p : *ring) lowerY = std::min(lowerY, p.y), upperY = std::max(upperY, p.y);
  }
  // About four edges a band: a level's outline (0.25 m cells) gets bands a
  // few cells high, a rectangle one band.
  bands_ = {};
  bands_.rings = int(rings.size());
  bands_.count = int(std::clamp<size_t>(edges / 4, 1, 4096));
  bands_.lowerY = lowerY;
  bands_.height = std::max((upperY - lowerY) / double(bands_.count), std::numeric_limits<double>::min());
  const size_t stride = rings.size();
  std::vector<std::vector<glm::dvec2>> perBand(size_t(bands_.count) * stride);
  for (size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = *rings[r];
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      const glm::dvec2 a = ring[j], b = ring[i];
      for (int band = bandOf(std::min(a.y, b.y)); band <= bandOf(std::max(a.y, b.y)); ++band) {
        std::vector<glm::dvec2>& list = perBand[size_t(band) * stride + r];
        list.push_back(a);
        list.push_back(b);
      }
    }
  }
  bands_.first.reserve(perBand.size() + 1);
  for (const std::vector<glm::dvec2>& list : perBand) {  // band by band, ring by ring
    bands_.first.push_back(bands_.ends.size());
    bands_.ends.insert(bands_.ends.end(), list.begin(), list.end());
  }
  bands_.first.push_back(bands_.ends.size());
}

std::span<const glm::dvec2> WalkableRegion::bandEnds(double lowerY, double upperY) const {
  if (bands_.first.empty()) return {};  // an empty region
  const size_t rings = size_t(bands_.rings);
  const size_t first = bands_.first[size_t(bandOf(lowerY)) * rings];
  return std::span<const glm::dvec2>(bands_.ends).subspan(first, bands_.first[size_t(bandOf(upperY) + 1) * rings] - first);
}

bool WalkableRegion::contains(glm::dvec2 point) const {
  const size_t base = size_t(bandOf(point.y)) * size_t(bands_.rings);
  auto ringEnds = [&](size_t ring) {
    const size_t first = bands_.first[base + ring];
    return std::span<const glm::dvec2>(bands_.ends).subspan(first, bands_.first[base + ring + 1] - first);
  };
  size_t ring = 0;
  for (const RegionPolygon& polygon : polygons_) {
    const size_t outer = ring;
    ring += 1 + polygon.holes.size();
    bool onBoundary = false;
    if (!insideRing(ringEnds(outer), point, onBoundary)) continue;
    bool inHole = false;
    for (size_t hole = outer + 1; hole < ring; ++hole) {
      bool onHoleBoundary = false;
      inHole |= insideRing(ringEnds(hole), point, onHoleBoundary) && !onHoleBoundary;
    }
    if (!inHole) return true;
  }
  return false;
}

bool WalkableRegion::containsSegment(glm::dvec2 a, glm::dvec2 b) const {
  // The boundary points on the segment cut it into pieces that are each
  // wholly inside or wholly outside; a proper crossing means outside.
  std::vector<double> cuts{0.0, 1.0};
  const glm::dvec2 direction = b - a;
  const double length2 = glm::dot(direction, direction);
  // An edge that crosses the segment, or has its first end on it, meets
  // the segment's box; skipping the edges that miss a slightly larger box
  // (by far more than the rounding of the cut's parameter below) leaves
  // every answer as the exact predicates on all edges give it.
  // Such an edge is listed in a band of the box's heights; an edge listed
  // in several is tested again, which adds only a repeated cut.
  const double margin = 1e-9 * (1.0 + std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)}));
  const glm::dvec2 lower = glm::min(a, b) - margin, upper = glm::max(a, b) + margin;
  const std::span<const glm::dvec2> ends = bandEnds(lower.y, upper.y);
  for (size_t e = 0; e + 1 < ends.size(); e += 2) {
    const glm::dvec2 c = ends[e], d = ends[e + 1];
    if (std::max(c.x, d.x) < lower.x || std::min(c.x, d.x) > upper.x || std::max(c.y, d.y) < lower.y ||
        std::min(c.y, d.y) > upper.y) {
      continue;
    }
    const int o1 = orientation(a, b, c), o2 = orientation(a, b, d), o3 = orientation(c, d, a), o4 = orientation(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return false;
    if (o1 == 0 && length2 > 0.0) {
      const double t = glm::dot(c - a, direction) / length2;
      if (t > 0.0 && t < 1.0) cuts.push_back(t);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  if (!contains(a) || !contains(b)) return false;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (cuts[k + 1] > cuts[k] && !contains(a + (0.5 * (cuts[k] + cuts[k + 1])) * direction)) return false;
  }
  return true;
}

std::shared_ptr<const WalkableRegion> sharedRegion(const WalkableRegion* region) {
  return region && !region->empty() ? std::make_shared<const WalkableRegion>(*region) : nullptr;
}

bool WalkableRegion::lineOfSight(glm::dvec2 a, glm::dvec2 b) const {
  return convex_ || containsSegment(a, b);
}

bool WalkableRegion::containsTriangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) const {
  if (orientation(a, b, c) < 0) std::swap(b, c);
  if (!containsSegment(a, b) || !containsSegment(b, c) || !containsSegment(c, a)) return false;
  // Every ring vertex is the first end of an edge listed in its own band.
  const glm::dvec2 lower = glm::min(a, glm::min(b, c)), upper = glm::max(a, glm::max(b, c));
  const std::span<const glm::dvec2> ends = bandEnds(lower.y, upper.y);
  for (size_t e = 0; e < ends.size(); e += 2) {
    const glm::dvec2 p = ends[e];
    if (p.x <= lower.x || p.x >= upper.x || p.y <= lower.y || p.y >= upper.y) continue;  // not strictly inside
    if (orientation(a, b, p) > 0 && orientation(b, c, p) > 0 && orientation(c, a, p) > 0) return false;
  }
  return true;
}

double WalkableRegion::area() const {
  double area = 0.0;
  for (const RegionPolygon& polygon : polygons_) {
    area += signedArea(polygon.outer);
    for (const Ring& hole : polygon.holes) area += signedArea(hole);  // negative
  }
  return area;
}

void WalkableRegion::bounds(glm::dvec2& lower, glm::dvec2& upper) const {
  lower = glm::dvec2(std::numeric_limits<double>::max());
  upper = glm::dvec2(std::numeric_limits<double>::lowest());
  for (const RegionPolygon& polygon : polygons_) {
    for (glm::dvec2 p : polygon.outer) lower = glm::min(lower, p), upper = glm::max(upper, p);
  }
}

nlohmann::json WalkableRegion::toJson() const {
  auto ringJson = [](const Ring& ring) {
    nlohmann::json points = nlohmann::json::array();
    for (glm::dvec2 p : ring) points.push_back({p.x, p.y});
    return points;
  };
  nlohmann::json polygons = nlohmann::json::array();
  for (const RegionPolygon& polygon : polygons_) {
    nlohmann::json holes = nlohmann::json::array();
    for (const Ring& hole : polygon.holes) holes.push_back(ringJson(hole));
    polygons.push_back({{"outer", ringJson(polygon.outer)}, {"holes", holes}});
  }
  return {{"polygons", polygons}};
}

WalkableRegion WalkableRegion::fromJson(const nlohmann::json& value, const std::string& subject) {
  auto ring = [&](const nlohmann::json& points, const std::string& where) {
    if (!points.is_array()) throw InputError(subject, where + ": a ring is an array of [x, y] points");
    Ring result;
    for (size_t i = 0; i < points.size(); ++i) {
      const nlohmann::json& point = points[i];
      if (!point.is_array() || point.size() != 2 || !point[0].is_number() || !point[1].is_number()) {
        throw InputError(subject, where + "[" + std::to_string(i) + "]: a point is [x, y] in metres");
      }
      const glm::dvec2 xy(point[0].get<double>(), point[1].get<double>());
      if (!withinCoordinateBound(xy.x) || !withinCoordinateBound(xy.y)) {
        throw InputError(subject, where + "[" + std::to_string(i) + "]: a coordinate is farther than " +
                                      kCoordinateBoundText + " from the origin");
      }
      result.push_back(xy);
    }
    return result;
  };
  if (!value.is_object() || !value.contains("polygons") || !value["polygons"].is_array()) {
    throw InputError(subject, "walkable: expected {\"polygons\": [{\"outer\": [...], \"holes\": [...]}, ...]}");
  }
  std::vector<RegionPolygon> polygons;
  const nlohmann::json& list = value["polygons"];
  for (size_t p = 0; p < list.size(); ++p) {
    const std::string where = "polygons[" + std::to_string(p) + "]";
    if (!list[p].is_object() || !list[p].contains("outer")) throw InputError(subject, where + ": needs an \"outer\" ring");
    RegionPolygon polygon;
    polygon.outer = ring(list[p]["outer"], where + ".outer");
    if (list[p].contains("holes")) {
      const nlohmann::json& holes = list[p]["holes"];
      if (!holes.is_array()) throw InputError(subject, where + ".holes: an array of rings");
      for (size_t h = 0; h < holes.size(); ++h) polygon.holes.push_back(ring(holes[h], where + ".holes[" + std::to_string(h) + "]"));
    }
    polygons.push_back(std::move(polygon));
  }
  return WalkableRegion(std::move(polygons), subject);
}

std::vector<double> sampleAreaWeights(std::span<const glm::dvec2> positions, const WalkableRegion& region) {
  const size_t n = positions.size();
  std::vector<double> weights(n, 0.0);
  if (n == 0) return weights;
  glm::dvec2 lower, upper;
  region.bounds(lower, upper);
  const double area = region.area();
  if (!(area > 0.0)) return std::vector<double>(n, 1.0);
  // About 200,000 raster cells over the region's bounding box, and never
  // more than 20,000 along one side: a thin or sprawling region (the
  // region fuzzer found one 1214 m long and 3 m wide) costs no more than
  // a square one.
  const glm::dvec2 extent = upper - lower;
  const double cell = std::max(std::sqrt(extent.x * extent.y / 200000.0), std::max(extent.x, extent.y) / 20000.0);

  // Buckets of samples for the nearest-sample search.
  glm::dvec2 sampleLower(std::numeric_limits<double>::max()), sampleUpper(std::numeric_limits<double>::lowest());
  for (glm::dvec2 p : positions) sampleLower = glm::min(sampleLower, p), sampleUpper = glm::max(sampleUpper, p);
  const glm::dvec2 gridLower = glm::min(sampleLower, lower), gridUpper = glm::max(sampleUpper, upper);
  const glm::dvec2 gridExtent = gridUpper - gridLower;
  const double bucket = std::max({std::sqrt(gridExtent.x * gridExtent.y / double(n)),
                                  std::max(gridExtent.x, gridExtent.y) / 1024.0, 1e-6});
  const int columns = std::max(1, int((gridUpper.x - gridLower.x) / bucket) + 1);
  const int rows = std::max(1, int((gridUpper.y - gridLower.y) / bucket) + 1);
  std::vector<std::vector<int>> buckets(size_t(columns) * size_t(rows));
  auto bucketOf = [&](glm::dvec2 p, int& bx, int& by) {
    bx = std::clamp(int((p.x - gridLower.x) / bucket), 0, columns - 1);
    by = std::clamp(int((p.y - gridLower.y) / bucket), 0, rows - 1);
  };
  for (size_t i = 0; i < n; ++i) {
    int bx, by;
    bucketOf(positions[i], bx, by);
    buckets[size_t(by) * size_t(columns) + size_t(bx)].push_back(int(i));
  }
  auto nearest = [&](glm::dvec2 p) {
    int bx, by;
    bucketOf(p, bx, by);
    int best = -1;
    double bestDistance = std::numeric_limits<double>::max();
    for (int ring = 0; ring <= std::max(columns, rows); ++ring) {
      // Every sample in a bucket `ring` steps away is at least (ring - 1) buckets off.
      if (best >= 0 && double(ring - 1) * bucket > std::sqrt(bestDistance)) break;
      for (int y = by - ring; y <= by + ring; ++y) {
        for (int x = bx - ring; x <= bx + ring; ++x) {
          if (std::max(std::abs(x - bx), std::abs(y - by)) != ring || x < 0 || y < 0 || x >= columns || y >= rows) continue;
          for (int i : buckets[size_t(y) * size_t(columns) + size_t(x)]) {
            const glm::dvec2 d = positions[size_t(i)] - p;
            const double distance = glm::dot(d, d);
            if (distance < bestDistance || (distance == bestDistance && i < best)) bestDistance = distance, best = i;
          }
        }
      }
    }
    return best;
  };

  // Raster rows: the x intervals inside the region from the ring crossings
  // (even-odd over all rings: holes subtract, disjoint polygons add).
  const std::vector<const Ring*> rings = ringsOf(region.polygons());
  const int rasterRows = int(std::ceil((upper.y - lower.y) / cell));
  for (int r = 0; r < rasterRows; ++r) {
    const double y = lower.y + (r + 0.5) * cell;
    std::vector<double> crossings;
    for (const Ring* ring : rings) {
      for (size_t i = 0; i < ring->size(); ++i) {
        const glm::dvec2 a = (*ring)[i], b = (*ring)[(i + 1) % ring->size()];
        if ((a.y > y) != (b.y > y)) crossings.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
      }
    }
    std::sort(crossings.begin(), crossings.end());
    for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
      const int first = int(std::ceil((crossings[k] - lower.x) / cell - 0.5));
      const int last = int(std::floor((crossings[k + 1] - lower.x) / cell - 0.5));
      for (int c = first; c <= last; ++c) weights[size_t(nearest({lower.x + (c + 0.5) * cell, y}))] += 1.0;
    }
  }
  double total = 0.0;
  for (double w : weights) total += w;
  if (!(total > 0.0)) return std::vector<double>(n, 1.0);
  for (double& w : weights) w *= double(n) / total;
  return weights;
}

}  // namespace triwalk
