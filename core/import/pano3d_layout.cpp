// The Pano3D layout (Matterport3D and GibsonV2 renders): under the folder,
// at any depth, <name>_color*.png beside <name>_depth*.exr (the same
// suffix), one float channel of metres with +inf where there is no depth.
// Pano3D itself has no poses; they come from poses.json or poses.csv in
// the folder (pose_table.h), keyed by <name> relative to the folder.

#include "core/import/capture_layout.h"
#include "core/import/pose_table.h"
#include "core/io/exr_io.h"
#include "core/io/json_fields.h"
#include "core/support/errors.h"

namespace triwalk {

namespace {

constexpr const char* kColorTag = "_color";
constexpr const char* kDepthTag = "_depth";

class Pano3DWriter : public LayoutWriter {
public:
  explicit Pano3DWriter(std::filesystem::path out) : out_(std::move(out)) {}

  void writeView(const ExportView& view) override {
    writeColorPng(out_ / (view.name + kColorTag + ".png"), view.panorama);
    writeDepthExr(out_ / (view.name + kDepthTag + ".exr"), view.panorama.distance);
    const std::vector<double> rowMajor = matrixRows(poseMatrix(view.pose));
    nlohmann::json rows = nlohmann::json::array();
    for (size_t row = 0; row < 4; ++row) rows.push_back(std::vector<double>(rowMajor.begin() + 4 * row, rowMajor.begin() + 4 * row + 4));
    poses_.push_back({{"name", view.name}, {"matrix", rows}});
  }

  void finish() override { writeJsonFile(out_ / "poses.json", {{"views", poses_}}); }

private:
  std::filesystem::path out_;
  nlohmann::json poses_ = nlohmann::json::array();
};

}  // namespace

std::vector<SourceView> scanPano3D(const std::filesystem::path& in, const LayoutOptions& options) {
  const std::filesystem::path poseFile = poseFileOf(in, options, {"poses.json", "poses.csv"});
  const PoseTable poses = readPoseTable(poseFile, options.matrix, options.up);
  std::vector<SourceView> views;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(in)) {
    const std::string file = entry.path().filename().string();
    const size_t tag = file.find(kColorTag);
    if (!entry.is_regular_file() || tag == std::string::npos || entry.path().extension() != ".png") continue;
    SourceView view;
    view.name = (std::filesystem::relative(entry.path().parent_path(), in) / file.substr(0, tag)).lexically_normal().string();
    view.color = entry.path();
    const std::string suffix = entry.path().stem().string().substr(tag + std::string(kColorTag).size());
    view.depth.path = entry.path().parent_path() / (file.substr(0, tag) + kDepthTag + suffix + ".exr");
    if (!std::filesystem::is_regular_file(view.depth.path)) {
      throw InputError(view.color.string(), "no depth beside it (" + view.depth.path.filename().string() + ")");
    }
    view.depth.unitsPerMetre = options.depthUnitsPerMetre.value_or(1.0);
    view.pose = poseOfView(view.name, poseFile, poses);
    view.poseFile = poseFile;
    views.push_back(std::move(view));
  }
  return views;
}

std::unique_ptr<LayoutWriter> makePano3DWriter(const std::filesystem::path& out) {
  return std::make_unique<Pano3DWriter>(out);
}

}  // namespace triwalk
