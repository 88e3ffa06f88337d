// Inspector: for the selected triangle, its reconstruction at the
// destination near its centroid, the ground truth there and the per-pixel
// error, with R, B and E.

#include "app/viewer/panel_window.h"
#include "app/viewer/viewer_state.h"

#include <imgui.h>

namespace triwalk {

void drawInspectorPanel(ViewerState& state) {
  if (!beginPanelWindow("Inspector", ImVec2(440, 10), ImVec2(560, 250))) return;
  if (state.selectedTriangle < 0) {
    ImGui::TextWrapped("Click a triangle on the map to see how its three panoramas reconstruct the view near its centroid.");
    ImGui::End();
    return;
  }
  if (!state.inspection || state.reconstructionImage.empty()) {
    ImGui::Text("reconstructing...");
    ImGui::End();
    return;
  }
  const DecimationSession::Inspection& inspection = *state.inspection;
  const Dataset& dataset = *state.dataset;
  ImGui::Text("triangle %d %d %d -> sample %d", dataset.sample(inspection.triangle[0]).id, dataset.sample(inspection.triangle[1]).id,
              dataset.sample(inspection.triangle[2]).id, dataset.sample(inspection.destination).id);
  ImGui::Text("R %.4f   B %.2f%%   E %.3f", inspection.error.rms, inspection.error.badPercent, inspection.error.total);
  const float width = (ImGui::GetContentRegionAvail().x - 16.0f) / 3.0f;
  const ImVec2 size(width, width / 2.0f);
  const GlImage* images[3] = {&state.reconstructionImage, &state.truthImage, &state.heatmapImage};
  const char* captions[3] = {"reconstruction", "ground truth", "error (red = 0.25)"};
  for (int i = 0; i < 3; ++i) {
    if (i > 0) ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::Image(images[i]->id(), size);
    ImGui::TextUnformatted(captions[i]);
    ImGui::EndGroup();
  }
  ImGui::End();
}

}  // namespace triwalk
