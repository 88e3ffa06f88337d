#pragma once
// An image on the GPU that ImGui can show.

#include "core/image/image.h"
#include "render/gl/gl_objects.h"

#include <imgui.h>

namespace triwalk {

class GlImage {
public:
  void upload(const Rgb8Image& image);
  bool empty() const { return !texture_; }
  ImTextureID id() const { return reinterpret_cast<ImTextureID>(intptr_t(texture_.get())); }
  int width() const { return width_; }
  int height() const { return height_; }

private:
  GlTexture texture_;
  int width_ = 0, height_ = 0;
};

}  // namespace triwalk
