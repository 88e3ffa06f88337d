#include "core/io/replaceable_output.h"

#include "core/io/atomic_file.h"
#include "core/io/camera_path_file.h"
#include "core/support/errors.h"

#include <nlohmann/json.hpp>

#include <fstream>

namespace triwalk {

namespace {

std::string kindName(OutputKind kind) {
  switch (kind) {
    case OutputKind::Selection: return "a triwalk selection";
    case OutputKind::Evaluation: return "a triwalk evaluation (eval --json)";
    case OutputKind::RenderStatistics: return "triwalk render statistics (render --stats)";
    case OutputKind::Png: return "a PNG image";
    case OutputKind::Video: return "a video (MP4, MOV or Matroska)";
    case OutputKind::CameraPath: return "a camera path";
  }
  return "a triwalk output";
}

std::string firstBytes(const std::filesystem::path& path, size_t count) {
  std::ifstream stream(path, std::ios::binary);
  std::string bytes(count, '\0');
  stream.read(bytes.data(), std::streamsize(count));
  bytes.resize(size_t(stream.gcount()));
  return bytes;
}

// Evaluations and render statistics written before they carried a format
// field (2026-12) are known by the fields only they have, so rerunning the
// main job over its own earlier output still works.
bool isUnformattedEarlierOutput(const nlohmann::json& document, OutputKind kind) {
  if (kind == OutputKind::Evaluation) return document.contains("rows") && document.contains("not_built");
  if (kind == OutputKind::RenderStatistics) return document.contains("frames") && document.contains("holes");
  return false;
}

bool holdsJsonOutput(const std::filesystem::path& path, OutputKind kind) {
  std::string text;
  try {
    text = readTextFile(path);  // bounded as every JSON input: a larger file is no output of ours
  } catch (const InputError&) {
    return false;
  }
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
  if (!document.is_object()) return false;
  const auto field = document.find("format");
  if (field == document.end()) return isUnformattedEarlierOutput(document, kind);
  return field->is_string() && field->get<std::string>() == outputFormat(kind);
}

bool holdsPng(const std::filesystem::path& path) {
  return firstBytes(path, 8) == std::string("\x89PNG\r\n\x1a\n", 8);
}

// What FFmpeg's muxers for the extensions render --video takes write first:
// an ISO base media "ftyp" box (MP4, MOV) or the EBML header (Matroska).
bool holdsVideo(const std::filesystem::path& path) {
  const std::string head = firstBytes(path, 8);
  return (head.size() == 8 && head.compare(4, 4, "ftyp") == 0) || head.rfind("\x1a\x45\xdf\xa3", 0) == 0;
}

bool holdsCameraPath(const std::filesystem::path& path) {
  try {
    readCameraPath(path);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

std::string outputFormat(OutputKind kind) {
  switch (kind) {
    case OutputKind::Selection: return "triwalk-selection";
    case OutputKind::Evaluation: return "triwalk-evaluation";
    case OutputKind::RenderStatistics: return "triwalk-render-statistics";
    default: return {};
  }
}

std::string foreignOutputProblem(const std::filesystem::path& path, OutputKind kind) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) return {};
  if (!std::filesystem::is_regular_file(status)) return path.string() + " exists and is not a file; refusing to overwrite it";
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error || size == 0) return {};
  bool ours = false;
  switch (kind) {
    case OutputKind::Selection:
    case OutputKind::Evaluation:
    case OutputKind::RenderStatistics: ours = holdsJsonOutput(path, kind); break;
    case OutputKind::Png: ours = holdsPng(path); break;
    case OutputKind::Video: ours = holdsVideo(path); break;
    case OutputKind::CameraPath: ours = holdsCameraPath(path); break;
  }
  if (ours) return {};
  return path.string() + " exists and is not " + kindName(kind) + "; refusing to overwrite it";
}

}  // namespace triwalk
