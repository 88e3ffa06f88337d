// Decimation: step one or N collapses (and the refinement's moves after
// them), forward and back, run to an error threshold or a sample count, see
// the cost of each step, save.

#include "app/viewer/sidebar.h"
#include "app/viewer/viewer_state.h"
#include "core/support/errors.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <cmath>

namespace triwalk {

void drawDecimationPanel(ViewerState& state) {
  if (!beginSidebarSection("Decimation")) return;
  const DecimationSession::Snapshot& s = state.snapshot;
  DecimationSession& session = *state.session;
  ImGui::Text("samples %d   triangles %zu   step %d of %d logged", s.samples, s.triangles.size(), s.step, s.logSize);
  const double currentCost = s.step > 0 && s.step <= int(s.costs.size()) ? s.costs[size_t(s.step - 1)] : 0.0;
  if (s.step > s.firstRelocation && s.step <= s.logSize) {
    ImGui::Text("refinement move %d of %d: dense-sample error %.3f", s.step - s.firstRelocation,
                s.logSize - s.firstRelocation, currentCost);
  } else if (s.step < s.logSize) {
    ImGui::Text("current cost %.3f   next cost %.3f (logged)", currentCost, s.costs[size_t(s.step)]);
  } else if (s.nextCost < 0.0) {
    ImGui::Text("current cost %.3f   next cost: step to compute it", currentCost);
  } else if (std::isinf(s.nextCost)) {
    ImGui::Text("current cost %.3f   no valid collapse left", currentCost);
  } else {
    ImGui::Text("current cost %.3f   next cost %.3f", currentCost, s.nextCost);
  }

  if (ImGui::Button("<< back N")) session.stepBack(state.stepCount);
  ImGui::SameLine();
  if (ImGui::Button("< back")) session.stepBack(1);
  ImGui::SameLine();
  if (ImGui::Button("step >")) session.stepForward(1);
  ImGui::SameLine();
  if (ImGui::Button("step N >>")) session.stepForward(state.stepCount);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  ImGui::InputInt("N", &state.stepCount);
  state.stepCount = std::max(1, state.stepCount);
  if (ImGui::RadioButton("error", !state.runRelative)) state.runRelative = false;
  ImGui::SameLine();
  if (ImGui::RadioButton("x dense mean", state.runRelative)) state.runRelative = true;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  ImGui::InputFloat("##error", state.runRelative ? &state.runRelativeError : &state.runError, 0.05f, 0.5f, "%.3f");
  ImGui::SameLine();
  if (ImGui::Button("run to error")) {
    if (state.runRelative) {
      session.runToRelativeError(state.runRelativeError);
    } else {
      session.runToError(state.runError);
    }
  }
  if (state.runRelative && !std::isnan(s.denseMeanError)) {
    ImGui::Text("dense mean %.3f: run to error %.3f", s.denseMeanError, state.runRelativeError * s.denseMeanError);
  }
  ImGui::SetNextItemWidth(120);
  ImGui::InputInt("##samples", &state.runSamples);
  state.runSamples = std::max(3, state.runSamples);
  ImGui::SameLine();
  if (ImGui::Button("run to samples")) session.runToSamples(state.runSamples);
  ImGui::SameLine();
  if (ImGui::Button("stop")) session.stop();

  if (!s.costs.empty()) {
    std::vector<float> costs(s.costs.begin(), s.costs.end());
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, s.firstRelocation < s.logSize ? "collapse costs, then refinement (step %d)"
                                                                          : "cost of each collapse (step %d)",
                  s.step);
    ImGui::PlotLines("##costs", costs.data(), int(costs.size()), 0, overlay, 0.0f, FLT_MAX,
                     ImVec2(ImGui::GetContentRegionAvail().x, 110));
  }

  ImGui::SetNextItemWidth(260);
  ImGui::InputText("##save", &state.savePath);
  ImGui::SameLine();
  if (ImGui::Button("save selection")) {
    try {
      writeSelection(state.savePath, session.selection(), *state.dataset);
      state.message = "saved " + state.savePath;
    } catch (const InputError& error) {
      state.message = error.what();
    }
  }
  ImGui::TextWrapped("%s%s", s.busy ? "working: " : "", s.status.c_str());
  if (s.errorsLoading) {
    ImGui::TextWrapped("panoramas at the error width still loading: new collapses, triangle colours and the inspector "
                       "follow when they are in");
  }
  if (!state.message.empty()) ImGui::TextWrapped("%s", state.message.c_str());
}

}  // namespace triwalk
