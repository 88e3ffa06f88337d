#include "core/io/exr_io.h"

#include "core/image/half_float.h"
#include "core/io/atomic_file.h"
#include "core/support/errors.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfThreading.h>
#include <half.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace triwalk {

namespace {

constexpr const char* kColorChannels[3] = {"R", "G", "B"};
constexpr const char* kDistanceChannel = "Z";

int32_t littleEndian32(const uint8_t bytes[4]) {
  return int32_t(uint32_t(bytes[0]) | uint32_t(bytes[1]) << 8 | uint32_t(bytes[2]) << 16 | uint32_t(bytes[3]) << 24);
}

// A data window triwalk reads: not empty, at most kMaxPanoramaWidth wide
// and half that high (computed in 64 bits: a hostile window overflows int).
void checkWindowSize(const std::string& name, int64_t width, int64_t height) {
  if (width <= 0 || height <= 0) throw InputError(name, "empty image");
  if (width > kMaxPanoramaWidth || height > kMaxPanoramaWidth / 2) {
    throw InputError(name, "size " + std::to_string(width) + "x" + std::to_string(height) + " is larger than triwalk reads (" +
                               std::to_string(kMaxPanoramaWidth) + "x" + std::to_string(kMaxPanoramaWidth / 2) + ")");
  }
}

// OpenEXR allocates and clears memory for what the header claims before it
// notices the file cannot hold it: every attribute at its stated size, and
// per-line tables for the data window, so a 200-byte file can cost seconds
// (both found by fuzzing). This walks the first header's attribute records
// (name, type, 32-bit size, value), refuses a size that runs past the end
// of the file and checks every dataWindow's size; all decoding stays with
// OpenEXR.
void checkHeaderBeforeOpenExr(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const auto fileSize = int64_t(std::filesystem::file_size(path));
  constexpr int64_t kMagicAndVersion = 8;
  constexpr size_t kMaxNameLength = 255;
  in.seekg(kMagicAndVersion);
  const auto readString = [&](std::string& text) {
    text.clear();
    char c = 0;
    while (in.get(c) && c != '\0') {
      if (text.size() == kMaxNameLength) return false;
      text.push_back(c);
    }
    return bool(in);
  };
  std::string attribute, type;
  while (readString(attribute) && !attribute.empty() && readString(type)) {
    uint8_t sizeBytes[4];
    if (!in.read(reinterpret_cast<char*>(sizeBytes), 4)) return;  // OpenEXR reports the truncation
    const int64_t size = littleEndian32(sizeBytes);
    const int64_t remaining = fileSize - int64_t(in.tellg());
    if (size < 0 || size > remaining) {
      throw InputError(path.string(), "header attribute '" + attribute + "' claims " + std::to_string(size) +
                                          " bytes but the file has " + std::to_string(remaining) + " left");
    }
    if (attribute == "dataWindow" && type == "box2i" && size == 16) {
      uint8_t box[16];
      if (!in.read(reinterpret_cast<char*>(box), 16)) return;
      checkWindowSize(path.string(), int64_t(littleEndian32(box + 8)) - littleEndian32(box) + 1,
                      int64_t(littleEndian32(box + 12)) - littleEndian32(box + 4) + 1);
      continue;
    }
    in.seekg(size, std::ios::cur);
  }
}

// An OpenEXR file opened after the checks above, with its data window.
struct OpenedExr {
  std::unique_ptr<Imf::InputFile> file;
  Imath::Box2i window;
  int width = 0;
  int height = 0;
  const Imf::ChannelList& channels() const { return file->header().channels(); }
};

OpenedExr openExr(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (!std::filesystem::is_regular_file(path)) throw InputError(name, "file does not exist");
  checkHeaderBeforeOpenExr(path);
  OpenedExr opened;
  opened.file = std::make_unique<Imf::InputFile>(name.c_str());
  opened.window = opened.file->header().dataWindow();
  const int64_t width = int64_t(opened.window.max.x) - int64_t(opened.window.min.x) + 1;
  const int64_t height = int64_t(opened.window.max.y) - int64_t(opened.window.min.y) + 1;
  checkWindowSize(name, width, height);
  opened.width = int(width);
  opened.height = int(height);
  return opened;
}

// Runs read, turning OpenEXR's exceptions into InputError naming the file.
template <class Read>
auto readingExr(const std::filesystem::path& path, Read read) {
  try {
    return read();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& error) {
    throw InputError(path.string(), std::string("cannot read OpenEXR: ") + error.what());
  }
}

std::string pixelName(size_t index, int width) {
  return std::to_string(index % size_t(width)) + "," + std::to_string(index / size_t(width));
}

}  // namespace

