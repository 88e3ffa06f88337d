#pragma once
// The on-disk layouts of RGB-D panorama captures triwalk imports and
// exports (README, "Bring your own capture"):
//   realsee  <scene>/viewpoints/<id>/{panoImage*.jpg|png, depth_image.png,
//            depth_scale.txt, extrinsics.txt, [pano_mask.png]}   (RealSee3D)
//   pano3d   <dir>/**/<name>_color*.png + <name>_depth*.exr, poses.json|csv
//            (Pano3D: Matterport3D and GibsonV2 renders)
//   folder   <dir>/color/<name>.png|jpg + <dir>/depth/<name>.exr|png,
//            poses.csv|json
// Panoramas are equirectangular in the photo convention
// (core/import/panorama_orientation.h); poses as in pose_table.h.

#include "core/import/depth_decoding.h"
#include "core/import/view_pose.h"
#include "core/image/image.h"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace triwalk {

enum class CaptureLayout { RealSee, Pano3D, Folder };
CaptureLayout parseCaptureLayout(const std::string& text, const std::string& option);
const char* captureLayoutName(CaptureLayout layout);

struct LayoutOptions {
  std::filesystem::path poses;                        // empty: the layout's own pose file
  PoseMatrix matrix = PoseMatrix::CameraToWorld;      // how 4x4 matrices are meant
  std::optional<double> depthUnitsPerMetre;           // overrides the layout's depth scale
  UpAxis up = UpAxis::PlusZ;                          // the axis yaw rows turn about
};

// One viewpoint found on disk, before anything is decoded.
struct SourceView {
  std::string name;
  std::filesystem::path color;
  DepthFile depth;
  std::filesystem::path mask;  // empty when there is none; 0 marks pixels without data
  ViewPose pose;               // in the source's axes and units
  std::filesystem::path poseFile;  // where the pose came from, for errors
};

// The views of a capture, sorted by name. Throws InputError naming the
// file or folder for a missing piece (image, depth, scale, pose) or a bad
// pose; reads only small text files, never an image.
std::vector<SourceView> scanCaptureLayout(CaptureLayout layout, const std::filesystem::path& in,
                                          const LayoutOptions& options);

// One view to write: its panorama in the photo convention, its pose in
// triwalk's frame (z up, metres).
struct ExportView {
  std::string name;
  Panorama panorama;
  ViewPose pose;
};

// Writes views into a layout's folder; finish() writes the files that
// list them all (pose tables, viewpoints.txt).
class LayoutWriter {
public:
  virtual ~LayoutWriter() = default;
  virtual void writeView(const ExportView& view) = 0;
  virtual void finish() = 0;
};
std::unique_ptr<LayoutWriter> makeLayoutWriter(CaptureLayout layout, const std::filesystem::path& out);

// The layouts' own readers and writers (realsee_layout.cpp, ...).
std::vector<SourceView> scanRealSee(const std::filesystem::path& in, const LayoutOptions& options);
std::vector<SourceView> scanPano3D(const std::filesystem::path& in, const LayoutOptions& options);
std::vector<SourceView> scanFolder(const std::filesystem::path& in, const LayoutOptions& options);
std::unique_ptr<LayoutWriter> makeRealSeeWriter(const std::filesystem::path& out);
std::unique_ptr<LayoutWriter> makePano3DWriter(const std::filesystem::path& out);
std::unique_ptr<LayoutWriter> makeFolderWriter(const std::filesystem::path& out);

// Shared by the layouts: the pose file to use (the option, else the first
// of the candidates in the folder), the colour PNG of a panorama, a pose
// table row for a view.
std::filesystem::path poseFileOf(const std::filesystem::path& in, const LayoutOptions& options,
                                 const std::vector<std::string>& candidates);
void writeColorPng(const std::filesystem::path& path, const Panorama& panorama);
ViewPose poseOfView(const std::string& name, const std::filesystem::path& poseFile,
                    const std::map<std::string, ViewPose>& poses);

}  // namespace triwalk
