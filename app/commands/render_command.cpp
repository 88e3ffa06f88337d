// `triwalk render`: headless walkthrough frames along a camera path, with
// the GPU warp; --compare also renders the CPU reference of each frame,
// --truth the scene itself (what the frame should have been).

#include "app/commands/commands.h"
#include "app/setup/option_checks.h"
#include "app/setup/quality_options.h"
#include "app/setup/scene_loading.h"
#include "app/setup/walkthrough_setup.h"
#include "app/video/video_file.h"
#include "core/image/image_annotation.h"
#include "core/image/image_compare.h"
#include "core/io/camera_path_file.h"
#include "core/io/json_fields.h"
#include "core/io/png_io.h"
#include "core/io/staged_directory.h"
#include "core/support/errors.h"
#include "core/support/progress.h"
#include "core/synthesis/blend.h"
#include "render/capture/truth_frame_renderer.h"
#include "render/gl/gl_context.h"
#include "render/walkthrough/walkthrough_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace triwalk {

namespace {

// The CPU reference of a frame (filled, marked or black as the GPU's), in
// display bytes. It warps the exact grids whatever --source-mesh says: the
// CPU warp simplifies for panorama destinations only, and --compare is
// there to show what the GPU's choice costs.
Rgb8Image cpuReference(const Dataset& dataset, const std::array<int, 3>& references, const PinholeCamera& camera,
                       const SynthesisOptions& synthesis, std::map<int, std::unique_ptr<WarpSource>>& sources) {
  std::vector<const WarpSource*> pointers;
  for (int sample : references) {
    auto& source = sources[sample];
    if (!source) {
      const ViewRecord& view = dataset.sample(sample);
      WarpOptions exact = synthesis.warp;
      exact.mesh = SourceMesh::Grid;
      source = std::make_unique<WarpSource>(dataset.loadView(view), view.position, degreesToRadians(view.yawDegrees), exact);
    }
    pointers.push_back(source.get());
  }
  return displayImage(synthesizeView(pointers, DestinationCamera::camera(camera), synthesis).blended, synthesis.holes);
}

// How the frames of a path compare with the scene: means, the worst frame,
// and the mean of the worst 5% of frames (at least one), each measure on
// its own.
struct FrameScores {
  double meanPsnr = 0.0, meanSsim = 0.0, worstPsnr = 0.0, worstSsim = 0.0;
  struct {
    double psnr = 0.0, ssim = 0.0;
  } worstShare;
};

// Equal frames count as 100 dB, so that a mean stays finite.
constexpr double kEqualFramesPsnr = 100.0;

FrameScores summarizeScores(std::vector<double> psnrs, std::vector<double> ssims) {
  std::sort(psnrs.begin(), psnrs.end());
  std::sort(ssims.begin(), ssims.end());
  const size_t worst = std::max<size_t>(1, (psnrs.size() + 19) / 20);
  auto meanOf = [](const std::vector<double>& values, size_t count) {
    double sum = 0.0;
    for (size_t i = 0; i < count; ++i) sum += values[i];
    return sum / double(count);
  };
  FrameScores scores;
  scores.meanPsnr = meanOf(psnrs, psnrs.size());
  scores.meanSsim = meanOf(ssims, ssims.size());
  scores.worstPsnr = psnrs.front();
  scores.worstSsim = ssims.front();
  scores.worstShare = {meanOf(psnrs, worst), meanOf(ssims, worst)};
  return scores;
}

// --out may be replaced as a whole when it holds an earlier render: its
// first frame marks it.
constexpr const char* kRenderOutputMarker = "frame_0000.png";

}  // namespace

