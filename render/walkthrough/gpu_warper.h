#pragma once
// The GPU warp (docs/DESIGN.md, "Rendering"): the view of a pinhole camera from
// up to three reference panoramas. Each reference is drawn as its grid mesh
// into its own layer with a depth test (its nearest surface per pixel, as
// the CPU reference keeps one layer per source) and its reliability, in
// one packed target (shaders/warp_layer_texel.glsl); a
// full-screen resolve pass then blends the layers within epsilon * z_front
// with the inverse-distance weights times reliability into a linear image
// and the frame's display colours (holes marked, black, or left for the
// fill); the push-pull passes of the hole fill (core/synthesis/hole_fill.h)
// then fill the holes from the background, the last one on the hole pixels
// alone. Before the fill, pixels that none of the references saw may be
// resolved from up to three more (the neighbouring triangles' references,
// issue 71): drawn only when the frame has holes, inside their bounding
// box, into the holes alone, so that the fill paints only what no loaded
// reference saw. One geometry pass per reference (not two over
// all references) halves the triangles llvmpipe sets up, and matches the
// CPU reference exactly where a reference overlaps itself. Tiles of the
// reference grids outside the view frustum are not drawn.

#include "core/geometry/projection.h"
#include "core/image/image.h"
#include "core/synthesis/blend.h"
#include "core/synthesis/hole_fill.h"
#include "render/gl/gl_objects.h"
#include "render/gl/shader_program.h"
#include "render/walkthrough/gpu_panorama.h"

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace triwalk {

struct GpuWarpSettings {
  BlendOptions blend;
  HoleMode holes = HoleMode::Fill;
  bool showSources = false;  // red, green, blue: which references contributed (holes not filled)
  // How much to trust each pixel (shaders/warp_resolve.frag; holes black, not filled).
  bool showTrust = false;
  // Resolve the holes from the extra references given (render's fallback)
  // before the fill, in full-size frames; not with showSources or
  // showTrust, which show the triangle's own references.
  bool holesFromNeighbours = true;

  bool operator==(const GpuWarpSettings&) const = default;
};

struct GpuFrameStatistics {
  size_t tilesDrawn = 0, tilesCulled = 0;
  size_t trianglesDrawn = 0;
  // With timing requested (glFinish after each pass): milliseconds.
  std::array<double, 3> layerMilliseconds{};
  double resolveMilliseconds = 0.0;
  int fallbackDrawn = 0;              // extra references resolved into the holes
  double fallbackMilliseconds = 0.0;  // reading the hole mark back, their layers and resolve
  double fillMilliseconds = 0.0;  // push-pull passes; 0 when not filling
};

// Pixels of the last frame that were holes before the fill and are after.
struct GpuHoleCounts {
  size_t holesBefore = 0, unfilled = 0, pixels = 0;
};

class GpuWarper {
public:
  GpuWarper(int width, int height);
  void resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }

  // Renders into the output framebuffer; references: 1 to 3. frameScale:
  // the frame's share of the window's side (a walking frame below 1 may
  // draw the references' walking meshes, GpuPanorama::tilesAt). fallback:
  // up to 3 more, resolved into the holes the references leave (with
  // settings.holesFromNeighbours).
  GpuFrameStatistics render(const PinholeCamera& camera, std::span<const GpuPanorama* const> references,
                            const GpuWarpSettings& settings, bool timePasses = false, float frameScale = 1.0f,
                            std::span<const GpuPanorama* const> fallback = {});

  // The last frame, top row first.
  Rgb8Image readPixels() const;
  // Reads back the blended and the filled images (slow: for statistics).
  GpuHoleCounts countHoles() const;
  GLuint outputFramebuffer() const { return outputFramebuffer_.get(); }
  GLuint outputTexture() const { return output_.get(); }

private:
  // A rectangle of the frame in pixels (rows from the bottom, corners included).
  struct PixelBox {
    int x0, y0, x1, y1;
  };
  // Draws a reference's layer; within box, if given, only the tiles whose
  // bounds reach that part of the view.
  void drawLayer(const PinholeCamera& camera, const GpuPanorama& reference, int layer, float frameScale,
                 const PixelBox* box, GpuFrameStatistics& statistics);
  void fillHoles(float epsilon);
  // Draws the references' layers and resolves them: into every pixel, or
  // (holes given: their bounding box) into the holes the last resolve
  // marked, drawing and resolving inside that box alone.
  void drawAndResolve(const PinholeCamera& camera, std::span<const GpuPanorama* const> references,
                      const GpuWarpSettings& settings, const PixelBox* holes, bool timePasses, float frameScale,
                      GpuFrameStatistics& statistics);
  // The bounding box of the holes the last resolve marked; none without
  // holes. Reads the mark back: about 4 bytes a pixel, a copy on llvmpipe.
  std::optional<PixelBox> holeBounds();

  int width_ = 0, height_ = 0;
  ShaderProgram gridLayerProgram_, simplifiedLayerProgram_;
  ShaderProgram resolveProgram_;
  ShaderProgram pushProgram_, pullProgram_;
  std::array<GlTexture, 3> layers_;
  GlTexture layerDepth_;  // the layers' depth test
  GlTexture depth_;       // the resolve's hole mark (1 hole, 0.5 resolved from the fallback, 0 resolved)
  std::vector<float> holeMark_;  // depth_ read back (holeBounds)
  std::array<GlFramebuffer, 3> layerFramebuffers_;
  // Linear blend (rgb, inverse distance; -1 for holes), then the fill's
  // pyramid: pushed_[l] is level l + 1, pulled_[l] is level l filled (at
  // level 0 only the holes are written). The resolve's framebuffer also
  // writes output_ and marks holes in depth_; so does pulled level 0's.
  GlTexture blended_;
  GlFramebuffer blendedFramebuffer_;
  std::vector<GlTexture> pushed_, pulled_;
  std::vector<GlFramebuffer> pushedFramebuffers_, pulledFramebuffers_;
  std::vector<glm::ivec2> levelSizes_;  // level 0 is the frame
  bool lastFrameFilled_ = false;
  GlTexture output_;
  GlFramebuffer outputFramebuffer_;
  GlVertexArray vertexArray_;
};

}  // namespace triwalk
