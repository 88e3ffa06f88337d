// Top view: the walkable region's walls, every sample, the current
// triangulation colored by triangle error (with a legend), the person and
// where they look, the triangle they stand in; a click goes there and
// selects the triangle for the inspector.

#include "app/viewer/sidebar.h"
#include "app/viewer/viewer_state.h"
#include "core/geometry/walk_constraint.h"
#include "core/geometry/walkable_region.h"
#include "core/image/color.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace triwalk {

namespace {

constexpr float kErrorScale = 3.0f;  // E shown red

ImU32 toImColor(glm::vec3 color, float alpha = 1.0f) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(color.r, color.g, color.b, alpha));
}

}  // namespace

void drawMapPanel(ViewerState& state) {
  if (!beginSidebarSection("Map")) return;
  const Dataset& dataset = *state.dataset;
  glm::vec2 lower(1e30f), upper(-1e30f);
  for (int i = 0; i < dataset.sampleCount(); ++i) {
    lower = glm::min(lower, glm::vec2(dataset.sample(i).position));
    upper = glm::max(upper, glm::vec2(dataset.sample(i).position));
  }
  const glm::vec2 margin = 0.05f * (upper - lower) + 0.2f;
  lower -= margin;
  upper += margin;

  // As wide as the sidebar, as high as the samples' extent asks (within
  // reason), so that the sections below stay in sight.
  const float width = std::max(ImGui::GetContentRegionAvail().x, 50.0f);
  const ImVec2 canvasSize(width, std::clamp(width * (upper.y - lower.y) / (upper.x - lower.x), 120.0f, 320.0f));
  const float scale = std::min(canvasSize.x / (upper.x - lower.x), canvasSize.y / (upper.y - lower.y));
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("map", canvasSize);
  const bool clicked = ImGui::IsItemClicked();
  // World x right, y up.
  auto toScreen = [&](glm::vec2 p) {
    return ImVec2(origin.x + (p.x - lower.x) * scale, origin.y + canvasSize.y - (p.y - lower.y) * scale);
  };
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, ImVec2(origin.x + canvasSize.x, origin.y + canvasSize.y), IM_COL32(25, 25, 30, 255));
  // The walkable region's walls: where the walker may go, triangles or not.
  if (const auto& region = state.mesh.region()) {
    std::vector<ImVec2> points;
    auto wall = [&](const Ring& ring) {
      points.clear();
      for (glm::dvec2 p : ring) points.push_back(toScreen(glm::vec2(p)));
      draw->AddPolyline(points.data(), int(points.size()), IM_COL32(150, 140, 110, 255), ImDrawFlags_Closed, 1.5f);
    };
    for (const RegionPolygon& polygon : region->polygons()) {
      wall(polygon.outer);
      for (const Ring& hole : polygon.holes) wall(hole);
    }
  }

  const std::vector<Triangle>& triangles = state.mesh.triangles();
  for (size_t t = 0; t < triangles.size(); ++t) {
    const ImVec2 a = toScreen(state.mesh.position(triangles[t][0])), b = toScreen(state.mesh.position(triangles[t][1])),
                 c = toScreen(state.mesh.position(triangles[t][2]));
    const bool known = t < state.snapshot.triangleErrors.size() && !std::isnan(state.snapshot.triangleErrors[t]) &&
                       state.snapshot.triangles.size() == triangles.size();
    const ImU32 fill = known ? toImColor(falseColor(float(state.snapshot.triangleErrors[t]) / kErrorScale), 0.85f)
                             : IM_COL32(90, 90, 90, 200);
    draw->AddTriangleFilled(a, b, c, fill);
    draw->AddTriangle(a, b, c, IM_COL32(20, 20, 20, 255), 1.0f);
  }
  auto outline = [&](int t, ImU32 color, float thickness) {
    if (t < 0 || t >= int(triangles.size())) return;
    draw->AddTriangle(toScreen(state.mesh.position(triangles[size_t(t)][0])), toScreen(state.mesh.position(triangles[size_t(t)][1])),
                      toScreen(state.mesh.position(triangles[size_t(t)][2])), color, thickness);
  };
  outline(state.selectedTriangle, IM_COL32(0, 230, 255, 255), 3.0f);
  outline(state.currentTriangle, IM_COL32(255, 230, 0, 255), 2.5f);
  for (int i = 0; i < dataset.sampleCount(); ++i) draw->AddCircleFilled(toScreen(glm::vec2(dataset.sample(i).position)), 1.5f, IM_COL32(150, 150, 150, 255));
  for (int v : state.mesh.vertices()) draw->AddCircleFilled(toScreen(glm::vec2(state.mesh.position(v))), 3.5f, IM_COL32(255, 255, 255, 255));
  for (int r : state.references) {
    if (r >= 0) draw->AddCircle(toScreen(glm::vec2(state.mesh.position(r))), 6.0f, IM_COL32(80, 255, 80, 255), 12, 2.0f);
  }
  // The person and the view frustum.
  const ImVec2 here = toScreen(glm::vec2(state.walk.position));
  const float aspect = 16.0f / 9.0f;
  const float halfHorizontal = std::atan(std::tan(glm::radians(state.verticalFovDegrees) * 0.5f) * aspect);
  for (float side : {-1.0f, 1.0f}) {
    const float angle = glm::radians(state.walk.yawDegrees) + side * halfHorizontal;
    draw->AddLine(here, toScreen(glm::vec2(state.walk.position) + 1.2f * glm::vec2(std::cos(angle), std::sin(angle))),
                  IM_COL32(255, 80, 80, 200), 1.5f);
  }
  const float yaw = glm::radians(state.walk.yawDegrees);
  draw->AddLine(here, toScreen(glm::vec2(state.walk.position) + 0.8f * glm::vec2(std::cos(yaw), std::sin(yaw))),
                IM_COL32(255, 60, 60, 255), 3.0f);
  draw->AddCircleFilled(here, 5.0f, IM_COL32(255, 60, 60, 255));

  if (clicked) {
    const ImVec2 mouse = ImGui::GetMousePos();
    const glm::dvec2 world(lower.x + (mouse.x - origin.x) / scale, lower.y + (origin.y + canvasSize.y - mouse.y) / scale);
    // Go there, where a walker may stand, and inspect the triangle there.
    if (isWalkable(state.mesh, world)) {
      state.walk.position = glm::vec3(glm::vec2(world), state.walk.position.z);
      state.walkPath.playingSince.reset();
    }
    const int t = state.mesh.locate(world);
    if (t >= 0 && state.mesh.contains(t, world)) {
      state.selectedTriangle = t;
      state.session->inspect(triangles[size_t(t)]);
    }
  }

  // Legend: triangle error from 0 to kErrorScale.
  const ImVec2 legend = ImGui::GetCursorScreenPos();
  const float legendWidth = std::min(canvasSize.x - 120.0f, 220.0f);
  for (int i = 0; i < 32; ++i) {
    const float x0 = legend.x + legendWidth * float(i) / 32.0f, x1 = legend.x + legendWidth * float(i + 1) / 32.0f;
    draw->AddRectFilled(ImVec2(x0, legend.y + 4), ImVec2(x1, legend.y + 16), toImColor(falseColor(float(i) / 31.0f)));
  }
  char label[96];
  std::snprintf(label, sizeof label, "triangle error E: 0 .. %.0f", kErrorScale);
  draw->AddText(ImVec2(legend.x + legendWidth + 8, legend.y + 2), IM_COL32(230, 230, 230, 255), label);
  ImGui::Dummy(ImVec2(canvasSize.x, 20));
  if (state.selectedTriangle < 0) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("Click the map to go there and inspect how the triangle's panoramas reconstruct a view.");
    ImGui::PopTextWrapPos();
  }
}

}  // namespace triwalk
