#include "core/selection/tiled_evaluation.h"

#include "core/selection/selection.h"
#include "core/selection/tile_partition.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace triwalk {
namespace {

// What one mesh asks of the tiles: each triangle's destinations, and the
// triangles each core owns.
struct MeshWork {
  std::vector<std::vector<std::pair<int, double>>> destinations;
  std::vector<std::vector<size_t>> ownedBy;  // by core: triangle indices, ascending
};

int localIndex(const std::vector<int>& sorted, int index) {
  return int(std::lower_bound(sorted.begin(), sorted.end(), index) - sorted.begin());
}

Triangle localTriangle(const std::vector<int>& sorted, const Triangle& triangle) {
  // The vertex order is kept: the blend sums the three layers in it.
  return {localIndex(sorted, triangle[0]), localIndex(sorted, triangle[1]), localIndex(sorted, triangle[2])};
}

}  // namespace

std::vector<MethodEvaluation> evaluateMeshesInTiles(const Dataset& dataset, const std::vector<NamedMesh>& meshes,
                                                    const TriangleErrorSettings& settings, size_t mostTileSamples,
                                                    bool quiet) {
  const std::vector<glm::dvec2> positions = samplePositions(dataset);
  const std::vector<TileCore> cores = splitIntoCores(positions, 0.0, {.mostTileSamples = mostTileSamples});
  std::vector<int> coreOf(positions.size());
  for (size_t k = 0; k < cores.size(); ++k) {
    for (int i : cores[k].members) coreOf[size_t(i)] = int(k);
  }
  std::vector<int> probeOwner(size_t(dataset.probeCount()));
  for (int p = 0; p < dataset.probeCount(); ++p) {
    const glm::dvec2 position(dataset.probe(p).position);
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < cores.size(); ++k) {
      if (const double d = distanceToCore(position, cores[k]); d < nearest) nearest = d, probeOwner[size_t(p)] = int(k);
    }
  }

  std::vector<MeshWork> work(meshes.size());
  std::vector<MethodEvaluation> evaluations(meshes.size());
  for (size_t m = 0; m < meshes.size(); ++m) {
    const ViewMesh& mesh = *meshes[m].mesh;
    MeshWork& w = work[m];
    w.destinations.resize(mesh.triangles().size());
    tbb::parallel_for(size_t(0), mesh.triangles().size(), [&](size_t t) {
      w.destinations[t] = triangleDestinations(positions, mesh.triangles()[t], settings.destinations);
    });
    w.ownedBy.resize(cores.size());
    for (size_t t = 0; t < mesh.triangles().size(); ++t) {
      w.ownedBy[size_t(coreOf[size_t(w.destinations[t].front().first)])].push_back(t);
    }
    MethodEvaluation& e = evaluations[m];
    e.method = meshes[m].method;
    e.samples = mesh.vertexCount();
    e.triangles = mesh.triangleCount();
    e.triangleErrors.resize(mesh.triangles().size());
    e.probeErrors.resize(size_t(dataset.probeCount()));
    for (int p = 0; p < dataset.probeCount(); ++p) e.probeTriangles.push_back(mesh.locate(glm::dvec2(dataset.probe(p).position)));
  }

  ProgressReporter progress("evaluate, by tiles", cores.size(), quiet);
  for (size_t k = 0; k < cores.size(); ++k) {
    throwIfInterrupted();
    std::vector<int> needed, probes;
    for (int p = 0; p < dataset.probeCount(); ++p) {
      if (probeOwner[size_t(p)] != int(k)) continue;
      probes.push_back(p);
      for (size_t m = 0; m < meshes.size(); ++m) {
        const Triangle& t = meshes[m].mesh->triangles()[size_t(evaluations[m].probeTriangles[size_t(p)])];
        needed.insert(needed.end(), t.begin(), t.end());
      }
    }
    for (size_t m = 0; m < meshes.size(); ++m) {
      for (size_t t : work[m].ownedBy[k]) {
        const Triangle& triangle = meshes[m].mesh->triangles()[t];
        needed.insert(needed.end(), triangle.begin(), triangle.end());
        for (const auto& [destination, weight] : work[m].destinations[t]) needed.push_back(destination);
      }
    }
    std::sort(needed.begin(), needed.end());
    needed.erase(std::unique(needed.begin(), needed.end()), needed.end());
    if (needed.empty()) {
      progress.advance();
      continue;
    }
    const Dataset part = dataset.withViews(needed, probes);
    DatasetTriangleErrors errors(part, settings, probes.empty() ? LoadedViews::Samples : LoadedViews::SamplesAndProbes,
                                 true);
    for (size_t m = 0; m < meshes.size(); ++m) {
      const std::vector<Triangle>& triangles = meshes[m].mesh->triangles();
      const std::vector<size_t>& owned = work[m].ownedBy[k];
      std::vector<SampleReconstruction> requests;
      for (size_t t : owned) {
        for (const auto& [destination, weight] : work[m].destinations[t]) {
          requests.push_back({localTriangle(needed, triangles[t]), localIndex(needed, destination)});
        }
      }
      std::vector<double> values(requests.size());
      errors.computeReconstructionErrors(requests, values);
      // Summed in the destinations' order, as DatasetTriangleErrors::computeErrors sums them.
      size_t next = 0;
      for (size_t t : owned) {
        double error = 0.0;
        for (const auto& destination : work[m].destinations[t]) error += destination.second * values[next++];
        evaluations[m].triangleErrors[t] = error;
      }
      tbb::parallel_for(size_t(0), probes.size(), [&](size_t local) {
        const int p = probes[local];
        const Triangle triangle = localTriangle(needed, triangles[size_t(evaluations[m].probeTriangles[size_t(p)])]);
        evaluations[m].probeErrors[size_t(p)] =
            errors.errorAt(triangle, dataset.probe(p).position, errors.probeDisplay(int(local))).total;
      });
    }
    progress.advance();
  }
  progress.finish();
  throwIfInterrupted();
  for (MethodEvaluation& e : evaluations) {
    meanAndDeviation(e.triangleErrors, e.meanError, e.stdError);
    meanAndDeviation(e.probeErrors, e.probeMeanError, e.probeStdError);
  }
  return evaluations;
}

}  // namespace triwalk
