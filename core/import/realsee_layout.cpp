// The RealSee3D layout (github.com/realsee-developer/RealSee3D,
// DATASET_STRUCTURE.md): one folder per viewpoint under viewpoints/, listed
// in viewpoints.txt; a 16-bit depth PNG whose metres are value / the number
// in depth_scale.txt; extrinsics.txt the 4x4 camera-to-world matrix, row
// by row (--matrix world-to-camera for captures that store its inverse).

#include "core/import/capture_layout.h"
#include "core/import/pose_table.h"
#include "core/io/atomic_file.h"
#include "core/io/png_io.h"
#include "core/support/errors.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace triwalk {

namespace {

std::vector<std::string> viewpointIds(const std::filesystem::path& in) {
  std::vector<std::string> ids;
  const std::filesystem::path list = in / "viewpoints.txt";
  if (std::filesystem::is_regular_file(list)) {
    std::stringstream text(readTextFile(list));
    std::string line;
    while (std::getline(text, line)) {
      line.erase(std::remove_if(line.begin(), line.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); }),
                 line.end());
      if (line.empty()) continue;
      if (line.find('/') != std::string::npos || line == "." || line == "..") {
        throw InputError(list.string(), "viewpoint id '" + line + "' is not a folder name");
      }
      ids.push_back(line);
    }
    return ids;
  }
  for (const auto& entry : std::filesystem::directory_iterator(in / "viewpoints")) {
    if (entry.is_directory()) ids.push_back(entry.path().filename().string());
  }
  return ids;
}

std::filesystem::path colorImageIn(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> candidates;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    const std::string extension = entry.path().extension().string();
    if (name.rfind("panoImage", 0) == 0 && (extension == ".jpg" || extension == ".jpeg" || extension == ".png")) {
      candidates.push_back(entry.path());
    }
  }
  if (candidates.empty()) throw InputError(folder.string(), "no colour panorama (panoImage*.jpg or .png)");
  std::sort(candidates.begin(), candidates.end());
  return candidates.front();
}

class RealSeeWriter : public LayoutWriter {
public:
  explicit RealSeeWriter(std::filesystem::path out) : out_(std::move(out)) {}

  void writeView(const ExportView& view) override {
    const std::filesystem::path folder = out_ / "viewpoints" / view.name;
    std::filesystem::create_directories(folder);
    writeColorPng(folder / "panoImage.png", view.panorama);
    // Millimetres when the farthest surface fits 16 bits, else the finest
    // whole scale that does; 0 marks pixels without a surface.
    float farthest = 0.0f;
    for (float d : view.panorama.distance.pixels) {
      if (std::isfinite(d)) farthest = std::max(farthest, d);
    }
    const double scale = std::max(1.0, std::min(1000.0, std::floor(65535.0 / std::max(farthest, 1e-3f))));
    Gray16Image depth(view.panorama.width(), view.panorama.height());
    for (size_t i = 0; i < depth.pixelCount(); ++i) {
      const float d = view.panorama.distance.pixels[i];
      depth.pixels[i] = std::isfinite(d) ? uint16_t(std::clamp(std::lround(d * scale), 1l, 65535l)) : 0;
    }
    writePng16(folder / "depth_image.png", depth);
    writeTextFileAtomically(folder / "depth_scale.txt", std::to_string(scale) + "\n");
    const std::vector<double> rowMajor = matrixRows(poseMatrix(view.pose));
    std::string rows;
    char number[64];
    for (size_t i = 0; i < rowMajor.size(); ++i) {
      std::snprintf(number, sizeof number, "%.9g%c", rowMajor[i], i % 4 == 3 ? '\n' : ' ');
      rows += number;
    }
    writeTextFileAtomically(folder / "extrinsics.txt", rows);
    ids_ += view.name + "\n";
  }

  void finish() override { writeTextFileAtomically(out_ / "viewpoints.txt", ids_); }

private:
  std::filesystem::path out_;
  std::string ids_;
};

}  // namespace

std::vector<SourceView> scanRealSee(const std::filesystem::path& in, const LayoutOptions& options) {
  if (!std::filesystem::is_directory(in / "viewpoints")) {
    throw InputError(in.string(), "no viewpoints/ folder (the realsee layout is <scene>/viewpoints/<id>/...)");
  }
  std::vector<SourceView> views;
  for (const std::string& id : viewpointIds(in)) {
    const std::filesystem::path folder = in / "viewpoints" / id;
    if (!std::filesystem::is_directory(folder)) throw InputError(folder.string(), "viewpoint folder does not exist");
    SourceView view;
    view.name = id;
    view.color = colorImageIn(folder);
    view.depth.path = folder / "depth_image.png";
    if (!std::filesystem::is_regular_file(view.depth.path)) throw InputError(view.depth.path.string(), "file does not exist");
    const std::filesystem::path scaleFile = folder / "depth_scale.txt";
    view.depth.unitsPerMetre = options.depthUnitsPerMetre ? *options.depthUnitsPerMetre : readNumberFile(scaleFile, 1)[0];
    if (!(view.depth.unitsPerMetre > 0.0)) throw InputError(scaleFile.string(), "depth scale must be positive");
    const std::filesystem::path extrinsics = folder / "extrinsics.txt";
    view.pose = poseFromMatrix(matrixFromRows(readNumberFile(extrinsics, 16)), options.matrix, extrinsics.string());
    view.poseFile = extrinsics;
    if (std::filesystem::is_regular_file(folder / "pano_mask.png")) view.mask = folder / "pano_mask.png";
    views.push_back(std::move(view));
  }
  return views;
}

std::unique_ptr<LayoutWriter> makeRealSeeWriter(const std::filesystem::path& out) {
  return std::make_unique<RealSeeWriter>(out);
}

}  // namespace triwalk
