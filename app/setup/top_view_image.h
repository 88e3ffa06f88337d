#pragma once
// A top view of a data set's walkthrough space for `triwalk region`: the
// walkable region (grey, holes white), a view mesh's edges (blue), its
// references (black), the other samples (grey dots) and the probes (red).
// North (+y) is up; one pixel is the same length along x and y. A band
// below says what each mark is, with its count, and gives a scale bar.

#include "core/geometry/view_mesh.h"
#include "core/image/image.h"
#include "core/io/dataset.h"

namespace triwalk {

// longSide: pixels along the longer side of the region's bounds.
Rgb8Image topViewImage(const Dataset& dataset, const ViewMesh& mesh, int longSide);

}  // namespace triwalk
