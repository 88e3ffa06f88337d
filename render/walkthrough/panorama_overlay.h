#pragma once
// An equirectangular image (a sample's per-pixel reconstruction error)
// laid over a pinhole frame: each pixel of the viewport shows the image in
// its ray's direction, blended with the frame underneath. Exact for a
// camera at the panorama's position; near it, directions to far surfaces
// still agree (the viewer's error overlay, standing on or near a sample).

#include "core/geometry/projection.h"
#include "render/gl/gl_objects.h"
#include "render/gl/shader_program.h"

namespace triwalk {

class PanoramaOverlay {
public:
  PanoramaOverlay();

  // Into the bound framebuffer's viewport: texture is width x height,
  // row 0 at the top (up), its column 0 at yaw - 180 degrees
  // (core/geometry/projection.h); camera's size is ignored (the viewport's
  // aspect counts). opacity 1: the image alone.
  void draw(GLuint texture, glm::ivec2 size, float panoramaYawDegrees, const PinholeCamera& camera, float aspect,
            float opacity);

private:
  ShaderProgram program_;
  GlVertexArray vertexArray_;
  GlSampler sampler_;  // linear: the error panorama is far coarser than the frame
};

}  // namespace triwalk
