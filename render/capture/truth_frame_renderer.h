#pragma once
// The scene itself through a pinhole camera, drawn as the capture draws
// its cube faces (render/capture/scene_view_drawer.h): the truth a
// walkthrough frame is judged against (`render --truth`). Each pixel
// averages supersampling x supersampling samples in linear colour.
// Needs a current GL 4.5 context.

#include "core/geometry/projection.h"
#include "core/image/image.h"
#include "render/capture/scene_view_drawer.h"

namespace triwalk {

class TruthFrameRenderer {
public:
  TruthFrameRenderer(const Scene& scene, int width, int height, int supersampling = 2);

  // Linear colour, top row first; the camera's size must be the renderer's.
  ColorImage render(const PinholeCamera& camera);

private:
  SceneViewDrawer drawer_;
  int width_, height_, supersampling_;
  GlTexture color_, depth_;
  GlFramebuffer framebuffer_;
};

}  // namespace triwalk
