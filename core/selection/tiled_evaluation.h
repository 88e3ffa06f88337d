#pragma once
// Table 1's errors (core/selection/evaluation.h) for a capture too large to
// hold every view at once: the same numbers, computed tile by tile. The
// samples are cut into cores as a tiled decimation cuts them (without
// margins); a core owns the triangles whose first destination sample it
// holds and the probes nearest its rectangle, and reads only the views
// those need: their destination samples, their vertices and its probes.
// Memory is set by the tile, whatever the capture; each view is read about
// once per mesh that uses it across cores.

#include "core/io/dataset.h"
#include "core/selection/evaluation.h"
#include "core/selection/triangle_error.h"

#include <string>
#include <vector>

namespace triwalk {

struct NamedMesh {
  std::string method;
  const ViewMesh* mesh = nullptr;  // over the data set's samples
};

// evaluateMesh for every mesh, equal to it number for number, reading at
// most about mostTileSamples samples' views at a time (plus the vertices of
// long triangles reaching into a core). Progress unless quiet; Ctrl-C
// throws Interrupted.
std::vector<MethodEvaluation> evaluateMeshesInTiles(const Dataset& dataset, const std::vector<NamedMesh>& meshes,
                                                    const TriangleErrorSettings& settings, size_t mostTileSamples,
                                                    bool quiet);

}  // namespace triwalk
