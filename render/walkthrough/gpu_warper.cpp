#include "render/walkthrough/gpu_warper.h"

#include "core/support/errors.h"
#include "core/synthesis/warp.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <optional>
#include <vector>

namespace triwalk {

namespace {

// Whether an axis-aligned box may intersect the frustum of planes through
// the camera (normals pointing inside).
bool boxInside(const std::array<glm::vec3, 5>& normals, const std::array<float, 5>& offsets, glm::vec3 origin,
               glm::vec3 lower, glm::vec3 upper) {
  for (size_t i = 0; i < normals.size(); ++i) {
    const glm::vec3 n = normals[i];
    const glm::vec3 farthest(n.x >= 0.0f ? upper.x : lower.x, n.y >= 0.0f ? upper.y : lower.y, n.z >= 0.0f ? upper.z : lower.z);
    if (glm::dot(n, farthest - origin) < offsets[i]) return false;
  }
  return true;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

GpuWarper::GpuWarper(int width, int height)
    : gridLayerProgram_("warp_layer.vert", "warp_layer_grid.frag"),
      simplifiedLayerProgram_("warp_layer.vert", "warp_layer_simplified.frag"),
      resolveProgram_("fullscreen.vert", "warp_resolve.frag"),
      pushProgram_("fullscreen.vert", "fill_push.frag"),
      pullProgram_("fullscreen.vert", "fill_pull.frag") {
  vertexArray_ = createVertexArray();
  glVertexArrayAttribFormat(vertexArray_.get(), 0, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vertexArray_.get(), 0, 0);
  resize(width, height);
}

void GpuWarper::resize(int width, int height) {
  if (width == width_ && height == height_) return;
  width_ = width;
  height_ = height;
  depth_ = createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(depth_.get(), 1, GL_DEPTH_COMPONENT32F, width, height);
  layerDepth_ = createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(layerDepth_.get(), 1, GL_DEPTH_COMPONENT32F, width, height);
  for (size_t k = 0; k < layers_.size(); ++k) {
    layers_[k] = createTexture(GL_TEXTURE_2D);
    // Colour, 1 / distance and reliability packed (shaders/warp_layer_texel.glsl).
    glTextureStorage2D(layers_[k].get(), 1, GL_RGBA32UI, width, height);
    // An integer texture with a linear filter is incomplete (reads as 0).
    glTextureParameteri(layers_[k].get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(layers_[k].get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    layerFramebuffers_[k] = createFramebuffer();
    glNamedFramebufferTexture(layerFramebuffers_[k].get(), GL_COLOR_ATTACHMENT0, layers_[k].get(), 0);
    glNamedFramebufferTexture(layerFramebuffers_[k].get(), GL_DEPTH_ATTACHMENT, layerDepth_.get(), 0);
    requireCompleteFramebuffer(layerFramebuffers_[k], "warp layer");
  }
  output_ = createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(output_.get(), 1, GL_RGBA8, width, height);
  glTextureParameteri(output_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(output_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  outputFramebuffer_ = createFramebuffer();
  glNamedFramebufferTexture(outputFramebuffer_.get(), GL_COLOR_ATTACHMENT0, output_.get(), 0);
  requireCompleteFramebuffer(outputFramebuffer_, "warp output");

  // A linear image; at the frame's size its framebuffer also writes the
  // display colours into output_ and tests against (or writes) depth_.
  const auto linearImage = [&](glm::ivec2 size, GlTexture& texture, GlFramebuffer& framebuffer, const char* what) {
    texture = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.get(), 1, GL_RGBA16F, size.x, size.y);
    framebuffer = createFramebuffer();
    glNamedFramebufferTexture(framebuffer.get(), GL_COLOR_ATTACHMENT0, texture.get(), 0);
    if (size == glm::ivec2(width, height)) {
      glNamedFramebufferTexture(framebuffer.get(), GL_COLOR_ATTACHMENT1, output_.get(), 0);
      glNamedFramebufferTexture(framebuffer.get(), GL_DEPTH_ATTACHMENT, depth_.get(), 0);
      const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
      glNamedFramebufferDrawBuffers(framebuffer.get(), 2, buffers);
    }
    requireCompleteFramebuffer(framebuffer, what);
  };
  linearImage({width, height}, blended_, blendedFramebuffer_, "blend");
  levelSizes_.assign(1, {width, height});
  while (levelSizes_.back().x > 1 || levelSizes_.back().y > 1) levelSizes_.push_back((levelSizes_.back() + 1) / 2);
  const size_t levels = levelSizes_.size();
  pushed_.resize(levels - 1);
  pushedFramebuffers_.resize(levels - 1);
  pulled_.resize(levels - 1);
  pulledFramebuffers_.resize(levels - 1);
  for (size_t l = 0; l + 1 < levels; ++l) {
    linearImage(levelSizes_[l + 1], pushed_[l], pushedFramebuffers_[l], "hole fill push level");
    linearImage(levelSizes_[l], pulled_[l], pulledFramebuffers_[l], "hole fill pull level");
  }
}

void GpuWarper::drawLayer(const PinholeCamera& camera, const GpuPanorama& reference, int layer, float frameScale,
                          const PixelBox* box, GpuFrameStatistics& statistics) {
  glBindFramebuffer(GL_FRAMEBUFFER, layerFramebuffers_[size_t(layer)].get());
  // 1 / distance -1: uncovered (warpLayerTexel).
  const GLuint uncovered[4] = {0u, 0u, std::bit_cast<GLuint>(-1.0f), 0u};
  glClearNamedFramebufferuiv(layerFramebuffers_[size_t(layer)].get(), GL_COLOR, 0, uncovered);
  const float farDepth = 0.0f;
  glClearNamedFramebufferfv(layerFramebuffers_[size_t(layer)].get(), GL_DEPTH, 0, &farDepth);

  // A simplified mesh's vertices come from its buffer; the grid's from the
  // distance texture (an enabled attribute without a buffer is an error).
  const bool explicitVertices = reference.vertexBuffer() != 0;
  ShaderProgram& layerProgram = explicitVertices ? simplifiedLayerProgram_ : gridLayerProgram_;
  layerProgram.use();
  layerProgram.set("panoramaSize", glm::ivec2(reference.width(), reference.height()));
  layerProgram.set("explicitVertices", explicitVertices ? 1 : 0);
  if (explicitVertices) {
    glVertexArrayVertexBuffer(vertexArray_.get(), 0, reference.vertexBuffer(), 0, GLsizei(sizeof(glm::vec4)));
    glEnableVertexArrayAttrib(vertexArray_.get(), 0);
  } else {
    glDisableVertexArrayAttrib(vertexArray_.get(), 0);
  }
  layerProgram.set("panoramaYaw", reference.yaw());
  layerProgram.set("sourcePosition", reference.position());
  layerProgram.set("poleDistances", reference.poleDistances());
  const glm::vec3 poleColors[2] = {reference.poleColor(0), reference.poleColor(1)};
  layerProgram.setArray("poleColors", poleColors, 2);
  glBindTextureUnit(0, reference.colorTexture());
  glBindTextureUnit(1, reference.distanceTexture());

  // Frustum planes through the camera, normals inside: four sides (the
  // frame's, or the box's: the sides at normalized device coordinates
  // a0 <= a <= a1, b0 <= b <= b1) and the near plane.
  const glm::vec3 f = camera.forward(), r = camera.right(), u = camera.up();
  const float tanY = camera.tanHalfFovY(), tanX = tanY * camera.aspect();
  float a0 = -1.0f, a1 = 1.0f, b0 = -1.0f, b1 = 1.0f;
  if (box) {
    a0 = 2.0f * float(box->x0) / float(width_) - 1.0f, a1 = 2.0f * float(box->x1 + 1) / float(width_) - 1.0f;
    b0 = 2.0f * float(box->y0) / float(height_) - 1.0f, b1 = 2.0f * float(box->y1 + 1) / float(height_) - 1.0f;
  }
  const std::array<glm::vec3, 5> normals = {f * (a1 * tanX) - r, r - f * (a0 * tanX), f * (b1 * tanY) - u,
                                            u - f * (b0 * tanY), f};
  const std::array<float, 5> pointOffsets = {0.0f, 0.0f, 0.0f, 0.0f, kPinholeNearPlane};
  const std::array<float, 5> directionOffsets = {0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  std::vector<GLsizei> counts;
  std::vector<const void*> offsets;
  for (const PanoramaTile& tile : reference.tilesAt(frameScale)) {
    const bool visible =
        (tile.hasFinite && boxInside(normals, pointOffsets, camera.position, tile.lower, tile.upper)) ||
        (tile.hasInfinite && boxInside(normals, directionOffsets, glm::vec3(0.0f), tile.directionLower, tile.directionUpper));
    if (!visible) {
      ++statistics.tilesCulled;
      continue;
    }
    ++statistics.tilesDrawn;
    statistics.trianglesDrawn += size_t(tile.indexCount / 3);
    counts.push_back(tile.indexCount);
    offsets.push_back(reinterpret_cast<const void*>(tile.firstIndex * sizeof(uint32_t)));
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, reference.triangleIndices());
  if (!counts.empty()) {
    glMultiDrawElements(GL_TRIANGLES, counts.data(), GL_UNSIGNED_INT, offsets.data(), GLsizei(counts.size()));
  }
  // Vertices whose every triangle was dropped, as single points (as the CPU).
  if (reference.orphanCount() > 0) {
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, reference.orphanIndices());
    glDrawElements(GL_POINTS, reference.orphanCount(), GL_UNSIGNED_INT, nullptr);
  }
}

GpuFrameStatistics GpuWarper::render(const PinholeCamera& camera, std::span<const GpuPanorama* const> references,
                                     const GpuWarpSettings& settings, bool timePasses, float frameScale,
                                     std::span<const GpuPanorama* const> fallback) {
  TRIWALK_CHECK(!references.empty() && references.size() <= 3, "the warp takes one to three references");
  TRIWALK_CHECK(fallback.size() <= 3, "the holes pass takes up to three references");
  TRIWALK_CHECK(camera.width == width_ && camera.height == height_, "camera size differs from the warper's");
  GpuFrameStatistics statistics;
  glViewport(0, 0, width_, height_);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(vertexArray_.get());
  drawAndResolve(camera, references, settings, nullptr, timePasses, frameScale, statistics);

  const bool showsReferences = settings.showSources || settings.showTrust;
  // Full-size frames only: the extra layers' vertex work does not shrink
  // with the frame, and in walking frames (drawn at a fraction of each side
  // to hold the frame budget) it took the viewer's walk on llvmpipe from
  // 27 to 40 ms median, over the 33 ms budget. A still frame (the walker
  // stopped, render, screenshots) is full size and gets the neighbours.
  const bool fullSize = frameScale >= 1.0f;
  if (settings.holesFromNeighbours && fullSize && !showsReferences && !fallback.empty()) {
    const auto fallbackStart = std::chrono::steady_clock::now();
    if (const std::optional<PixelBox> holes = holeBounds()) {
      GpuFrameStatistics extra;
      drawAndResolve(camera, fallback, settings, &*holes, false, frameScale, extra);
      statistics.fallbackDrawn = int(fallback.size());
      statistics.tilesDrawn += extra.tilesDrawn;
      statistics.tilesCulled += extra.tilesCulled;
      statistics.trianglesDrawn += extra.trianglesDrawn;
    }
    if (timePasses) {
      glFinish();
      statistics.fallbackMilliseconds = millisecondsSince(fallbackStart);
    }
  }

  lastFrameFilled_ = settings.holes == HoleMode::Fill && !showsReferences && levelSizes_.size() > 1;
  if (lastFrameFilled_) {
    const auto fillStart = std::chrono::steady_clock::now();
    fillHoles(settings.blend.epsilon);
    if (timePasses) {
      glFinish();
      statistics.fillMilliseconds = millisecondsSince(fillStart);
    }
  }
  glViewport(0, 0, width_, height_);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindVertexArray(0);
  return statistics;
}

void GpuWarper::drawAndResolve(const PinholeCamera& camera, std::span<const GpuPanorama* const> references,
                               const GpuWarpSettings& settings, const PixelBox* holes, bool timePasses, float frameScale,
                               GpuFrameStatistics& statistics) {
  const bool holesOnly = holes != nullptr;
  // The holes pass draws inside their box alone: the layers are cleared,
  // drawn and resolved there, and its tiles culled to that part of the view.
  if (holes) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(holes->x0, holes->y0, holes->x1 - holes->x0 + 1, holes->y1 - holes->y0 + 1);
  }
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_GEQUAL);  // reversed depth; sky at exactly 0 still draws
  for (ShaderProgram* layerProgram : {&gridLayerProgram_, &simplifiedLayerProgram_}) {
    layerProgram->use();
    layerProgram->set("colorTexture", 0);
    layerProgram->set("distanceTexture", 1);
    layerProgram->set("viewProjection", pinholeViewProjection(camera, kPinholeNearPlane));
    layerProgram->set("cameraPosition", camera.position);
  }
  for (size_t k = 0; k < references.size(); ++k) {
    if (timePasses) glFinish();
    const auto start = std::chrono::steady_clock::now();
    drawLayer(camera, *references[k], int(k), frameScale, holes, statistics);
    if (timePasses) {
      glFinish();
      statistics.layerMilliseconds[k] = millisecondsSince(start);
    }
  }
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);

  const auto resolveStart = std::chrono::steady_clock::now();
  glBindFramebuffer(GL_FRAMEBUFFER, blendedFramebuffer_.get());
  // Depth writes need the test on: every pixel writes its hole mark; the
  // holes pass writes only where the mark is a hole (see warp_resolve.frag).
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(holesOnly ? GL_LEQUAL : GL_ALWAYS);
  resolveProgram_.use();
  std::vector<glm::vec3> positions;
  for (const GpuPanorama* reference : references) positions.push_back(reference->position());
  const std::vector<float> weights = blendWeights(camera.position, positions, settings.blend);
  glm::vec3 weightVector(0.0f);
  for (size_t k = 0; k < weights.size(); ++k) weightVector[int(k)] = weights[k];
  for (int k = 0; k < 3; ++k) {
    const std::string layer = "layer" + std::to_string(k);
    resolveProgram_.set(layer.c_str(), 2 + k);
    glBindTextureUnit(GLuint(2 + k), layers_[size_t(k)].get());
  }
  resolveProgram_.set("layerCount", int(references.size()));
  resolveProgram_.set("weights", weightVector);
  resolveProgram_.set("reliabilityWeights", settings.blend.weights == BlendWeights::Reliability ? 1 : 0);
  resolveProgram_.set("epsilon", settings.blend.epsilon);
  resolveProgram_.set("showSources", settings.showSources ? 1 : 0);
  resolveProgram_.set("showTrust", settings.showTrust ? 1 : 0);
  resolveProgram_.set("holesOnly", holesOnly ? 1 : 0);
  resolveProgram_.set("holeColor", settings.showTrust ? glm::vec3(0.0f) : holeDisplayColor(settings.holes));
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_SCISSOR_TEST);
  if (timePasses) {
    glFinish();
    statistics.resolveMilliseconds = millisecondsSince(resolveStart);
  }
}

std::optional<GpuWarper::PixelBox> GpuWarper::holeBounds() {
  holeMark_.resize(size_t(width_) * size_t(height_));
  glGetTextureImage(depth_.get(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(holeMark_.size() * sizeof(float)),
                    holeMark_.data());
  PixelBox box{width_, height_, -1, -1};
  for (int y = 0; y < height_; ++y) {
    const float* row = holeMark_.data() + size_t(y) * size_t(width_);
    for (int x = 0; x < width_; ++x) {
      if (row[x] < 1.0f) continue;
      box.x0 = std::min(box.x0, x), box.x1 = std::max(box.x1, x);
      box.y0 = std::min(box.y0, y), box.y1 = std::max(box.y1, y);
    }
  }
  if (box.x1 < 0) return std::nullopt;
  return box;
}

void GpuWarper::fillHoles(float epsilon) {
  const size_t levels = levelSizes_.size();
  pushProgram_.use();
  pushProgram_.set("finer", 2);
  pushProgram_.set("epsilon", epsilon);
  for (size_t l = 0; l + 1 < levels; ++l) {
    glViewport(0, 0, levelSizes_[l + 1].x, levelSizes_[l + 1].y);
    glBindFramebuffer(GL_FRAMEBUFFER, pushedFramebuffers_[l].get());
    glBindTextureUnit(2, l == 0 ? blended_.get() : pushed_[l - 1].get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  pullProgram_.use();
  pullProgram_.set("level", 2);
  pullProgram_.set("coarser", 3);
  pullProgram_.set("epsilon", epsilon);
  for (size_t l = levels - 1; l-- > 0;) {
    glViewport(0, 0, levelSizes_[l].x, levelSizes_[l].y);
    glBindFramebuffer(GL_FRAMEBUFFER, pulledFramebuffers_[l].get());
    glBindTextureUnit(2, l == 0 ? blended_.get() : pushed_[l - 1].get());
    glBindTextureUnit(3, l + 2 == levels ? pushed_[l].get() : pulled_[l + 1].get());
    if (l == 0) {
      // The full-screen triangle lies at depth 0.5: it passes where the
      // resolve marked a hole (1) and nowhere else (0).
      glEnable(GL_DEPTH_TEST);
      glDepthMask(GL_FALSE);
    }
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
}

GpuHoleCounts GpuWarper::countHoles() const {
  GpuHoleCounts counts;
  counts.pixels = size_t(width_) * size_t(height_);
  std::vector<glm::vec4> blended(counts.pixels);
  glGetTextureImage(blended_.get(), 0, GL_RGBA, GL_FLOAT, GLsizei(blended.size() * sizeof(glm::vec4)), blended.data());
  counts.holesBefore = size_t(std::count_if(blended.begin(), blended.end(), [](const glm::vec4& t) { return t.a < 0.0f; }));
  counts.unfilled = counts.holesBefore;
  if (lastFrameFilled_) {
    // Pulled level 0 holds the fill at the holes (and stale texels elsewhere).
    std::vector<glm::vec4> filled(counts.pixels);
    glGetTextureImage(pulled_[0].get(), 0, GL_RGBA, GL_FLOAT, GLsizei(filled.size() * sizeof(glm::vec4)), filled.data());
    counts.unfilled = 0;
    for (size_t i = 0; i < counts.pixels; ++i) counts.unfilled += blended[i].a < 0.0f && filled[i].a < 0.0f;
  }
  return counts;
}

Rgb8Image GpuWarper::readPixels() const {
  Rgb8Image image(width_, height_);
  std::vector<glm::u8vec3> rows(image.pixelCount());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, outputFramebuffer_.get());
  glNamedFramebufferReadBuffer(outputFramebuffer_.get(), GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  // OpenGL's first row is the bottom one.
  for (int y = 0; y < height_; ++y) {
    std::copy_n(rows.begin() + ptrdiff_t(size_t(height_ - 1 - y) * size_t(width_)), width_,
                image.pixels.begin() + ptrdiff_t(size_t(y) * size_t(width_)));
  }
  return image;
}

}  // namespace triwalk
