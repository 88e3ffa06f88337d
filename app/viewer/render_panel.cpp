// Render settings and statistics: the blend's epsilon and weights, the
// stretch test, hole display, which reference made each pixel; frame rate
// and the working set.

#include "app/viewer/sidebar.h"
#include "app/viewer/viewer_state.h"

#include <imgui.h>

namespace triwalk {

void drawRenderPanel(ViewerState& state) {
  if (!beginSidebarSection("Render")) return;
  // A scripted run's screenshot leaves out what depends on timing, so that it repeats.
  if (state.scripted) {
    ImGui::TextDisabled("frame times and the working set: not shown in scripted runs (--frames)");
  } else {
    ImGui::Text("%.1f fps, frame %.1f ms (%.2f M triangles)",
                state.smoothedFrameSeconds > 0.0 ? 1.0 / state.smoothedFrameSeconds : 0.0, state.frameMilliseconds,
                double(state.frame.trianglesDrawn) / 1e6);
  }
  const Dataset& dataset = *state.dataset;
  ImGui::Text("triangle %d, references", state.currentTriangle);
  for (int r : state.references) {
    ImGui::SameLine();
    ImGui::Text("%d", r >= 0 ? dataset.sample(r).id : -1);
  }
  if (state.referencesAvailable < 3) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1, 0.6f, 0.2f, 1), "(%d loading)", 3 - state.referencesAvailable);
  }
  if (!state.scripted) {
    ImGui::Text("working set: %d resident, %.0f MB, %d pending; hits %llu, misses %llu", state.cache.resident,
                double(state.cache.residentBytes) / 1e6, state.cache.pending, (unsigned long long)state.cache.hits,
                (unsigned long long)state.cache.misses);
  }
  ImGui::Separator();
  ImGui::SliderFloat("epsilon", &state.warp.blend.epsilon, 0.001f, 0.5f, "%.3f", ImGuiSliderFlags_Logarithmic);
  ImGui::SliderFloat("r_min (m)", &state.warp.blend.minimumWeightDistance, 0.01f, 2.0f, "%.2f");
  int weights = int(state.warp.blend.weights);
  if (ImGui::Combo("weights", &weights, "inverse distance x reliability\0inverse distance (paper)\0")) {
    state.warp.blend.weights = BlendWeights(weights);
  }
  ImGui::SliderFloat("grazing angle", &state.grazingAngleDegrees, 0.5f, 30.0f, "%.1f deg");
  ImGui::SameLine();
  if (ImGui::Button("apply")) state.stretchChanged = true;
  int holes = int(state.warp.holes);
  if (ImGui::Combo("holes", &holes, "fill from the background\0mark in magenta\0black\0")) {
    state.warp.holes = HoleMode(holes);
  }
  ImGui::Checkbox("show references (red, green, blue)", &state.warp.showSources);
  int overlay = int(state.overlay);
  if (ImGui::Combo("overlay (T, E)", &overlay, "none\0trust\0error against the nearest sample or probe\0")) {
    state.overlay = ViewOverlay(overlay);
  }
  ImGui::SliderFloat("field of view", &state.verticalFovDegrees, 30.0f, 110.0f, "%.0f deg");
  ImGui::SliderFloat("render scale", &state.renderScale, 0.25f, 1.0f, "%.2f");
  ImGui::Checkbox("while walking, fit the frame in", &state.holdFrameBudget);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120.0f);
  ImGui::SliderFloat("ms", &state.frameBudgetMilliseconds, 10.0f, 200.0f, "%.0f");
  ImGui::Text("on screen: %.2f of each side%s", state.currentScale,
              state.currentScale < state.renderScale ? " (walking; full once you stop)" : "");
  ImGui::SliderFloat("walking speed", &state.walk.speed, 0.1f, 5.0f, "%.1f m/s");
  ImGui::Text("position (%.2f, %.2f)  yaw %.0f  pitch %.0f", state.walk.position.x, state.walk.position.y, state.walk.yawDegrees,
              state.walk.pitchDegrees);
  if (ImGui::Button("screenshot (F12)")) state.screenshotRequested = true;
  ImGui::TextDisabled("W A S D / arrows: walk, Shift: run, drag: look around, F1: every key");
}

}  // namespace triwalk
