#include "app/viewer/gl_image.h"

namespace triwalk {

void GlImage::upload(const Rgb8Image& image) {
  if (image.width != width_ || image.height != height_ || !texture_) {
    texture_ = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(texture_.get(), 1, GL_RGB8, image.width, image.height);
    glTextureParameteri(texture_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture_.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    width_ = image.width;
    height_ = image.height;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture_.get(), 0, 0, 0, image.width, image.height, GL_RGB, GL_UNSIGNED_BYTE, image.pixels.data());
}

}  // namespace triwalk
