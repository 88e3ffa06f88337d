#include "app/viewer/view_overlay.h"

#include "app/viewer/decimation_session.h"
#include "core/image/color.h"

#include <algorithm>
#include <cstdio>

namespace triwalk {

OverlayView overlayView(const Dataset& dataset, glm::vec3 walker) {
  OverlayView nearest;
  double nearestDistance = kErrorOverlayRadiusMetres;
  auto consider = [&](const ViewRecord& view, OverlayView candidate) {
    const double distance = glm::distance(glm::dvec2(view.position), glm::dvec2(walker));
    if (distance <= nearestDistance) nearest = candidate, nearestDistance = distance;
  };
  for (int i = 0; i < dataset.sampleCount(); ++i) consider(dataset.sample(i), {i, false});
  for (int i = 0; i < dataset.probeCount(); ++i) consider(dataset.probe(i), {i, true});
  return nearest;
}

const ViewRecord& overlayViewRecord(const Dataset& dataset, OverlayView view) {
  return view.probe ? dataset.probe(view.index) : dataset.sample(view.index);
}

void drawOverlayLegend(ImDrawList* draw, ImVec2 display, float viewWidth, ViewOverlay overlay, const std::string& note) {
  if (overlay == ViewOverlay::None) return;
  const std::string title = std::string(overlay == ViewOverlay::Trust ? "trust (T): " : "error against a captured view (E): ") + note;
  char high[96];
  if (overlay == ViewOverlay::Trust) {
    std::snprintf(high, sizeof high, "1: three references agree (black: none)");
  } else {
    std::snprintf(high, sizeof high, "%.2f RMS colour difference", double(kInspectionHeatmapScale));
  }
  const float width = std::min(260.0f, viewWidth * 0.4f), left = 12.0f, top = display.y - 46.0f;
  // A dark box behind the bar and its words, as wide as they are, so that they read over any scene.
  const float right = std::max(left + ImGui::CalcTextSize(title.c_str()).x, left + width + 8.0f + ImGui::CalcTextSize(high).x);
  draw->AddRectFilled(ImVec2(left - 6.0f, top - 24.0f), ImVec2(right + 6.0f, top + 36.0f), IM_COL32(0, 0, 0, 170), 4.0f);
  constexpr int kSteps = 32;
  for (int i = 0; i < kSteps; ++i) {
    const glm::vec3 c = falseColor((float(i) + 0.5f) / float(kSteps));
    draw->AddRectFilled(ImVec2(left + width * float(i) / kSteps, top), ImVec2(left + width * float(i + 1) / kSteps, top + 14.0f),
                        ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f)));
  }
  const ImU32 text = IM_COL32(235, 235, 235, 255);
  draw->AddText(ImVec2(left, top + 16.0f), text, "0");
  draw->AddText(ImVec2(left + width + 8.0f, top), text, high);
  draw->AddText(ImVec2(left, top - 20.0f), text, title.c_str());
}

}  // namespace triwalk
