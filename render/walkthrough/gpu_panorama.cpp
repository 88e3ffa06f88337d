#include "render/walkthrough/gpu_panorama.h"

#include "core/image/half_float.h"
#include "core/support/errors.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <limits>

namespace triwalk {

namespace {

constexpr int kTileSize = 32;  // pixels per tile side

void grow(glm::vec3& lower, glm::vec3& upper, bool& any, glm::vec3 p) {
  lower = any ? glm::min(lower, p) : p;
  upper = any ? glm::max(upper, p) : p;
  any = true;
}

// Appends each non-empty tile's indices to `indices` and returns the tiles,
// with the bounds of their vertices.
std::vector<PanoramaTile> appendTiles(const std::vector<std::vector<uint32_t>>& tileIndices, const WarpSource& source,
                                      std::vector<uint32_t>& indices) {
  std::vector<PanoramaTile> tiles;
  for (const std::vector<uint32_t>& list : tileIndices) {
    if (list.empty()) continue;
    PanoramaTile tile;
    tile.firstIndex = indices.size();
    tile.indexCount = GLsizei(list.size());
    for (uint32_t vertex : list) {
      if (source.atInfinity(vertex)) {
        grow(tile.directionLower, tile.directionUpper, tile.hasInfinite, source.point(vertex));
      } else {
        grow(tile.lower, tile.upper, tile.hasFinite, source.point(vertex));
      }
    }
    indices.insert(indices.end(), list.begin(), list.end());
    tiles.push_back(tile);
  }
  return tiles;
}

}  // namespace

size_t PreparedPanorama::bytes() const {
  return colorHalf.size() * sizeof(uint16_t) + distance.size() * sizeof(float) + vertices.size() * sizeof(glm::vec4) +
         (triangleIndices.size() + orphanIndices.size()) * sizeof(uint32_t);
}

PreparedPanorama preparePanorama(const Panorama& panorama, float yawRadians, const WarpSource& source,
                                 const WalkingMesh* walking) {
  PreparedPanorama prepared;
  prepared.width = panorama.width();
  prepared.height = panorama.height();
  const glm::vec3 position = source.position();
  prepared.position = position;
  prepared.yaw = yawRadians;
  const int width = prepared.width, height = prepared.height;
  // The mesh decisions (stretch test, orphans, poles, simplification) come
  // from the CPU reference itself, so both paths warp the same triangles.
  const bool simplified = source.mesh() == SourceMesh::Simplified;
  const size_t pixels = size_t(width) * size_t(height);

  // Converted as one array (the F16C instructions where the processor has
  // them: glm's one value at a time took 16 ms a 1024x512 reference), then
  // spread to RGBA; a view read from its EXR file holds halves already, so
  // the bits are the file's.
  std::vector<uint16_t> rgb(pixels * 3);
  floatsToHalves(std::span<const float>(&panorama.color.pixels[0].r, pixels * 3), rgb);
  // Alpha: 1 - the pixel's silhouette fringe flag, which the layer shaders
  // read with the colour (interpolated as it is) for the reliability.
  const uint16_t one = glm::packHalf1x16(1.0f), zero = glm::packHalf1x16(0.0f);
  const std::vector<uint8_t>& fringe = source.fringeFlags();
  prepared.colorHalf.resize(pixels * 4);
  for (size_t i = 0; i < pixels; ++i) {
    std::copy_n(&rgb[3 * i], 3, &prepared.colorHalf[4 * i]);
    prepared.colorHalf[4 * i + 3] = fringe[i] ? zero : one;
  }
  prepared.distance = panorama.distance.pixels;
  for (int pole = 0; pole < 2 && !simplified; ++pole) {
    const uint32_t vertex = uint32_t(pixels) + uint32_t(pole);
    prepared.poleColors[pole] = source.color(vertex);
    prepared.poleDistances[pole] = source.atInfinity(vertex) ? std::numeric_limits<float>::infinity()
                                                             : glm::length(source.point(vertex) - position);
  }

  // Kept triangles by tile: grid quads by their top-left pixel, simplified
  // triangles by their centroid's; then one tile for each pole fan.
  const int tilesX = (width + kTileSize - 1) / kTileSize, tilesY = (height - 1 + kTileSize - 1) / kTileSize;
  const uint32_t quadTriangles = 2 * uint32_t(width) * uint32_t(height - 1);
  const EquirectProjection projection{width, height, yawRadians};
  // A simplified triangle's tile is that of the sum of its vertices'
  // directions: each vertex's direction made once, the image points of
  // all the sums four at a time (the same bits as one at a time).
  std::vector<glm::vec3> directions;
  if (simplified) {
    directions.resize(source.vertexCount());
    for (uint32_t v = 0; v < source.vertexCount(); ++v) {
      directions[v] = source.atInfinity(v) ? source.point(v) : glm::normalize(source.point(v) - position);
    }
  }
  const auto simplifiedTiles = [&](std::span<const uint32_t> triangles) {
    std::vector<glm::vec3> sums(triangles.size() / 3);
    for (size_t t = 0; t < sums.size(); ++t) {
      const uint32_t* v = &triangles[3 * t];
      sums[t] = directions[v[0]] + directions[v[1]] + directions[v[2]];
    }
    std::vector<glm::vec2> points(sums.size());
    projection.imagePoints(sums, points);
    std::vector<size_t> tiles(points.size());
    for (size_t t = 0; t < points.size(); ++t) {
      const glm::vec2 p = points[t];
      tiles[t] =
          size_t(std::min(int(p.y), height - 2) / kTileSize * tilesX + std::min(int(p.x), width - 1) / kTileSize);
    }
    return tiles;
  };
  std::vector<size_t> meshTiles;
  if (simplified) {
    std::vector<uint32_t> triangles(size_t(source.triangleCount()) * 3);
    for (uint32_t t = 0; t < source.triangleCount(); ++t) source.triangleVertices(t, &triangles[3 * size_t(t)]);
    meshTiles = simplifiedTiles(triangles);
  }
  std::vector<std::vector<uint32_t>> tileIndices(size_t(tilesX * tilesY + 2));
  for (uint32_t t = 0; t < source.triangleCount(); ++t) {
    if (!source.triangleKept(t)) continue;
    uint32_t v[3];
    source.triangleVertices(t, v);
    size_t tile;
    if (simplified) {
      tile = meshTiles[t];
    } else if (t < quadTriangles) {
      const uint32_t quad = t / 2;
      tile = size_t(int(quad / uint32_t(width)) / kTileSize * tilesX + int(quad % uint32_t(width)) / kTileSize);
    } else {
      tile = size_t(tilesX * tilesY) + ((t - quadTriangles) < uint32_t(width) ? 0 : 1);
    }
    tileIndices[tile].insert(tileIndices[tile].end(), v, v + 3);
  }
  prepared.tiles = appendTiles(tileIndices, source, prepared.triangleIndices);
  if (walking) {
    TRIWALK_CHECK(simplified, "only a simplified reference has a walking mesh");
    std::vector<std::vector<uint32_t>> walkingIndices(tileIndices.size());
    const std::vector<size_t> walkingTiles = simplifiedTiles(walking->triangles);
    for (size_t t = 0; t < walkingTiles.size(); ++t) {
      const uint32_t* v = &walking->triangles[3 * t];
      std::vector<uint32_t>& list = walkingIndices[walkingTiles[t]];
      list.insert(list.end(), v, v + 3);
    }
    prepared.walkingTiles = appendTiles(walkingIndices, source, prepared.triangleIndices);
    prepared.walkingScale = walking->scale;
  }
  const uint32_t pixelVertices = simplified ? source.pixelVertexCount() : uint32_t(pixels);
  for (uint32_t v = 0; v < pixelVertices; ++v) {
    if (source.orphan(v)) prepared.orphanIndices.push_back(v);
  }
  if (simplified) {
    prepared.vertices.reserve(source.vertexCount());
    for (uint32_t v = 0; v < source.vertexCount(); ++v) {
      prepared.vertices.emplace_back(source.point(v), source.atInfinity(v) ? 0.0f : 1.0f);
    }
  }
  return prepared;
}

GpuPanorama::GpuPanorama(const PreparedPanorama& prepared)
    : width_(prepared.width),
      height_(prepared.height),
      position_(prepared.position),
      yaw_(prepared.yaw),
      orphanCount_(GLsizei(prepared.orphanIndices.size())),
      tiles_(prepared.tiles),
      walkingTiles_(prepared.walkingTiles),
      walkingScale_(prepared.walkingScale),
      poleDistances_(prepared.poleDistances),
      poleColors_{prepared.poleColors[0], prepared.poleColors[1]},
      bytes_(prepared.bytes()) {
  color_ = createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(color_.get(), 1, GL_RGBA16F, width_, height_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(color_.get(), 0, 0, 0, width_, height_, GL_RGBA, GL_HALF_FLOAT, prepared.colorHalf.data());
  distance_ = createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(distance_.get(), 1, GL_R32F, width_, height_);
  glTextureSubImage2D(distance_.get(), 0, 0, 0, width_, height_, GL_RED, GL_FLOAT, prepared.distance.data());
  auto upload = [](const std::vector<uint32_t>& values) {
    GlBuffer buffer = createBuffer();
    glNamedBufferStorage(buffer.get(), GLsizeiptr(std::max<size_t>(1, values.size()) * sizeof(uint32_t)),
                         values.empty() ? nullptr : values.data(), 0);
    return buffer;
  };
  triangles_ = upload(prepared.triangleIndices);
  orphans_ = upload(prepared.orphanIndices);
  if (!prepared.vertices.empty()) {
    vertices_ = createBuffer();
    glNamedBufferStorage(vertices_.get(), GLsizeiptr(prepared.vertices.size() * sizeof(glm::vec4)), prepared.vertices.data(), 0);
    // Looked up along source rays: bilinear, wrapping across the seam.
    glTextureParameteri(color_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(color_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(color_.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(color_.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
}

const std::vector<PanoramaTile>& GpuPanorama::tilesAt(float scale) const {
  // Frame scales are steps of a twentieth (FrameScaleController), not exact in binary.
  constexpr float kRounding = 1e-3f;
  return !walkingTiles_.empty() && scale <= walkingScale_ + kRounding ? walkingTiles_ : tiles_;
}

}  // namespace triwalk
