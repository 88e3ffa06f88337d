#include "app/viewer/panel_window.h"

namespace triwalk {

bool beginPanelWindow(const char* title, ImVec2 position, ImVec2 size) {
  ImGui::SetNextWindowPos(position, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(size, ImGuiCond_FirstUseEver);
  if (ImGui::Begin(title)) return true;
  ImGui::End();
  return false;
}

}  // namespace triwalk
