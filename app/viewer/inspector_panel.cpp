// Inspector: for the selected triangle, its reconstruction at the
// destination near its centroid, the ground truth there and the per-pixel
// error, with R, B and E.

#include "app/viewer/sidebar.h"
#include "app/viewer/viewer_state.h"

#include <imgui.h>

namespace triwalk {

void drawInspectorPanel(ViewerState& state) {
  // Only with something in it: the map says how to choose a triangle.
  if (state.selectedTriangle < 0 || !beginSidebarSection("Inspector")) return;
  if (!state.inspection || state.reconstructionImage.empty()) {
    ImGui::Text("reconstructing...");
    return;
  }
  const DecimationSession::Inspection& inspection = *state.inspection;
  const Dataset& dataset = *state.dataset;
  ImGui::Text("triangle %d %d %d -> sample %d", dataset.sample(inspection.triangle[0]).id, dataset.sample(inspection.triangle[1]).id,
              dataset.sample(inspection.triangle[2]).id, dataset.sample(inspection.destination).id);
  ImGui::Text("R %.4f   B %.2f%%   E %.3f", inspection.error.rms, inspection.error.badPercent, inspection.error.total);
  // One above the other at the sidebar's width: side by side they would
  // be a third as wide.
  const float width = ImGui::GetContentRegionAvail().x;
  const ImVec2 size(width, width / 2.0f);
  const GlImage* images[3] = {&state.reconstructionImage, &state.truthImage, &state.heatmapImage};
  const char* captions[3] = {"reconstruction", "ground truth", "error (red = 0.25)"};
  for (int i = 0; i < 3; ++i) {
    ImGui::Image(images[i]->id(), size);
    ImGui::TextUnformatted(captions[i]);
  }
}

}  // namespace triwalk
