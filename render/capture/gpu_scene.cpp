#include "render/capture/gpu_scene.h"

#include "render/gl/shader_program.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace triwalk {

namespace {

// The most indices one draw of a face's triangles holds. On llvmpipe a
// draw with a triangle to clip (one reaching behind the eye: most draws
// of a face) runs through Mesa's draw pipeline, whose output buffer holds
// 4 KiB of vertices, a few dozen; at each flush of it, every vertex the
// draw fetched is marked unemitted again, so a draw's cost grows with the
// square of its size. A region probe's faces are 16 pixels wide, so that
// loop was the largest single part of the region search (15% of its CPU
// on oacmpdm1). Draws of 32 triangles, all given in one call, bound it; a
// full capture, bound by its fragments, takes as long either way
// (docs/history/BENCHMARKS-2026-11.md, "the region search's draws in runs of 32 triangles").
constexpr size_t kIndicesPerDraw = 96;
static_assert(kIndicesPerDraw % 3 == 0, "whole triangles");

GlTexture uploadTexture(const SceneTexture& texture) {
  GlTexture name = createTexture(GL_TEXTURE_2D);
  const int levels = 1 + int(std::floor(std::log2(float(std::max(texture.width, texture.height)))));
  glTextureStorage2D(name.get(), levels, GL_SRGB8_ALPHA8, texture.width, texture.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(name.get(), 0, 0, 0, texture.width, texture.height, GL_RGBA, GL_UNSIGNED_BYTE,
                      texture.rgba.data());
  glGenerateTextureMipmap(name.get());
  glTextureParameteri(name.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(name.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(name.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(name.get(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  // Trilinear only: llvmpipe's anisotropic filtering (Mesa 22.3) took 80 s
  // for a single cube face at some viewpoints. The capture's 2x2
  // supersampling provides the anti-aliasing instead.
  return name;
}

bool opaque(const SceneTexture& texture) {
  for (size_t i = 3; i < texture.rgba.size(); i += 4) {
    if (texture.rgba[i] != 255) return false;
  }
  return true;
}

}  // namespace

GpuScene::GpuScene(const Scene& scene) : materials_(scene.materials) {
  std::vector<bool> opaqueTextures;  // many materials share a texture: each is read once
  for (const SceneTexture& texture : scene.textures) {
    textures_.push_back(uploadTexture(texture));
    opaqueTextures.push_back(opaque(texture));
  }
  for (const SceneMaterial& material : materials_) {
    const bool textureAlpha = material.diffuseTexture >= 0 && !opaqueTextures[size_t(material.diffuseTexture)];
    discards_.push_back(!material.alphaTest       ? Discard::Never
                        : textureAlpha            ? Discard::ByTexture
                        : material.useVertexColor ? Discard::ByVertexAlpha
                                                  : Discard::Never);
  }

  std::vector<SceneVertex> vertices;
  for (const SceneMesh& mesh : scene.meshes) {
    const uint32_t base = uint32_t(vertices.size());
    ranges_.push_back({mesh.material, indices_.size(), GLsizei(mesh.indices.size())});
    vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
    for (uint32_t index : mesh.indices) indices_.push_back(base + index);
  }
  triangleCount_ = indices_.size() / 3;
  std::stable_sort(ranges_.begin(), ranges_.end(),
                   [](const DrawRange& a, const DrawRange& b) { return a.material < b.material; });
  positions_.reserve(vertices.size());
  for (const SceneVertex& vertex : vertices) positions_.push_back(vertex.position);

  vertices_ = createBuffer();
  glNamedBufferStorage(vertices_.get(), GLsizeiptr(std::max<size_t>(1, vertices.size()) * sizeof(SceneVertex)),
                       vertices.empty() ? nullptr : vertices.data(), 0);
  faceIndexBuffer_ = createBuffer();

  vertexArray_ = createVertexArray();
  const GLuint vao = vertexArray_.get();
  glVertexArrayVertexBuffer(vao, 0, vertices_.get(), 0, sizeof(SceneVertex));
  glVertexArrayElementBuffer(vao, faceIndexBuffer_.get());
  struct Attribute {
    GLuint location;
    GLint components;
    size_t offset;
  };
  const Attribute attributes[] = {{0, 3, offsetof(SceneVertex, position)},
                                  {1, 3, offsetof(SceneVertex, normal)},
                                  {2, 2, offsetof(SceneVertex, uv)},
                                  {3, 2, offsetof(SceneVertex, lightmapUv)},
                                  {4, 4, offsetof(SceneVertex, color)}};
  for (const Attribute& attribute : attributes) {
    glEnableVertexArrayAttrib(vao, attribute.location);
    glVertexArrayAttribFormat(vao, attribute.location, attribute.components, GL_FLOAT, GL_FALSE,
                              GLuint(attribute.offset));
    glVertexArrayAttribBinding(vao, attribute.location, 0);
  }
}

void GpuScene::selectCubeFaceTriangles(glm::vec3 eye) {
  // The vertex shader's own subtraction (shaders/scene.vert), so each
  // vertex is beyond a plane here exactly when its clip coordinates are.
  outcodes_.resize(positions_.size());
  cubeFaceOutcodes(positions_, eye, outcodes_);
  for (int face = 0; face < kCubeFaces; ++face) {
    faceIndices_[size_t(face)].clear();
    faceRanges_[size_t(face)].clear();
  }
  for (const DrawRange& range : ranges_) {
    std::array<size_t, kCubeFaces> starts;
    for (int face = 0; face < kCubeFaces; ++face) starts[size_t(face)] = faceIndices_[size_t(face)].size();
    const uint32_t* triangle = indices_.data() + range.firstIndex;
    for (GLsizei i = 0; i + 2 < range.indexCount; i += 3, triangle += 3) {
      const uint8_t faces = cubeFacesTouched(outcodes_[triangle[0]], outcodes_[triangle[1]], outcodes_[triangle[2]]);
      for (int face = 0; face < kCubeFaces; ++face) {
        if (faces & (1u << face)) {
          faceIndices_[size_t(face)].insert(faceIndices_[size_t(face)].end(), triangle, triangle + 3);
        }
      }
    }
    // Consecutive meshes of one material become one draw: the same
    // triangles in the same order, with a fraction of the draw calls.
    for (int face = 0; face < kCubeFaces; ++face) {
      const size_t start = starts[size_t(face)], count = faceIndices_[size_t(face)].size() - start;
      std::vector<DrawRange>& draws = faceRanges_[size_t(face)];
      if (count == 0) continue;
      if (!draws.empty() && draws.back().material == range.material) {
        draws.back().indexCount += GLsizei(count);
      } else {
        draws.push_back({range.material, start, GLsizei(count)});
      }
    }
  }
  // One buffer, the faces one after the other.
  size_t total = 0;
  for (int face = 0; face < kCubeFaces; ++face) {
    for (DrawRange& drawn : faceRanges_[size_t(face)]) drawn.firstIndex += total;
    total += faceIndices_[size_t(face)].size();
  }
  glNamedBufferData(faceIndexBuffer_.get(), GLsizeiptr(std::max<size_t>(1, total) * sizeof(uint32_t)), nullptr,
                    GL_STREAM_DRAW);
  size_t offset = 0;
  for (const std::vector<uint32_t>& indices : faceIndices_) {
    if (!indices.empty()) {
      glNamedBufferSubData(faceIndexBuffer_.get(), GLintptr(offset * sizeof(uint32_t)),
                           GLsizeiptr(indices.size() * sizeof(uint32_t)), indices.data());
    }
    offset += indices.size();
  }
}

size_t GpuScene::selectedTriangles() const {
  size_t indices = 0;
  for (const std::vector<uint32_t>& face : faceIndices_) indices += face.size();
  return indices / 3;
}

void GpuScene::drawCubeFace(ShaderProgram& program, int face, Outputs outputs) const {
  glBindVertexArray(vertexArray_.get());
  program.set("diffuseTexture", 0);
  if (outputs == Outputs::ColorAndDistance) program.set("lightmapTexture", 1);  // the distance shader has no lightmap
  // State changes between draws are most of a small face's time on
  // llvmpipe, texture binds above all. A texture already on its unit (a
  // lightmap page many materials share) is not bound again. For distances
  // only, a fragment's plane and distance depend only on whether it is
  // discarded: a material whose texture cannot discard is drawn without
  // it, and a run of materials that discard alike is one draw (their
  // triangles are one after the other in the buffer, in the same order).
  int boundTextures[2] = {-1, -1};
  const auto bindTexture = [&](int unit, int texture) {
    if (texture < 0 || boundTextures[unit] == texture) return;
    glBindTextureUnit(GLuint(unit), textures_[size_t(texture)].get());
    boundTextures[unit] = texture;
  };
  const std::vector<DrawRange>& draws = faceRanges_[size_t(face)];  // one per material, consecutive
  std::vector<GLsizei> counts;
  std::vector<const void*> offsets;
  for (size_t first = 0; first < draws.size();) {
    const SceneMaterial& material = materials_[size_t(draws[first].material)];
    const Discard discard = discards_[size_t(draws[first].material)];
    size_t end = first + 1;
    if (outputs == Outputs::ColorAndDistance) {
      program.set("baseColor", material.baseColor);
      program.set("hasDiffuse", material.diffuseTexture >= 0 ? 1 : 0);
      program.set("hasLightmap", material.lightmapTexture >= 0 ? 1 : 0);
      program.set("lightmapScale", material.lightmapScale);
      program.set("useVertexColor", material.useVertexColor ? 1 : 0);
      program.set("alphaTest", material.alphaTest ? 1 : 0);
      program.set("specularStrength", material.specular);
      program.set("shininess", material.shininess);
      bindTexture(0, material.diffuseTexture);
      bindTexture(1, material.lightmapTexture);
    } else {
      // The distance shader reads only what can discard (its albedo's
      // alpha does not depend on the base colour).
      if (discard != Discard::ByTexture) {
        while (end < draws.size() && discards_[size_t(draws[end].material)] == discard) ++end;
      }
      const bool byTexture = discard == Discard::ByTexture;
      const bool vertexAlpha = discard == Discard::ByVertexAlpha || (byTexture && material.useVertexColor);
      program.set("hasDiffuse", byTexture ? 1 : 0);
      program.set("useVertexColor", vertexAlpha ? 1 : 0);
      program.set("alphaTest", discard != Discard::Never ? 1 : 0);
      if (byTexture) bindTexture(0, material.diffuseTexture);
    }
    const size_t indexCount = draws[end - 1].firstIndex + size_t(draws[end - 1].indexCount) - draws[first].firstIndex;
    counts.clear();
    offsets.clear();
    for (size_t drawn = 0; drawn < indexCount; drawn += kIndicesPerDraw) {
      counts.push_back(GLsizei(std::min(kIndicesPerDraw, indexCount - drawn)));
      offsets.push_back(reinterpret_cast<const void*>((draws[first].firstIndex + drawn) * sizeof(uint32_t)));
    }
    glMultiDrawElements(GL_TRIANGLES, counts.data(), GL_UNSIGNED_INT, offsets.data(), GLsizei(counts.size()));
    first = end;
  }
  glBindVertexArray(0);
}

}  // namespace triwalk
