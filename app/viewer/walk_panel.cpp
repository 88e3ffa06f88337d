// Walks: record (R), play (P), save and load the camera path file, and
// export the walk as a video; what was done last, or why it failed.

#include "app/viewer/sidebar.h"
#include "app/viewer/viewer_state.h"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace triwalk {

void drawWalkPanel(ViewerState& state) {
  if (!beginSidebarSection("Walk")) return;
  WalkRecording& walk = state.walkPath;
  if (walk.recordingSince) {
    ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "recording: %.1f s, %zu poses", state.clock - *walk.recordingSince,
                       walk.recording.poses.size());
  }
  if (walk.path.poses.empty()) {
    ImGui::TextDisabled("no walk yet: R records one");
  } else {
    ImGui::Text("walk (%s): %zu pose%s, %.1f s", walk.source.c_str(), walk.path.poses.size(),
                walk.path.poses.size() == 1 ? "" : "s", pathDuration(walk.path, kPathFramesPerSecond));
  }
  if (ImGui::Button(walk.recordingSince ? "stop recording (R)" : "record (R)")) toggleRecording(walk, state.clock);
  ImGui::SameLine();
  if (ImGui::Button(walk.playingSince ? "stop (P)" : "play (P)")) togglePlayback(walk, state.clock);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
  ImGui::InputText("##walk file", &walk.file);
  ImGui::SameLine();
  if (ImGui::Button("save")) saveWalk(walk);
  ImGui::SameLine();
  if (ImGui::Button("load")) loadWalk(walk);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
  ImGui::InputText("##video file", &walk.videoFile);
  ImGui::SameLine();
  if (state.exportFrames > 0) {
    ImGui::ProgressBar(float(state.exportFrame) / float(state.exportFrames), ImVec2(-1.0f, 0.0f));
  } else if (ImGui::Button("export video (V)")) {
    state.exportRequested = true;
  }
  if (!walk.message.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(walk.message.c_str());
    ImGui::PopTextWrapPos();
  }
}

}  // namespace triwalk
