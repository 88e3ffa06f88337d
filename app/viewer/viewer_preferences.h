#pragma once
// What the viewer remembers between runs, per user: whether the tools
// sidebar is shown. Kept in $XDG_CONFIG_HOME/triwalk/viewer.json (else
// ~/.config/triwalk/viewer.json); without either variable nothing is kept.

#include <filesystem>
#include <optional>

namespace triwalk {

struct ViewerPreferences {
  bool sidebar = false;  // the scene fills the window at first start
};

std::optional<std::filesystem::path> viewerPreferencesPath();

// The preferences kept, or the defaults when there are none; a damaged
// file is said in one line and replaced at the next change.
ViewerPreferences readViewerPreferences();

// Written atomically; a failure is said in one line and the walk goes on.
void writeViewerPreferences(const ViewerPreferences& preferences);

}  // namespace triwalk