bool acceptedPanoramaColor(glm::vec3 color) {
  return std::isfinite(color.r) && std::isfinite(color.g) && std::isfinite(color.b);
}

bool acceptedPanoramaDistance(float distance) { return !std::isnan(distance) && distance >= 0.0f; }

Panorama readPanoramaExr(const std::filesystem::path& path, std::optional<glm::ivec2> expectedSize) {
  const std::string name = path.string();
  return readingExr(path, [&] {
    OpenedExr exr = openExr(path);
    const int width = exr.width, height = exr.height;
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (expectedSize && (width != expectedSize->x || height != expectedSize->y)) {
      throw InputError(name, "size " + size + " but the manifest says " + std::to_string(expectedSize->x) + "x" +
                                 std::to_string(expectedSize->y));
    }

    for (const char* channel : kColorChannels) {
      if (!exr.channels().findChannel(channel)) {
        throw InputError(name, std::string("missing channel ") + channel);
      }
    }
    if (!exr.channels().findChannel(kDistanceChannel)) throw InputError(name, "missing channel Z (distance)");

    const size_t pixelCount = size_t(width) * size_t(height);
    std::vector<uint16_t> halves[3];
    std::vector<float> channels[3];
    std::vector<float> distance(pixelCount);
    Imf::FrameBuffer frameBuffer;
    for (int c = 0; c < 3; ++c) {
      halves[c].resize(pixelCount);
      frameBuffer.insert(kColorChannels[c], Imf::Slice::Make(Imf::HALF, halves[c].data(), exr.window));
    }
    frameBuffer.insert(kDistanceChannel, Imf::Slice::Make(Imf::FLOAT, distance.data(), exr.window));
    exr.file->setFrameBuffer(frameBuffer);
    exr.file->readPixels(exr.window.min.y, exr.window.max.y);
    // Whole channels at once (F16C where the processor has it): the same
    // floats as Imath's table a value at a time, which missed the cache.
    for (int c = 0; c < 3; ++c) {
      channels[c].resize(pixelCount);
      halvesToFloats(halves[c], channels[c]);
    }

    Panorama panorama{ColorImage(width, height), ScalarImage(width, height)};
    for (size_t i = 0; i < pixelCount; ++i) {
      const glm::vec3 color{channels[0][i], channels[1][i], channels[2][i]};
      if (!acceptedPanoramaColor(color)) throw InputError(name, "non-finite color at pixel " + pixelName(i, width));
      const float d = distance[i];
      if (!acceptedPanoramaDistance(d)) {
        throw InputError(name, std::string(std::isnan(d) ? "NaN" : "negative") + " distance at pixel " + pixelName(i, width));
      }
      panorama.color.pixels[i] = color;
      panorama.distance.pixels[i] = d;
    }
    return panorama;
  });
}

ScalarImage readDepthExr(const std::filesystem::path& path) {
  const std::string name = path.string();
  return readingExr(path, [&] {
    OpenedExr exr = openExr(path);
    std::string channel;
    const Imf::ChannelList& channels = exr.channels();
    size_t channelCount = 0;
    for (auto it = channels.begin(); it != channels.end(); ++it) ++channelCount;
    if (channelCount == 1) {
      channel = channels.begin().name();
    } else {
      for (const char* candidate : {"Z", "Y", "R", "depth"}) {
        if (channels.findChannel(candidate)) {
          channel = candidate;
          break;
        }
      }
    }
    if (channel.empty()) throw InputError(name, "no depth channel (expected one channel, or Z, Y, R or depth)");
    ScalarImage depth(exr.width, exr.height);
    Imf::FrameBuffer frameBuffer;
    frameBuffer.insert(channel, Imf::Slice::Make(Imf::FLOAT, depth.pixels.data(), exr.window));
    exr.file->setFrameBuffer(frameBuffer);
    exr.file->readPixels(exr.window.min.y, exr.window.max.y);
    for (size_t i = 0; i < depth.pixelCount(); ++i) {
      if (std::isnan(depth.pixels[i])) throw InputError(name, "NaN depth at pixel " + pixelName(i, exr.width));
      if (depth.pixels[i] < 0.0f) throw InputError(name, "negative depth at pixel " + pixelName(i, exr.width));
    }
    return depth;
  });
}

