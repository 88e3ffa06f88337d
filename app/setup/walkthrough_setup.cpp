#include "app/setup/walkthrough_setup.h"

#include "core/selection/evaluation.h"
#include "core/selection/selection.h"
#include "core/support/errors.h"

#include <cstdio>

namespace triwalk {

ViewMesh walkthroughMesh(const Dataset& dataset, const std::string& selectionPath) {
  if (selectionPath.empty()) return datasetMesh(dataset, {}, dataset.manifestPath().string());
  return selectionMesh(readSelection(selectionPath, dataset), dataset);
}

std::string describeSamplesOutsideTriangles(const Dataset& dataset, const ViewMesh& mesh) {
  const UncoveredPositions uncovered = uncoveredPositions(mesh, samplePositions(dataset));
  if (uncovered.count == 0) return "";
  char text[200];
  std::snprintf(text, sizeof text,
                "%d of %d samples lie outside every view triangle (up to %.2f m from one); frames there come "
                "from the best-ranked triangle's references",
                uncovered.count, dataset.sampleCount(), uncovered.farthest);
  return text;
}

float sampleEyeHeight(const Dataset& dataset) {
  double sum = 0.0;
  for (int i = 0; i < dataset.sampleCount(); ++i) sum += dataset.sample(i).position.z;
  return float(sum / dataset.sampleCount());
}

void parseSize(const std::string& text, const std::string& option, int& width, int& height) {
  char x = 0;
  int consumed = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%n", &width, &x, &height, &consumed) != 3 || x != 'x' ||
      consumed != int(text.size()) || width < 16 || height < 16 || width > 8192 || height > 8192) {
    throw InputError(option, "expected WIDTHxHEIGHT between 16 and 8192, got '" + text + "'");
  }
}

}  // namespace triwalk
