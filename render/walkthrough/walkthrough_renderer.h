#pragma once
// Walkthrough frames: the triangle of the selection around the camera
// (found by walking from the last one; outside the covered area, the
// nearest), its three panoramas from the working set, warped on the GPU.
// The working set is asked for the triangle's references first and the
// neighbouring triangles' next, so that walking on finds them loaded; the
// three of those nearest the camera also fill, before the hole fill, what
// the triangle's references did not see (GpuWarpSettings::holesFromNeighbours).

#include "core/geometry/view_mesh.h"
#include "render/walkthrough/gpu_warper.h"
#include "render/walkthrough/panorama_cache.h"

#include <array>
#include <vector>

namespace triwalk {

class WalkthroughRenderer {
public:
  WalkthroughRenderer(ViewMesh mesh, PanoramaCache& cache, int width, int height);

  struct Frame {
    int triangle = -1;
    std::array<int, 3> references{-1, -1, -1};  // sample indices
    int available = 0;                          // references drawn (the others still loading)
    std::vector<int> neighbours;                // references offered for the holes (sample indices)
    GpuFrameStatistics statistics;
  };

  // waitForPanoramas: offline rendering waits for the disk; the viewer
  // does not (a frame with no reference loaded leaves the output as it was).
  // frameScale: see GpuWarper::render.
  Frame render(const PinholeCamera& camera, const GpuWarpSettings& settings, bool waitForPanoramas,
               bool timePasses = false, float frameScale = 1.0f);

  const ViewMesh& mesh() const { return mesh_; }
  void setMesh(ViewMesh mesh);
  GpuWarper& warper() { return warper_; }
  int triangleAt(glm::vec3 position);

private:
  // Asks the working set for the triangle's references and then its
  // neighbours'; returns the neighbours' other vertices, nearest first.
  std::vector<int> prefetch(int triangle, glm::vec3 position);

  ViewMesh mesh_;
  PanoramaCache& cache_;
  GpuWarper warper_;
  int lastTriangle_ = -1;
};

}  // namespace triwalk
