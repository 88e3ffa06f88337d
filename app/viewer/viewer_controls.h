#pragma once
// Every key and mouse control of the viewer, in one list: the help overlay
// (F1) and `view --help` both print it.

#include <span>
#include <string>

namespace triwalk {

struct ViewerControl {
  const char* keys;
  const char* action;
};

std::span<const ViewerControl> viewerControls();

// The list as lines "  KEYS  ACTION", for a command's help.
std::string describeViewerControls();

}  // namespace triwalk
