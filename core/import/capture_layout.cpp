#include "core/import/capture_layout.h"

#include "core/io/contained_path.h"
#include "core/io/png_io.h"
#include "core/support/errors.h"

#include <algorithm>

namespace triwalk {

CaptureLayout parseCaptureLayout(const std::string& text, const std::string& option) {
  if (text == "realsee") return CaptureLayout::RealSee;
  if (text == "pano3d") return CaptureLayout::Pano3D;
  if (text == "folder") return CaptureLayout::Folder;
  throw InputError(option, "unknown layout '" + text + "' (realsee, pano3d or folder)");
}

const char* captureLayoutName(CaptureLayout layout) {
  switch (layout) {
    case CaptureLayout::RealSee: return "realsee";
    case CaptureLayout::Pano3D: return "pano3d";
    case CaptureLayout::Folder: return "folder";
  }
  return "folder";
}

std::vector<SourceView> scanCaptureLayout(CaptureLayout layout, const std::filesystem::path& in,
                                          const LayoutOptions& options) {
  if (!std::filesystem::is_directory(in)) throw InputError(in.string(), "capture folder does not exist");
  std::vector<SourceView> views;
  switch (layout) {
    case CaptureLayout::RealSee: views = scanRealSee(in, options); break;
    case CaptureLayout::Pano3D: views = scanPano3D(in, options); break;
    case CaptureLayout::Folder: views = scanFolder(in, options); break;
  }
  if (views.empty()) throw InputError(in.string(), std::string("no views found in the ") + captureLayoutName(layout) + " layout");
  // What the layout found must stay in the folder, as a data set's files
  // must; a pose file given by --poses is the user's own choice.
  for (const SourceView& view : views) {
    requireInside(in, view.color, "the colour image of view '" + view.name + "'");
    requireInside(in, view.depth.path, "the depth image of view '" + view.name + "'");
    if (!view.mask.empty()) requireInside(in, view.mask, "the mask of view '" + view.name + "'");
    if (options.poses.empty()) requireInside(in, view.poseFile, "the pose file");
  }
  std::sort(views.begin(), views.end(), [](const SourceView& a, const SourceView& b) { return a.name < b.name; });
  return views;
}

std::unique_ptr<LayoutWriter> makeLayoutWriter(CaptureLayout layout, const std::filesystem::path& out) {
  switch (layout) {
    case CaptureLayout::RealSee: return makeRealSeeWriter(out);
    case CaptureLayout::Pano3D: return makePano3DWriter(out);
    case CaptureLayout::Folder: return makeFolderWriter(out);
  }
  return makeFolderWriter(out);
}

std::filesystem::path poseFileOf(const std::filesystem::path& in, const LayoutOptions& options,
                                 const std::vector<std::string>& candidates) {
  if (!options.poses.empty()) return options.poses;
  for (const std::string& candidate : candidates) {
    if (std::filesystem::is_regular_file(in / candidate)) return in / candidate;
  }
  std::string names;
  for (const std::string& candidate : candidates) names += (names.empty() ? "" : " or ") + candidate;
  throw InputError(in.string(), "no pose file (" + names + "; or give --poses)");
}

void writeColorPng(const std::filesystem::path& path, const Panorama& panorama) {
  writePng(path, toDisplayImage(panorama.color));
}

ViewPose poseOfView(const std::string& name, const std::filesystem::path& poseFile,
                    const std::map<std::string, ViewPose>& poses) {
  const auto found = poses.find(name);
  if (found == poses.end()) throw InputError(poseFile.string(), "no pose for view '" + name + "'");
  return found->second;
}

}  // namespace triwalk
