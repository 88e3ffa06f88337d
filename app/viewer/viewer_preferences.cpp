#include "app/viewer/viewer_preferences.h"

#include "core/io/atomic_file.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <exception>

namespace triwalk {

std::optional<std::filesystem::path> viewerPreferencesPath() {
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config) {
    return std::filesystem::path(config) / "triwalk" / "viewer.json";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".config" / "triwalk" / "viewer.json";
  }
  return std::nullopt;
}

ViewerPreferences readViewerPreferences() {
  ViewerPreferences preferences;
  const std::optional<std::filesystem::path> path = viewerPreferencesPath();
  if (!path || !std::filesystem::exists(*path)) return preferences;
  try {
    const nlohmann::json document = nlohmann::json::parse(readTextFile(*path, 1 << 16));
    preferences.sidebar = document.at("sidebar").get<bool>();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "triwalk: warning: %s: not the viewer's preferences (%s); using the defaults\n",
                 path->c_str(), error.what());
  }
  return preferences;
}

void writeViewerPreferences(const ViewerPreferences& preferences) {
  const std::optional<std::filesystem::path> path = viewerPreferencesPath();
  if (!path) return;
  try {
    std::filesystem::create_directories(path->parent_path());
    writeTextFileAtomically(*path, nlohmann::json{{"sidebar", preferences.sidebar}}.dump() + "\n");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "triwalk: warning: %s: preferences not kept (%s)\n", path->c_str(), error.what());
  }
}

}  // namespace triwalk
