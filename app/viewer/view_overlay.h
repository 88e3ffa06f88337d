#pragma once
// What the 3D view can be coloured by besides the scene (T and E, or
// view --overlay): how much to trust each pixel (the GPU warp's trust
// colouring, shaders/warp_resolve.frag), or, standing on or near a
// captured sample, the per-pixel reconstruction error against its
// panorama (the paper's E; at a held-out probe, as Table 1 judges it; laid over the view: render/walkthrough/
// panorama_overlay.h). Each comes with its colour bar.

#include "core/io/dataset.h"

#include <glm/glm.hpp>
#include <imgui.h>

#include <string>

namespace triwalk {

enum class ViewOverlay { None, Trust, Error };

// The error overlay's view: the nearest within this distance of the walker.
constexpr double kErrorOverlayRadiusMetres = 0.5;

// A captured view the error overlay judges: a sample, or a held-out probe.
struct OverlayView {
  int index = -1;  // -1: none near
  bool probe = false;
  bool operator==(const OverlayView&) const = default;
};

// The sample or probe nearest to the walker within kErrorOverlayRadiusMetres.
OverlayView overlayView(const Dataset& dataset, glm::vec3 walker);
const ViewRecord& overlayViewRecord(const Dataset& dataset, OverlayView view);

// The colour bar and its caption at the bottom left of the view (x from
// 0 to viewWidth): trust from 0 to 1, or error from 0 to the inspection's
// heatmap scale; `note` is a line above it.
void drawOverlayLegend(ImDrawList* draw, ImVec2 display, float viewWidth, ViewOverlay overlay, const std::string& note);

}  // namespace triwalk
