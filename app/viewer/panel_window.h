#pragma once
// The window every viewer panel opens: placed and sized on first use (the
// person may move it after), skipped while collapsed.

#include <imgui.h>

namespace triwalk {

// True when the panel's contents should be drawn; then end it with
// ImGui::End(). False when collapsed (already ended).
bool beginPanelWindow(const char* title, ImVec2 position, ImVec2 size);

}  // namespace triwalk
