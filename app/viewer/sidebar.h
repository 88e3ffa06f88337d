#pragma once
// The viewer's tools live in one sidebar at the window's right edge, the
// 3D view beside it (never under it); Tab shows and hides the sidebar.
// Each panel is a section of it that the person can fold.

#include <imgui.h>

namespace triwalk {

// The sidebar's width for a window of this size, in ImGui's units.
float sidebarWidth(ImVec2 display);

// Opens the sidebar window; end it with ImGui::End().
void beginSidebar(ImVec2 display);

// True when the section is unfolded and its contents should be drawn
// (no End needed).
bool beginSidebarSection(const char* title);

}  // namespace triwalk
