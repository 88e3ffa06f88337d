#include "app/viewer/viewer_controls.h"

#include <array>
#include <cstdio>

namespace triwalk {

namespace {

constexpr std::array kControls = {
    ViewerControl{"W A S D, arrow keys", "walk forward, left, back, right (within the walkable region)"},
    ViewerControl{"Shift", "walk three times as fast"},
    ViewerControl{"drag (left or right button)", "look around"},
    ViewerControl{"Tab", "show or hide the tools (remembered between runs)"},
    ViewerControl{"F1 or ?", "show or hide this list"},
    ViewerControl{"F12", "save a screenshot of the window (triwalk_screenshot_NNN.png)"},
    ViewerControl{"click on the map", "inspect that triangle: its reconstruction, the truth and the error"},
};

}  // namespace

std::span<const ViewerControl> viewerControls() { return kControls; }

std::string describeViewerControls() {
  std::string text = "Controls:\n";
  for (const ViewerControl& control : kControls) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-28s %s\n", control.keys, control.action);
    text += line;
  }
  return text;
}

}  // namespace triwalk
