#include "app/video/video_file.h"

#include "core/support/errors.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <atomic>
#include <system_error>
#include <unistd.h>

namespace triwalk {

namespace {

std::string describeError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

// The temporary file beside the video, named so that two writers never
// share one.
std::filesystem::path temporaryBeside(const std::filesystem::path& path) {
  static std::atomic<int> counter{0};
  return path.parent_path() / ("." + path.filename().string() + ".partial-" + std::to_string(getpid()) + "-" +
                               std::to_string(counter++) + path.extension().string());
}

}  // namespace

struct VideoWriter::Encoder {
  std::filesystem::path path, temporary;
  int width = 0, height = 0;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scaler = nullptr;
  int64_t nextPts = 0;
  bool fileOpen = false, committed = false;
  std::string codecName;

  [[noreturn]] void fail(const std::string& what, int code) const {
    throw InputError(path.string(), what + ": " + describeError(code));
  }

  // Sends a frame (nullptr: the end) and writes every packet the encoder has.
  void encode(const AVFrame* input) {
    if (const int status = avcodec_send_frame(codec, input); status < 0) fail("encoding a frame", status);
    while (true) {
      const int status = avcodec_receive_packet(codec, packet);
      if (status == AVERROR(EAGAIN) || status == AVERROR_EOF) return;
      if (status < 0) fail("encoding a frame", status);
      // Each frame lasts one frame's time, the last one too: without it the
      // container ends the video when the last frame starts.
      packet->duration = 1;
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      if (const int written = av_interleaved_write_frame(format, packet); written < 0) fail("writing", written);
    }
  }

  ~Encoder() {
    sws_freeContext(scaler);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (format) {
      if (fileOpen) avio_closep(&format->pb);
      avformat_free_context(format);
    }
    if (!committed && !temporary.empty()) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
    }
  }
};

VideoWriter::VideoWriter(const std::filesystem::path& path, int width, int height, int framesPerSecond)
    : encoder_(std::make_unique<Encoder>()) {
  Encoder& e = *encoder_;
  e.path = path;
  e.width = width;
  e.height = height;
  if (width <= 0 || height <= 0 || width % 2 != 0 || height % 2 != 0) {
    throw InputError(path.string(), "a video needs an even width and height, got " + std::to_string(width) + "x" +
                                        std::to_string(height));
  }
  const AVOutputFormat* container = av_guess_format(nullptr, path.filename().c_str(), nullptr);
  if (!container || container->video_codec == AV_CODEC_ID_NONE) {
    throw InputError(path.string(), "no video container for its extension (use .mp4, .mkv or .mov)");
  }
  const AVCodec* codec = avcodec_find_encoder_by_name("libx264");
  if (!codec) codec = avcodec_find_encoder(AV_CODEC_ID_MPEG4);
  if (!codec) throw InputError(path.string(), "this FFmpeg has neither an H.264 nor an MPEG-4 encoder");
  e.codecName = codec->name;

  e.temporary = temporaryBeside(path);
  if (const int status = avformat_alloc_output_context2(&e.format, container, nullptr, e.temporary.c_str()); status < 0) {
    e.fail("opening the container", status);
  }
  e.stream = avformat_new_stream(e.format, nullptr);
  e.codec = avcodec_alloc_context3(codec);
  e.frame = av_frame_alloc();
  e.packet = av_packet_alloc();
  TRIWALK_CHECK(e.stream && e.codec && e.frame && e.packet, "FFmpeg could not allocate an encoder");
  e.codec->width = width;
  e.codec->height = height;
  e.codec->time_base = AVRational{1, framesPerSecond};
  e.codec->framerate = AVRational{framesPerSecond, 1};
  e.codec->pix_fmt = AV_PIX_FMT_YUV420P;
  e.codec->gop_size = framesPerSecond;
  if (e.format->oformat->flags & AVFMT_GLOBALHEADER) e.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  if (e.codecName == "libx264") {
    // Visually lossless for rendered frames, at x264's default speed.
    av_opt_set(e.codec->priv_data, "crf", "18", 0);
    av_opt_set(e.codec->priv_data, "preset", "medium", 0);
  } else {
    e.codec->bit_rate = int64_t(width) * height * framesPerSecond / 4;  // about 0.25 bit a pixel
  }
  if (const int status = avcodec_open2(e.codec, codec, nullptr); status < 0) e.fail("opening the encoder", status);
  if (const int status = avcodec_parameters_from_context(e.stream->codecpar, e.codec); status < 0) {
    e.fail("describing the stream", status);
  }
  e.stream->time_base = e.codec->time_base;
  if (const int status = avio_open(&e.format->pb, e.temporary.c_str(), AVIO_FLAG_WRITE); status < 0) {
    e.fail("creating " + e.temporary.string(), status);
  }
  e.fileOpen = true;
  if (const int status = avformat_write_header(e.format, nullptr); status < 0) e.fail("writing the header", status);

  e.frame->format = e.codec->pix_fmt;
  e.frame->width = width;
  e.frame->height = height;
  if (const int status = av_frame_get_buffer(e.frame, 0); status < 0) e.fail("allocating a frame", status);
  e.scaler = sws_getContext(width, height, AV_PIX_FMT_RGB24, width, height, AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr,
                            nullptr, nullptr);
  TRIWALK_CHECK(e.scaler, "FFmpeg could not convert RGB to YUV");
}

