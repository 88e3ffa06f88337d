#pragma once
// What the 3D view can be coloured by besides the scene (T and E, or
// view --overlay): how much to trust each pixel (the GPU warp's trust
// colouring, shaders/warp_resolve.frag), or, standing on or near a
// captured sample, the per-pixel reconstruction error against its
// panorama (the paper's E, laid over the view: render/walkthrough/
// panorama_overlay.h). Each comes with its colour bar.

#include "core/io/dataset.h"

#include <glm/glm.hpp>
#include <imgui.h>

#include <string>

namespace triwalk {

enum class ViewOverlay { None, Trust, Error };

// The error overlay's sample: the nearest within this distance of the walker.
constexpr double kErrorOverlayRadiusMetres = 0.5;

// The sample nearest to the walker within kErrorOverlayRadiusMetres, else -1.
int overlaySample(const Dataset& dataset, glm::vec3 walker);

// The colour bar and its caption at the bottom left of the view (x from
// 0 to viewWidth): trust from 0 to 1, or error from 0 to the inspection's
// heatmap scale; `note` is a line above it.
void drawOverlayLegend(ImDrawList* draw, ImVec2 display, float viewWidth, ViewOverlay overlay, const std::string& note);

}  // namespace triwalk
