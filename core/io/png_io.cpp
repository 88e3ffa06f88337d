#include "core/io/png_io.h"

#include "core/image/color.h"
#include "core/io/atomic_file.h"
#include "core/support/errors.h"

// The implementations come from Debian's libstb (which Dear ImGui uses too).
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <png.h>

#include <cmath>
#include <memory>

namespace triwalk {

namespace {

void appendBytes(void* context, void* data, int size) {
  auto* bytes = static_cast<std::string*>(context);
  bytes->append(static_cast<const char*>(data), size_t(size));
}

}  // namespace

// Encoded in memory and written by writeTextFileAtomically, whose write is
// checked: stb's own file writer ignores a failed fwrite, so a full disk
// left empty PNGs and exit status 0.
void writePng(const std::filesystem::path& path, const Rgb8Image& image) {
  TRIWALK_CHECK(!image.empty(), "empty image");
  std::string bytes;
  if (!stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, 3, image.pixels.data(), image.width * 3)) {
    throw InputError(path.string(), "cannot encode PNG");
  }
  writeTextFileAtomically(path, bytes);
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

glm::ivec2 imageFileSize(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path.string(), "file does not exist");
  int width = 0, height = 0, channels = 0;
  if (!stbi_info(path.string().c_str(), &width, &height, &channels)) {
    throw InputError(path.string(), std::string("cannot read image: ") + stbi_failure_reason());
  }
  return {width, height};
}

Gray16Image readPng16(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (!std::filesystem::is_regular_file(path)) throw InputError(name, "file does not exist");
  int width = 0, height = 0, channels = 0;
  if (!stbi_info(name.c_str(), &width, &height, &channels)) {
    throw InputError(name, std::string("cannot read image: ") + stbi_failure_reason());
  }
  if (!stbi_is_16_bit(name.c_str())) throw InputError(name, "not a 16-bit PNG (depth maps need 16 bits)");
  if (channels != 1) throw InputError(name, "has " + std::to_string(channels) + " channels; a depth map has one");
  std::unique_ptr<stbi_us, void (*)(void*)> data(stbi_load_16(name.c_str(), &width, &height, &channels, 1),
                                                 stbi_image_free);
  if (!data) throw InputError(name, std::string("cannot read image: ") + stbi_failure_reason());
  Gray16Image image(width, height);
  std::copy_n(data.get(), image.pixelCount(), image.pixels.begin());
  return image;
}

void writePng16(const std::filesystem::path& path, const Gray16Image& image) {
  TRIWALK_CHECK(!image.empty(), "empty image");
  png_image header{};
  header.version = PNG_IMAGE_VERSION;
  header.width = png_uint_32(image.width);
  header.height = png_uint_32(image.height);
  // LINEAR marks 16-bit samples stored as given, without gamma encoding.
  header.format = PNG_FORMAT_LINEAR_Y;
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&header, nullptr, &size, 0, image.pixels.data(), 0, nullptr)) {
    throw InputError(path.string(), std::string("cannot encode PNG: ") + header.message);
  }
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&header, bytes.data(), &size, 0, image.pixels.data(), 0, nullptr)) {
    throw InputError(path.string(), std::string("cannot encode PNG: ") + header.message);
  }
  bytes.resize(size);
  writeTextFileAtomically(path, bytes);
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
