#include "app/viewer/sidebar.h"

#include <algorithm>

namespace triwalk {

float sidebarWidth(ImVec2 display) {
  // Wide enough for the map and the decimation's plot, and never more
  // than a third of the window, so the scene keeps the rest.
  return std::clamp(display.x / 3.0f, 280.0f, 440.0f);
}

void beginSidebar(ImVec2 display) {
  const float width = sidebarWidth(display);
  ImGui::SetNextWindowPos(ImVec2(display.x - width, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(width, display.y));
  ImGui::Begin("Tools (Tab hides them, F1 lists every key)", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings);
}

bool beginSidebarSection(const char* title) { return ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen); }

}  // namespace triwalk