glm::ivec2 exrFileSize(const std::filesystem::path& path) {
  return readingExr(path, [&] {
    const OpenedExr exr = openExr(path);
    return glm::ivec2(exr.width, exr.height);
  });
}

void writeDepthExr(const std::filesystem::path& path, const ScalarImage& depth) {
  TRIWALK_CHECK(!depth.empty(), "empty depth image");
  writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
    try {
      Imf::Header header(depth.width, depth.height);
      header.compression() = Imf::ZIP_COMPRESSION;
      header.channels().insert(kDistanceChannel, Imf::Channel(Imf::FLOAT));
      Imf::FrameBuffer frameBuffer;
      frameBuffer.insert(kDistanceChannel,
                         Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(depth.pixels.data())),
                                    sizeof(float), sizeof(float) * size_t(depth.width)));
      Imf::OutputFile file(temporary.string().c_str(), header);
      file.setFrameBuffer(frameBuffer);
      file.writePixels(depth.height);
    } catch (const std::exception& error) {
      throw InputError(path.string(), std::string("cannot write OpenEXR: ") + error.what());
    }
  });
}

Panorama asWrittenToExr(const Panorama& panorama) {
  Panorama written = panorama;
  for (glm::vec3& color : written.color.pixels) {
    for (int c = 0; c < 3; ++c) color[c] = float(half(color[c]));  // writePanoramaExr's conversion, then the reader's
  }
  return written;
}

void writePanoramaExr(const std::filesystem::path& path, const Panorama& panorama) {
  const int width = panorama.width();
  const int height = panorama.height();
  TRIWALK_CHECK(panorama.distance.width == width && panorama.distance.height == height,
                "color and distance sizes differ");
  const size_t pixelCount = size_t(width) * size_t(height);
  // Refuse what the reader would reject (a shading bug upstream, or a colour
  // beyond half's range) instead of leaving an unreadable view behind.
  for (size_t i = 0; i < pixelCount; ++i) {
    const glm::vec3& color = panorama.color.pixels[i];
    const bool representable = std::isfinite(color.r) && std::isfinite(color.g) && std::isfinite(color.b) &&
                               std::abs(color.r) <= HALF_MAX && std::abs(color.g) <= HALF_MAX &&
                               std::abs(color.b) <= HALF_MAX;
    if (!representable) {
      throw InputError(path.string(), "not written: non-finite or out-of-range color at pixel " +
                                          std::to_string(i % size_t(width)) + "," + std::to_string(i / size_t(width)));
    }
  }
  std::vector<half> channels[3];
  for (int c = 0; c < 3; ++c) {
    channels[c].resize(pixelCount);
    for (size_t i = 0; i < pixelCount; ++i) channels[c][i] = half(panorama.color.pixels[i][c]);
  }

  writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
    try {
      Imf::Header header(width, height);
      header.compression() = Imf::ZIP_COMPRESSION;
      for (const char* channel : kColorChannels) header.channels().insert(channel, Imf::Channel(Imf::HALF));
      header.channels().insert(kDistanceChannel, Imf::Channel(Imf::FLOAT));
      Imf::FrameBuffer frameBuffer;
      for (int c = 0; c < 3; ++c) {
        frameBuffer.insert(kColorChannels[c],
                           Imf::Slice(Imf::HALF, reinterpret_cast<char*>(channels[c].data()), sizeof(half),
                                      sizeof(half) * size_t(width)));
      }
      frameBuffer.insert(kDistanceChannel,
                         Imf::Slice(Imf::FLOAT,
                                    reinterpret_cast<char*>(const_cast<float*>(panorama.distance.pixels.data())),
                                    sizeof(float), sizeof(float) * size_t(width)));
      Imf::OutputFile file(temporary.string().c_str(), header);
      file.setFrameBuffer(frameBuffer);
      file.writePixels(height);
    } catch (const std::exception& error) {
      throw InputError(path.string(), std::string("cannot write OpenEXR: ") + error.what());
    }
  });
}

}  // namespace triwalk