VideoWriter::~VideoWriter() = default;

const std::string& VideoWriter::codecName() const { return encoder_->codecName; }

void VideoWriter::write(const Rgb8Image& image) {
  Encoder& e = *encoder_;
  TRIWALK_CHECK(image.width == e.width && image.height == e.height, "a video frame of another size");
  if (const int status = av_frame_make_writable(e.frame); status < 0) e.fail("preparing a frame", status);
  const uint8_t* source[1] = {reinterpret_cast<const uint8_t*>(image.pixels.data())};
  const int sourceStride[1] = {3 * image.width};
  sws_scale(e.scaler, source, sourceStride, 0, image.height, e.frame->data, e.frame->linesize);
  e.frame->pts = e.nextPts++;
  e.encode(e.frame);
}

void VideoWriter::commit() {
  Encoder& e = *encoder_;
  e.encode(nullptr);
  if (const int status = av_write_trailer(e.format); status < 0) e.fail("finishing", status);
  if (const int status = avio_closep(&e.format->pb); status < 0) e.fail("closing", status);
  e.fileOpen = false;
  std::filesystem::rename(e.temporary, e.path);
  e.committed = true;
}

VideoInfo readVideoInfo(const std::filesystem::path& path) {
  AVFormatContext* format = nullptr;
  if (const int status = avformat_open_input(&format, path.c_str(), nullptr, nullptr); status < 0) {
    throw InputError(path.string(), "not a video FFmpeg reads: " + describeError(status));
  }
  struct Closer {
    AVFormatContext** format;
    AVCodecContext* codec = nullptr;
    AVPacket* packet = nullptr;
    AVFrame* frame = nullptr;
    ~Closer() {
      av_frame_free(&frame);
      av_packet_free(&packet);
      avcodec_free_context(&codec);
      avformat_close_input(format);
    }
  } closer{&format};
  if (const int status = avformat_find_stream_info(format, nullptr); status < 0) {
    throw InputError(path.string(), "no stream information: " + describeError(status));
  }
  const AVCodec* decoder = nullptr;
  const int stream = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  if (stream < 0 || !decoder) throw InputError(path.string(), "holds no video stream FFmpeg decodes");
  closer.codec = avcodec_alloc_context3(decoder);
  closer.packet = av_packet_alloc();
  closer.frame = av_frame_alloc();
  TRIWALK_CHECK(closer.codec && closer.packet && closer.frame, "FFmpeg could not allocate a decoder");
  avcodec_parameters_to_context(closer.codec, format->streams[stream]->codecpar);
  if (const int status = avcodec_open2(closer.codec, decoder, nullptr); status < 0) {
    throw InputError(path.string(), "cannot open its decoder: " + describeError(status));
  }
  VideoInfo info;
  info.width = closer.codec->width;
  info.height = closer.codec->height;
  info.codec = decoder->name;
  info.seconds = format->duration > 0 ? double(format->duration) / AV_TIME_BASE : 0.0;
  auto drain = [&] {
    while (avcodec_receive_frame(closer.codec, closer.frame) == 0) ++info.frames;
  };
  while (av_read_frame(format, closer.packet) >= 0) {
    if (closer.packet->stream_index == stream && avcodec_send_packet(closer.codec, closer.packet) >= 0) drain();
    av_packet_unref(closer.packet);
  }
  avcodec_send_packet(closer.codec, nullptr);
  drain();
  return info;
}

}  // namespace triwalk
