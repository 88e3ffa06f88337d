#include "render/walkthrough/walkthrough_renderer.h"

#include <algorithm>

namespace triwalk {

WalkthroughRenderer::WalkthroughRenderer(ViewMesh mesh, PanoramaCache& cache, int width, int height)
    : mesh_(std::move(mesh)), cache_(cache), warper_(width, height) {}

void WalkthroughRenderer::setMesh(ViewMesh mesh) {
  mesh_ = std::move(mesh);
  lastTriangle_ = -1;
}

int WalkthroughRenderer::triangleAt(glm::vec3 position) {
  lastTriangle_ = mesh_.locate(glm::dvec2(position), lastTriangle_);
  return lastTriangle_;
}

std::vector<int> WalkthroughRenderer::prefetch(int triangle, glm::vec3 position) {
  const Triangle& current = mesh_.triangles()[size_t(triangle)];
  std::vector<int> wanted(current.begin(), current.end());
  // Then the other vertices of the neighbouring triangles, nearest first.
  std::vector<int> neighbours;
  for (int e = 0; e < 3; ++e) {
    const int next = mesh_.neighbour(triangle, e);
    if (next < 0) continue;
    for (int v : mesh_.triangles()[size_t(next)]) {
      if (std::find(wanted.begin(), wanted.end(), v) == wanted.end() &&
          std::find(neighbours.begin(), neighbours.end(), v) == neighbours.end()) {
        neighbours.push_back(v);
      }
    }
  }
  const glm::dvec2 here(position);
  std::stable_sort(neighbours.begin(), neighbours.end(), [&](int a, int b) {
    return glm::length(mesh_.position(a) - here) < glm::length(mesh_.position(b) - here);
  });
  wanted.insert(wanted.end(), neighbours.begin(), neighbours.end());
  cache_.request(wanted);
  return neighbours;
}

WalkthroughRenderer::Frame WalkthroughRenderer::render(const PinholeCamera& camera, const GpuWarpSettings& settings,
                                                       bool waitForPanoramas, bool timePasses, float frameScale) {
  Frame frame;
  frame.triangle = triangleAt(camera.position);
  if (frame.triangle < 0) return frame;
  const Triangle& triangle = mesh_.triangles()[size_t(frame.triangle)];
  frame.references = {triangle[0], triangle[1], triangle[2]};
  const std::vector<int> neighbours = prefetch(frame.triangle, camera.position);
  std::vector<const GpuPanorama*> references;
  for (int sample : triangle) {
    const GpuPanorama* panorama = waitForPanoramas ? cache_.wait(sample) : cache_.find(sample);
    if (panorama) references.push_back(panorama);
  }
  frame.available = int(references.size());
  // The three nearest neighbours for the holes; a walk that does not wait
  // takes those already loaded.
  std::vector<const GpuPanorama*> fallback;
  if (settings.holesFromNeighbours) {
    for (int sample : neighbours) {
      if (fallback.size() == 3) break;
      const GpuPanorama* panorama = waitForPanoramas ? cache_.wait(sample) : cache_.find(sample);
      if (!panorama) continue;
      fallback.push_back(panorama);
      frame.neighbours.push_back(sample);
    }
  }
  if (warper_.width() != camera.width || warper_.height() != camera.height) warper_.resize(camera.width, camera.height);
  if (!references.empty()) {
    frame.statistics = warper_.render(camera, references, settings, timePasses, frameScale, fallback);
  }
  return frame;
}

}  // namespace triwalk
