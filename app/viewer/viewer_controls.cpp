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
    ViewerControl{"N, B", "step to the nearest reference ahead, behind (stand where its panorama was taken)"},
    ViewerControl{"click on the map", "go there, and inspect that triangle: its reconstruction, the truth and the error"},
    ViewerControl{"T", "colour the view by trust: how many references agree on each pixel, how well they saw it"},
    ViewerControl{"E", "near a sample or held-out probe: the per-pixel error of its reconstruction against it"},
    ViewerControl{"R", "record the walk; again: stop and save it (the Walk tools' file, walk.txt)"},
    ViewerControl{"P", "play the walk in real time; again: stop"},
    ViewerControl{"V", "export the walk as a video at the window's size (the Walk tools' file, walk.mp4)"},
    ViewerControl{"Esc", "stop playing, or cancel a video export"},
    ViewerControl{"F12", "save a screenshot of the window (triwalk_screenshot_NNN.png)"},
    ViewerControl{"Ctrl+Q", "quit (a recording still going is saved)"},
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
