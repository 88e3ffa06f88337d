#pragma once
// Walkthrough videos with FFmpeg's libraries (libavformat, libavcodec,
// libswscale): H.264 (libx264) when the build of libavcodec has it, else
// MPEG-4 part 2, in the container the file's extension names (.mp4,
// .mkv, .mov, ...). A video is written to a temporary file beside its
// path and renamed into place when finished: an interrupted or failed
// encoding leaves nothing.

#include "core/image/image.h"

#include <filesystem>
#include <memory>
#include <string>

namespace triwalk {

class VideoWriter {
public:
  // Throws InputError naming the path when its extension names no
  // container FFmpeg writes, or the size is odd (4:2:0 chroma needs even
  // sides), before any frame.
  VideoWriter(const std::filesystem::path& path, int width, int height, int framesPerSecond);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // One frame of the video's size, shown for 1 / framesPerSecond seconds.
  void write(const Rgb8Image& frame);
  // Flushes the encoder, finishes the file and moves it into place.
  void commit();

  const std::string& codecName() const;

private:
  struct Encoder;
  std::unique_ptr<Encoder> encoder_;
};

// What a video file holds, every frame decoded: for checking a written
// video.
struct VideoInfo {
  int frames = 0;
  int width = 0, height = 0;
  double seconds = 0.0;  // the container's duration
  std::string codec;
};

VideoInfo readVideoInfo(const std::filesystem::path& path);

}  // namespace triwalk
