// Any folder of panoramas: colour images in color/ and depth images in
// depth/, matched by file name without extension; poses in poses.csv or
// poses.json (pose_table.h). Depth as .exr is metres, as 16-bit .png
// millimetres, unless --depth-scale says otherwise.

#include "core/import/capture_layout.h"
#include "core/import/pose_table.h"
#include "core/io/atomic_file.h"
#include "core/io/exr_io.h"
#include "core/support/errors.h"

#include <cstdio>
#include <map>

namespace triwalk {

namespace {

bool isColorImage(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  return extension == ".png" || extension == ".jpg" || extension == ".jpeg";
}

bool isDepthImage(const std::filesystem::path& path) {
  return path.extension() == ".exr" || path.extension() == ".png";
}

// Files of a folder by name without extension; two with one name are an error.
std::map<std::string, std::filesystem::path> filesByStem(const std::filesystem::path& folder,
                                                         bool (*accepted)(const std::filesystem::path&)) {
  if (!std::filesystem::is_directory(folder)) throw InputError(folder.string(), "folder does not exist");
  std::map<std::string, std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (!entry.is_regular_file() || !accepted(entry.path())) continue;
    const auto [existing, inserted] = files.emplace(entry.path().stem().string(), entry.path());
    if (!inserted) {
      throw InputError(entry.path().string(), "has the same name as " + existing->second.filename().string());
    }
  }
  return files;
}

class FolderWriter : public LayoutWriter {
public:
  explicit FolderWriter(std::filesystem::path out) : out_(std::move(out)) {
    std::filesystem::create_directories(out_ / "color");
    std::filesystem::create_directories(out_ / "depth");
  }

  void writeView(const ExportView& view) override {
    writeColorPng(out_ / "color" / (view.name + ".png"), view.panorama);
    writeDepthExr(out_ / "depth" / (view.name + ".exr"), view.panorama.distance);
    char row[256];
    std::snprintf(row, sizeof row, "%s,%.9g,%.9g,%.9g,%.9g\n", view.name.c_str(), view.pose.position.x,
                  view.pose.position.y, view.pose.position.z, yawDegrees(view.pose));
    rows_ += row;
  }

  void finish() override { writeTextFileAtomically(out_ / "poses.csv", rows_); }

private:
  std::filesystem::path out_;
  std::string rows_ = "name,x,y,z,yaw_deg\n";
};

}  // namespace

std::vector<SourceView> scanFolder(const std::filesystem::path& in, const LayoutOptions& options) {
  const std::filesystem::path poseFile = poseFileOf(in, options, {"poses.csv", "poses.json"});
  const PoseTable poses = readPoseTable(poseFile, options.matrix, options.up);
  const auto colors = filesByStem(in / "color", isColorImage);
  const auto depths = filesByStem(in / "depth", isDepthImage);
  for (const auto& [name, depth] : depths) {
    if (!colors.count(name)) throw InputError(depth.string(), "no colour image color/" + name + ".png or .jpg");
  }
  std::vector<SourceView> views;
  for (const auto& [name, color] : colors) {
    const auto depth = depths.find(name);
    if (depth == depths.end()) throw InputError(color.string(), "no depth image depth/" + name + ".exr or .png");
    SourceView view;
    view.name = name;
    view.color = color;
    view.depth.path = depth->second;
    view.depth.unitsPerMetre = options.depthUnitsPerMetre.value_or(depth->second.extension() == ".png" ? 1000.0 : 1.0);
    view.pose = poseOfView(name, poseFile, poses);
    view.poseFile = poseFile;
    views.push_back(std::move(view));
  }
  return views;
}

std::unique_ptr<LayoutWriter> makeFolderWriter(const std::filesystem::path& out) {
  return std::make_unique<FolderWriter>(out);
}

}  // namespace triwalk
