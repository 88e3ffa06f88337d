#include "core/io/png_io.h"

#include "core/image/color.h"
#include "core/io/atomic_file.h"
#include "core/support/errors.h"

// The implementations come from Debian's libstb (which Dear ImGui uses too).
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <cmath>

namespace triwalk {

void writePng(const std::filesystem::path& path, const Rgb8Image& image) {
  TRIWALK_CHECK(!image.empty(), "empty image");
  writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
    if (!stbi_write_png(temporary.string().c_str(), image.width, image.height, 3, image.pixels.data(),
                        image.width * 3)) {
      throw InputError(path.string(), "cannot write PNG");
    }
  });
}

Rgb8Image readPng(const std::filesystem::path& path) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* data = stbi_load(path.string().c_str(), &width, &height, &channels, 3);
  if (!data) throw InputError(path.string(), std::string("cannot read image: ") + stbi_failure_reason());
  Rgb8Image image(width, height);
  for (size_t i = 0; i < image.pixelCount(); ++i) image.pixels[i] = {data[3 * i], data[3 * i + 1], data[3 * i + 2]};
  stbi_image_free(data);
  return image;
}

Rgba8Image decodeImage(std::span<const uint8_t> bytes, const std::string& subject) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* data = stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 4);
  if (!data) throw InputError(subject, std::string("cannot decode image: ") + stbi_failure_reason());
  Rgba8Image image{width, height, std::vector<uint8_t>(data, data + size_t(width) * size_t(height) * 4)};
  stbi_image_free(data);
  return image;
}

Rgb8Image toDisplayImage(const ColorImage& linear) {
  Rgb8Image image(linear.width, linear.height);
  for (size_t i = 0; i < linear.pixelCount(); ++i) image.pixels[i] = toBytes(displayColor(linear.pixels[i]));
  return image;
}

Rgb8Image distanceFalseColorImage(const ScalarImage& distance, float maxDistance) {
  Rgb8Image image(distance.width, distance.height);
  for (size_t i = 0; i < distance.pixelCount(); ++i) {
    const float d = distance.pixels[i];
    // Logarithmic scale from 0.1 m keeps near detail and far rooms readable.
    const float t = std::log(1.0f + std::max(d, 0.0f) / 0.1f) / std::log(1.0f + maxDistance / 0.1f);
    image.pixels[i] = std::isinf(d) ? glm::u8vec3(0) : toBytes(falseColor(t));
  }
  return image;
}

Rgb8Image heatmapImage(const ScalarImage& values, float maxValue) {
  Rgb8Image image(values.width, values.height);
  for (size_t i = 0; i < values.pixelCount(); ++i) image.pixels[i] = toBytes(falseColor(values.pixels[i] / maxValue));
  return image;
}

Rgb8Image concatenateHorizontally(std::span<const Rgb8Image> images) {
  int width = 0;
  const int height = images.empty() ? 0 : images[0].height;
  for (const Rgb8Image& image : images) {
    TRIWALK_CHECK(image.height == height, "images differ in height");
    width += image.width;
  }
  Rgb8Image result(width, height);
  int x0 = 0;
  for (const Rgb8Image& image : images) {
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < image.width; ++x) result.at(x0 + x, y) = image.at(x, y);
    }
    x0 += image.width;
  }
  return result;
}

}  // namespace triwalk