void registerRenderCommand(CLI::App& app) {
  struct Arguments {
    std::string dataset, selection, path = "rotate", out, size = "1280x720", gl = "auto", stats, video;
    int fps = 30;
    float fov = 60.0f, pitch = 0.0f;
    std::vector<float> at, from, to, yaw;
    int frames = 0;
    bool compare = false, truth = false, showSources = false;
    size_t cacheMegabytes = 1024;
    QualityArguments quality;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("render", "Render walkthrough frames headless (GPU warp) along a camera path");
  command->add_option("--dataset", arguments->dataset, "Data set directory")->required();
  command->add_option("--selection", arguments->selection, "Selection (from decimate); default: all samples");
  command->add_option("--path", arguments->path,
                      "Camera path file (x y z yaw pitch [seconds] a line: one pose a frame, or a walk recorded in "
                      "the viewer, played in time at --fps), or the preset rotate (turn at --at) or translate (--from "
                      "to --to)")
      ->capture_default_str();
  command->add_option("--out", arguments->out,
                      "Directory for frame_NNNN.png, replaced as a whole (an existing one must be empty or hold an "
                      "earlier render); optional with --video")->check(writableDirectory());
  command->add_option("--video", arguments->video,
                      "Also (or, without --out, only) encode the frames as a video: H.264 in the container the "
                      "extension names (.mp4, .mkv, .mov), written whole or not at all; inside --out, part of it");
  command->add_option("--fps", arguments->fps, "Frames a second of --video, and at which a recorded walk (a path with seconds) is rendered")
      ->capture_default_str()->check(CLI::Range(1, 240));
  command->add_option("--size", arguments->size, "Frame size WIDTHxHEIGHT")->capture_default_str();
  command->add_option("--fov", arguments->fov, "Vertical field of view, degrees")
      ->capture_default_str()->check(CLI::Range(10.0f, 150.0f));
  command->add_option("--frames", arguments->frames, "Frames of a preset path (default: 36 rotate, 24 translate)")
      ->check(CLI::Range(1, int(kMaxPathFrames)));
  command->add_option("--at", arguments->at, "rotate: position x,y[,z] (default: the middle of the samples)")
      ->delimiter(',')->expected(2, 3)->check(coordinate());
  command->add_option("--from", arguments->from, "translate: start x,y[,z]")->delimiter(',')->expected(2, 3)->check(coordinate());
  command->add_option("--to", arguments->to, "translate: end x,y[,z]")->delimiter(',')->expected(2, 3)->check(coordinate());
  command->add_option("--yaw", arguments->yaw, "translate: view yaw, degrees (default: sideways to the motion)")->expected(1);
  command->add_option("--pitch", arguments->pitch, "Pitch of preset paths, degrees")->capture_default_str();
  command->add_flag("--compare", arguments->compare,
                    "Also write the CPU reference and a difference heatmap of each frame, and print PSNR");
  command->add_flag("--truth", arguments->truth,
                    "Also render the scene itself at each frame's pose (a data set made by capture keeps its scene), "
                    "write it and a difference heatmap beside the frame, and print PSNR and SSIM against it");
  command->add_option("--stats", arguments->stats,
                      "Write per-frame statistics (holes before the fill, left after it, frame time; PSNR and SSIM "
                      "with --compare or --truth) to this JSON file; inside --out, part of it");
  command->add_flag("--show-sources", arguments->showSources, "Color each pixel by the references that made it");
  command->add_option("--cache-mb", arguments->cacheMegabytes, "Memory for resident panoramas, MiB")
      ->capture_default_str()->check(CLI::Range(size_t(1), size_t(1) << 24));
  command->add_option("--gl", arguments->gl, "Headless OpenGL: auto, egl or osmesa")->capture_default_str();
  addRenderQualityOptions(*command, arguments->quality, SourceMesh::Grid);

  command->callback([arguments] {
    const Arguments& a = *arguments;
    if (a.out.empty() && a.video.empty()) throw InputError("--out", "give a directory for the frames, or --video FILE");
    // Side outputs inside --out are written into it, and replaced with it
    // as a whole; elsewhere their folder must exist.
    const std::optional<std::filesystem::path> statsInOut = pathInside(a.stats, a.out);
    const std::optional<std::filesystem::path> videoInOut = pathInside(a.video, a.out);
    if (!a.stats.empty() && !statsInOut) checkWritableFile(a.stats, "--stats", OutputKind::RenderStatistics);
    if (!a.video.empty() && !videoInOut) checkWritableFile(a.video, "--video", OutputKind::Video);
    if (a.out.empty() && (a.compare || a.truth)) {
      throw InputError("--out", "--compare and --truth write their images beside the frames: give --out DIR");
    }
    const Dataset dataset = Dataset::open(a.dataset);
    ViewMesh mesh = walkthroughMesh(dataset, a.selection);
    // Before any frame: a data set that keeps no scene is said in one line.
    std::optional<Scene> truthScene;
    if (a.truth) truthScene.emplace(loadCapturedScene(dataset));
    int width = 0, height = 0;
    parseSize(a.size, "--size", width, height);
    const SynthesisOptions synthesis = synthesisOptions(a.quality);

    // Presets centre on the samples of the mesh at eye height.
    glm::dvec2 lower(1e30), upper(-1e30);
    for (int v : mesh.vertices()) lower = glm::min(lower, mesh.position(v)), upper = glm::max(upper, mesh.position(v));
    const float eye = sampleEyeHeight(dataset);
    auto point = [&](const std::vector<float>& v, glm::vec3 fallback) {
      if (v.empty()) return fallback;
      return glm::vec3(v[0], v[1], v.size() > 2 ? v[2] : eye);
    };
    const glm::vec3 middle(glm::vec2(0.5 * (lower + upper)), eye);
    std::vector<CameraPose> poses;
    if (a.path == "rotate") {
      poses = rotatePath(point(a.at, middle), a.frames > 0 ? a.frames : 36, a.pitch);
    } else if (a.path == "translate") {
      const glm::vec3 from = point(a.from, glm::vec3(float(lower.x), middle.y, eye));
      const glm::vec3 to = point(a.to, glm::vec3(float(upper.x), middle.y, eye));
      const glm::vec3 motion = to - from;
      const float sideways = glm::degrees(std::atan2(motion.y, motion.x)) + 90.0f;
      poses = translatePath(from, to, a.frames > 0 ? a.frames : 24, a.yaw.empty() ? sideways : a.yaw[0], a.pitch);
    } else {
      const CameraPath path = readCameraPath(a.path);
      if (frameCount(path, a.fps) > kMaxPathFrames) {
        throw InputError(a.path, "lasts " + std::to_string(int(pathDuration(path, a.fps))) + " s: more than " +
                                     std::to_string(kMaxPathFrames) + " frames at --fps " + std::to_string(a.fps));
      }
      poses = framePoses(path, a.fps);
    }

    // No reference saw from outside the walkable region: frames there are
    // black or filled. Said before the work, in one line.
    const WalkableRegion region = dataset.walkableRegion();
    const size_t outside = size_t(std::count_if(poses.begin(), poses.end(), [&](const CameraPose& pose) {
      return !region.contains(glm::dvec2(pose.position));
    }));
    if (outside > 0) {
      std::fprintf(stderr,
                   "triwalk: warning: %zu of %zu frames stand outside the walkable region of %s, where no reference "
                   "saw from\n",
                   outside, poses.size(), a.dataset.c_str());
    }
    auto context = createHeadlessContext(parseHeadlessBackend(a.gl));
    PanoramaCache cache(dataset, synthesis.warp, a.cacheMegabytes << 20);
    WalkthroughRenderer renderer(std::move(mesh), cache, width, height);
    std::optional<TruthFrameRenderer> truthRenderer;
    if (truthScene) truthRenderer.emplace(*truthScene, width, height);
    GpuWarpSettings settings;
    settings.blend = synthesis.blend;
    settings.holes = synthesis.holes;
    settings.showSources = a.showSources;
    std::optional<StagedDirectory> staging;
    if (!a.out.empty()) staging.emplace(a.out, kRenderOutputMarker, "an earlier render");
    std::optional<VideoWriter> video;
    const std::filesystem::path videoPath = videoInOut ? staging->path() / *videoInOut : std::filesystem::path(a.video);
    if (videoInOut) std::filesystem::create_directories(videoPath.parent_path());
    if (!a.video.empty()) video.emplace(videoPath, width, height, a.fps);
    std::map<int, std::unique_ptr<WarpSource>> cpuSources;
    nlohmann::json statistics = {{"format", outputFormat(OutputKind::RenderStatistics)},
                                 {"holes", holeModeName(synthesis.holes)},
                                 {"blend_weights", blendWeightsName(synthesis.blend.weights)},
                                 {"frames", nlohmann::json::array()}};
    double psnrSum = 0.0, worstPsnr = INFINITY;
    std::vector<double> truthPsnr, truthSsim;
    double frameMilliseconds = 0.0;
    InterruptScope interruptScope;
    ProgressReporter progress("render", poses.size());
    for (size_t i = 0; i < poses.size(); ++i) {
      throwIfInterrupted();
      PinholeCamera camera;
      camera.width = width;
      camera.height = height;
      camera.verticalFovDegrees = a.fov;
      camera.position = poses[i].position;
      camera.yawDegrees = poses[i].yawDegrees;
      camera.pitchDegrees = poses[i].pitchDegrees;
      const auto start = std::chrono::steady_clock::now();
      const WalkthroughRenderer::Frame frame = renderer.render(camera, settings, true);
      const Rgb8Image image = renderer.warper().readPixels();
      const double milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      frameMilliseconds += milliseconds;
      nlohmann::json frameStatistics;
      if (!a.stats.empty()) {
        const GpuHoleCounts holes = renderer.warper().countHoles();
        frameStatistics = {{"frame", i},
                           {"holes_before_fill", double(holes.holesBefore) / double(holes.pixels)},
                           {"unfilled", double(holes.unfilled) / double(holes.pixels)},
                           {"ms", milliseconds}};
      }
      char stem[64];
      std::snprintf(stem, sizeof stem, "frame_%04zu", i);
      auto write = [&](const std::string& suffix, const Rgb8Image& picture) {
        if (staging) staging->writeFile(stem + suffix, [&](const std::filesystem::path& path) { writePng(path, picture); });
      };
      write(".png", image);
      if (video) video->write(image);
      if (a.compare) {
        const Rgb8Image reference = cpuReference(dataset, frame.references, camera, synthesis, cpuSources);
        if (cpuSources.size() > 9) cpuSources.clear();
        write("_cpu.png", reference);
        write("_diff.png", withColourBar(heatmapImage(differenceImage(image, reference), 0.25f), 0.25f,
                                         "per-pixel RMS colour difference, GPU against CPU"));
        const double value = psnr(image, reference);
        psnrSum += value;
        worstPsnr = std::min(worstPsnr, value);
        if (!a.stats.empty()) frameStatistics["psnr_cpu"] = value;
        progress.setStatus("PSNR " + std::to_string(int(value * 10) / 10.0).substr(0, 5) + " dB");
      }
      if (truthRenderer) {
        const Rgb8Image truth = toDisplayImage(truthRenderer->render(camera));
        write("_truth.png", truth);
        write("_truth_diff.png", withColourBar(heatmapImage(differenceImage(image, truth), 0.25f), 0.25f,
                                               "per-pixel RMS colour difference, frame against the scene"));
        truthPsnr.push_back(std::min(psnr(image, truth), kEqualFramesPsnr));
        truthSsim.push_back(ssim(image, truth));
        if (!a.stats.empty()) frameStatistics["psnr_truth"] = truthPsnr.back(), frameStatistics["ssim_truth"] = truthSsim.back();
        char status[64];
        std::snprintf(status, sizeof status, "against the scene: PSNR %.1f dB, SSIM %.3f", truthPsnr.back(), truthSsim.back());
        progress.setStatus(status);
      }
      if (!a.stats.empty()) statistics["frames"].push_back(std::move(frameStatistics));
      progress.advance();
    }
    progress.finish();
    if (video) video->commit();
    // What is printed below about the video is read back before the folder moves.
    const std::optional<VideoInfo> written = video ? std::optional<VideoInfo>(readVideoInfo(videoPath)) : std::nullopt;
    std::printf("rendered %zu frames %dx%d%s%s (holes %s, %s weights), %.1f ms a frame with loading\n", poses.size(),
                width, height, a.out.empty() ? "" : " into ", a.out.c_str(), holeModeName(synthesis.holes),
                blendWeightsName(synthesis.blend.weights), frameMilliseconds / double(poses.size()));
    if (written) {
      // Read back: the file decodes, frame for frame.
      std::printf("wrote %s: %d frames of %dx%d at %d a second, %.2f s (%s)\n", a.video.c_str(), written->frames,
                  written->width, written->height, a.fps, written->seconds, video->codecName().c_str());
    }
    if (truthRenderer) {
      const FrameScores scores = summarizeScores(truthPsnr, truthSsim);
      statistics["truth"] = {{"mean_psnr", scores.meanPsnr},   {"mean_ssim", scores.meanSsim},
                             {"worst_psnr", scores.worstPsnr}, {"worst_ssim", scores.worstSsim},
                             {"worst_5_percent_psnr", scores.worstShare.psnr},
                             {"worst_5_percent_ssim", scores.worstShare.ssim}};
      std::printf("frames against the scene: mean PSNR %.2f dB, SSIM %.4f; worst frame %.2f dB, %.4f; worst 5%% of "
                  "frames %.2f dB, %.4f\n",
                  scores.meanPsnr, scores.meanSsim, scores.worstPsnr, scores.worstSsim, scores.worstShare.psnr,
                  scores.worstShare.ssim);
    }
    if (statsInOut) {
      staging->writeFile(statsInOut->string(), [&](const std::filesystem::path& path) {
        std::filesystem::create_directories(path.parent_path());
        writeJsonFile(path, statistics);
      });
    }
    if (staging) staging->commit();
    if (!a.stats.empty()) {
      if (!statsInOut) writeJsonFile(a.stats, statistics);
      std::printf("wrote frame statistics to %s\n", a.stats.c_str());
    }
    if (a.compare) {
      std::printf("GPU vs CPU reference: mean PSNR %.2f dB, worst %.2f dB\n", psnrSum / double(poses.size()), worstPsnr);
    }
  });
}

}  // namespace triwalk
