#include "core/selection/collapse/placement_candidates.h"

namespace triwalk {

std::vector<PlacementCandidate> placementCandidates(const CollapseMesh& mesh, int a, int b, bool oneRing,
                                                    NearestToMidpoint& nearest) {
  std::vector<PlacementCandidate> result = {{a, PlacementKind::First}, {b, PlacementKind::Second}};
  const glm::dvec2 midpoint = 0.5 * (mesh.position(a) + mesh.position(b));
  nearest = {};
  for (int s = 0; s < mesh.sampleCount(); ++s) {
    if (mesh.isVertex(s) && s != a && s != b) continue;
    const double d = glm::length(mesh.position(s) - midpoint);
    if (d < nearest.distance) nearest = {s, d};
  }
  if (nearest.sample != a && nearest.sample != b) result.push_back({nearest.sample, PlacementKind::Midpoint});
  if (!oneRing) return result;

  std::vector<int> ring = mesh.incident(a);
  ring.insert(ring.end(), mesh.incident(b).begin(), mesh.incident(b).end());
  for (int s = 0; s < mesh.sampleCount(); ++s) {
    if (mesh.isVertex(s) || s == nearest.sample) continue;
    for (int t : ring) {
      const Triangle& tri = mesh.triangle(t);
      bool inside = true;
      for (int e = 0; e < 3 && inside; ++e) {
        inside =
            orientation(mesh.position(tri[size_t(e)]), mesh.position(tri[size_t((e + 1) % 3)]), mesh.position(s)) >= 0;
      }
      if (inside) {
        result.push_back({s, PlacementKind::OneRing});
        break;
      }
    }
  }
  return result;
}

}  // namespace triwalk
