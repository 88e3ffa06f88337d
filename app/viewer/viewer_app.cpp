// The viewer's main loop, read top to bottom as in Dear ImGui's GLFW
// example: set up, loop (poll, skip while iconified, walk, render the warp,
// build the panels, draw them, swap), tear down in reverse order.

#include "app/viewer/viewer_app.h"

#include "app/setup/decimation_options.h"
#include "app/setup/option_checks.h"
#include "app/setup/walkthrough_setup.h"
#include "app/viewer/path_video_export.h"
#include "app/viewer/sidebar.h"
#include "app/viewer/viewer_controls.h"
#include "app/viewer/viewer_preferences.h"
#include "app/viewer/viewer_state.h"
#include "app/viewer/walk_recording.h"
#include "core/geometry/walk_constraint.h"
#include "core/io/png_io.h"
#include "core/selection/selection.h"
#include "render/gl/glfw_window_context.h"
#include "render/walkthrough/frame_scale.h"
#include "render/walkthrough/panorama_overlay.h"
#include "render/walkthrough/walkthrough_renderer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

namespace triwalk {

namespace {

// A scripted screenshot waits at most this long for what it shows to load.
constexpr double kScreenshotWaitSeconds = 300.0;
// The walk panel's videos, as render's default --fps.
constexpr int kExportFramesPerSecond = 30;
// The error overlay over the scene: enough of the scene shows through to tell where the error is.
constexpr float kErrorOverlayOpacity = 0.7f;

Rgb8Image readWindow(int width, int height) {
  std::vector<glm::u8vec3> rows(size_t(width) * size_t(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glNamedFramebufferReadBuffer(0, GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
  Rgb8Image image(width, height);
  for (int y = 0; y < height; ++y) {
    std::copy_n(rows.begin() + ptrdiff_t(size_t(height - 1 - y) * size_t(width)), width,
                image.pixels.begin() + ptrdiff_t(size_t(y) * size_t(width)));
  }
  return image;
}

// A start inside the covered area: the middle of the mesh if covered,
// else the centroid of the triangle nearest to it.
glm::vec3 startPosition(const ViewMesh& mesh, float eye) {
  glm::dvec2 lower(1e30), upper(-1e30);
  for (int v : mesh.vertices()) lower = glm::min(lower, mesh.position(v)), upper = glm::max(upper, mesh.position(v));
  const glm::dvec2 middle = 0.5 * (lower + upper);
  const int t = mesh.locate(middle);
  return glm::vec3(glm::vec2(mesh.contains(t, middle) ? middle : mesh.centroid(t)), eye);
}

// The errors the live decimation computes: those a continued selection was
// made with (a decimation on a lattice, on grid meshes or with other blend
// weights goes on that way), else decimate's defaults, so that its steps
// match the command's. --error-width and --error-stride override them;
// --holes, --source-mesh and --blend-weights choose only what the walker
// sees.
TriangleErrorSettings liveErrorSettings(const ViewerOptions& options, const Dataset& dataset,
                                        const std::optional<Selection>& selection) {
  TriangleErrorSettings settings = selectionErrorDefaults(dataset);
  if (selection && selection->errors) {
    settings = *selection->errors;
  } else {
    settings.synthesis = withSelectionDefaults(options.synthesis);  // the viewer's warp and blend constants
  }
  if (options.errorWidth > 0) {
    settings.width = namingOption("error_width", "--error-width", [&] { return errorWidthFor(dataset, options.errorWidth); });
  }
  if (options.errorStride > 0) settings.stride = options.errorStride;
  // The live errors' holes are the selection's: the viewer's --holes is the walker's.
  checkErrorStride(settings, "--error-stride", "a selection made with --holes");
  return settings;
}

// "run to error" starts at the threshold the selection was made with (a
// factor of the dense mean error where it came from one), else at
// decimate's default, the relative one. Says which.
std::string startRunThreshold(ViewerState& state, const std::optional<Selection>& selection) {
  state.runRelative = !(selection && selection->relativeError == 0.0 && selection->maxError > 0.0);
  if (selection && selection->relativeError > 0.0) state.runRelativeError = float(selection->relativeError);
  if (selection && selection->maxError > 0.0) state.runError = float(selection->maxError);
  char text[64];
  if (state.runRelative) {
    std::snprintf(text, sizeof text, "%.2f x the dense mean error", double(state.runRelativeError));
  } else {
    std::snprintf(text, sizeof text, "error %.3f", double(state.runError));
  }
  return text;
}

class Viewer {
public:
  // The data set, the selection and the errors are read before the window
  // opens, so that bad input fails without a display.
  explicit Viewer(const ViewerOptions& options)
      : options_(options), dataset_(Dataset::open(options.dataset)),
        selection_(options.selection.empty() ? std::nullopt
                                             : std::optional<Selection>(readSelection(options.selection, dataset_))),
        errorSettings_(liveErrorSettings(options, dataset_, selection_)),
        context_(options.width, options.height, "triwalk") {
    // A selection goes on with the collapse options it was made with.
    const DecimationOptions decimation =
        selection_ && selection_->decimation ? *selection_->decimation : DecimationOptions{};
    const std::string threshold = startRunThreshold(state_, selection_);
    std::printf("live decimation: %s; %s cost; runs to %s\n", describeErrorSettings(errorSettings_).c_str(),
                collapseCostName(decimation.cost), threshold.c_str());
    std::fflush(stdout);
    session_ = std::make_unique<DecimationSession>(dataset_, errorSettings_, decimation, selection_);
    state_.dataset = &dataset_;
    state_.session = session_.get();
    state_.snapshot = session_->snapshot();
    state_.mesh = datasetTriangles(dataset_, state_.snapshot.triangles);
    state_.warp.blend = options.synthesis.blend;
    state_.warp.holes = options.synthesis.holes;
    state_.grazingAngleDegrees = options.synthesis.warp.grazingAngleDegrees;
    state_.walk.position = startPosition(state_.mesh, sampleEyeHeight(dataset_));
    warpOptions_ = options.synthesis.warp;
    state_.sidebar = options.sidebar.value_or(preferences_.sidebar) && !options.hideUi;
    state_.scripted = options.frames > 0;
    state_.overlay = options.overlay;
    if (!options.path.poses.empty()) {
      state_.walkPath.path = options.path;
      state_.walkPath.source = options.pathFile;
      state_.walkPath.playingSince = 0.0;
    }
    if (!options.record.empty()) {
      state_.walkPath.file = options.record.string();
      state_.walkPath.recordingSince = 0.0;
    }
    openWorkingSet();

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the data
    ImGui::StyleColorsDark();
    // F12, Tab, F1 and ? through GLFW's callbacks, not ImGui::IsKeyPressed:
    // ImGui 1.86 keeps only the key state per frame, so a tap shorter than a
    // frame (often, at llvmpipe's 70 ms) would be lost. ImGui's backend
    // chains to these. A key typed into a text field stays there.
    glfwSetWindowUserPointer(context_.window(), this);
    glfwSetKeyCallback(context_.window(), [](GLFWwindow* window, int key, int, int action, int mods) {
      if (action != GLFW_PRESS) return;
      Viewer& viewer = *static_cast<Viewer*>(glfwGetWindowUserPointer(window));
      viewer.pressed(key, mods);
    });
    glfwSetCharCallback(context_.window(), [](GLFWwindow* window, unsigned int codepoint) {
      Viewer& viewer = *static_cast<Viewer*>(glfwGetWindowUserPointer(window));
      if (codepoint == '?' && !ImGui::GetIO().WantTextInput) viewer.toggleHelp();
    });
    panoramaOverlay_ = std::make_unique<PanoramaOverlay>();
    ImGui_ImplGlfw_InitForOpenGL(context_.window(), true);
    ImGui_ImplOpenGL3_Init("#version 450");
  }

  ~Viewer() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }

  int run() {
    auto last = std::chrono::steady_clock::now();
    for (int frame = 0; !context_.shouldClose(); ++frame) {
      glfwPollEvents();
      if (glfwGetWindowAttrib(context_.window(), GLFW_ICONIFIED)) {
        glfwWaitEventsTimeout(0.1);
        continue;
      }
      const auto now = std::chrono::steady_clock::now();
      const double seconds = std::chrono::duration<double>(now - last).count();
      last = now;
      const bool scripted = state_.scripted;
      // A scripted run's last frame waits for what it shows to load; it is
      // then drawn once more for the screenshot, because ImGui lays a
      // window out from its previous frame (a scrollbar sized while a
      // notice was still there).
      const bool finalFrame = scripted && frame + 1 >= options_.frames;
      const bool screenshotFrame = scripted && frame >= options_.frames;
      if (frame > 0 && !screenshotFrame) state_.clock += scripted ? 1.0 / kPathFramesPerSecond : seconds;
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();

      update(seconds, scripted, finalFrame && !screenshotFrame);
      renderWalkthrough(finalFrame);
      const ImVec2 display = ImGui::GetIO().DisplaySize;
      if (state_.sidebar) {
        beginSidebar(display);
        drawMapPanel(state_);
        drawWalkPanel(state_);
        drawDecimationPanel(state_);
        drawInspectorPanel(state_);
        drawRenderPanel(state_);
        ImGui::End();
      } else if (!options_.hideUi) {
        ImGui::GetForegroundDrawList()->AddText(ImVec2(10.0f, 8.0f), IM_COL32(255, 255, 255, 160),
                                                "Tab: tools    F1: keys");
      }
      if (!options_.hideUi) {
        if (state_.help) drawHelpOverlay(display);
        drawNotices();
      }
      drawOverlayLegend(ImGui::GetForegroundDrawList(), display, sceneWidth(display), state_.overlay, state_.overlayNote);

      ImGui::Render();
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (state_.screenshotRequested || screenshotFrame) saveScreenshot(screenshotFrame);
      context_.swapBuffers();
      state_.frameMilliseconds = 1000.0 * std::chrono::duration<double>(std::chrono::steady_clock::now() - now).count();
      // Average the frame time, not its reciprocal: a few fast frames while
      // panoramas load would otherwise inflate the fps for seconds.
      state_.smoothedFrameSeconds =
          state_.smoothedFrameSeconds > 0.0 ? 0.9 * state_.smoothedFrameSeconds + 0.1 * seconds : seconds;
      if (screenshotFrame) break;
    }
    // A recording still going is kept.
    if (state_.walkPath.recordingSince) toggleRecording(state_.walkPath, state_.clock);
    return 0;
  }

private:
  // Keys through GLFW's callback (see the constructor).
  void pressed(int key, int mods) {
    if (key == GLFW_KEY_F12) state_.screenshotRequested = true;
    if (key == GLFW_KEY_Q && (mods & GLFW_MOD_CONTROL)) glfwSetWindowShouldClose(context_.window(), GLFW_TRUE);
    if (ImGui::GetIO().WantTextInput) return;
    if (key == GLFW_KEY_ESCAPE) cancel();
    if (key == GLFW_KEY_R) toggleRecording(state_.walkPath, state_.clock);
    if (key == GLFW_KEY_P) togglePlayback(state_.walkPath, state_.clock);
    if (key == GLFW_KEY_V && !export_) state_.exportRequested = true;
    if (key == GLFW_KEY_N || key == GLFW_KEY_B) teleportToReference(key == GLFW_KEY_B);
    if (key == GLFW_KEY_T) toggleOverlay(ViewOverlay::Trust);
    if (key == GLFW_KEY_E) toggleOverlay(ViewOverlay::Error);
    if (key == GLFW_KEY_F1) toggleHelp();
    if (key == GLFW_KEY_TAB && !options_.hideUi) toggleSidebar();
  }

  // F1 and '?': the list of controls; never over the view alone (--hide-ui).
  void toggleHelp() {
    if (!options_.hideUi) state_.help = !state_.help;
  }

  void toggleOverlay(ViewOverlay overlay) { state_.overlay = state_.overlay == overlay ? ViewOverlay::None : overlay; }

  // The error overlay follows the sample or probe nearest to the walker: its
  // reconstruction from the triangle that holds it, asked of the session's
  // worker, shown once it arrives.
  void updateErrorOverlay() {
    const OverlayView near = overlayView(dataset_, state_.walk.position);
    if (near.index < 0) {
      shownOverlay_.reset();
      state_.overlayNote = "no captured view within 0.5 m: walk to one (the map's dots; N, B: the references)";
      return;
    }
    const ViewRecord& record = overlayViewRecord(dataset_, near);
    const glm::dvec2 at(record.position);
    const int t = state_.mesh.locate(at);
    if (t < 0) return;
    const OverlayKey key{near, state_.mesh.triangles()[size_t(t)]};
    if (key != requestedOverlay_) {
      session_->inspectView(key.triangle, near.index, near.probe);
      requestedOverlay_ = key;
    }
    const auto inspection = session_->sampleInspection();
    if (inspection && inspection->destination == near.index && inspection->probe == near.probe &&
        inspection->triangle == key.triangle && shownOverlay_ != key) {
      state_.errorOverlayImage.upload(inspection->heatmap);
      shownOverlay_ = key;
      overlayError_ = inspection->error;
    }
    char note[160];
    const double away = glm::distance(at, glm::dvec2(state_.walk.position));
    const char* kind = near.probe ? "probe" : "sample";
    if (shownOverlay_ == key) {
      std::snprintf(note, sizeof note, "%s %d, %.2f m away: E %.3f (R %.4f, B %.1f%%)", kind, record.id, away,
                    overlayError_.total, overlayError_.rms, overlayError_.badPercent);
    } else {
      std::snprintf(note, sizeof note, "reconstructing %s %d...", kind, record.id);
    }
    state_.overlayNote = note;
  }

  // Esc: ends a video export (leaving no file), else a playback.
  void cancel() {
    if (export_) {
      export_.reset();
      state_.exportFrames = 0;
      state_.walkPath.message = "export cancelled: no video written";
    } else if (state_.walkPath.playingSince) {
      togglePlayback(state_.walkPath, state_.clock);
    }
  }

  // N and B: to the nearest reference ahead or behind, standing where its
  // panorama was captured (the view there is the reference itself).
  void teleportToReference(bool behind) {
    const int v = nearestVertexAhead(state_.mesh, glm::dvec2(state_.walk.position),
                                     double(state_.walk.yawDegrees) + (behind ? 180.0 : 0.0));
    if (v < 0) return;
    state_.walkPath.playingSince.reset();
    state_.walk.position = glm::vec3(glm::vec2(state_.mesh.position(v)), state_.walk.position.z);
  }

  void startExport() {
    state_.exportRequested = false;
    WalkRecording& walk = state_.walkPath;
    if (walk.path.poses.empty()) {
      walk.message = "no walk to export: R records one, or load a file";
      return;
    }
    try {
      // The window's size, even for the video's 4:2:0 chroma.
      export_ = std::make_unique<PathVideoExport>(walk.path, walk.videoFile, options_.width & ~1, options_.height & ~1,
                                                  kExportFramesPerSecond);
    } catch (const std::exception& error) {
      walk.message = std::string("no video: ") + error.what();
      return;
    }
    walk.playingSince.reset();
    state_.exportFrame = 0;
    state_.exportFrames = export_->frames();
    walk.message = "exporting " + walk.videoFile + " (Esc cancels)";
  }

  // One frame of the export, as render draws it: every reference waited for, the full size.
  void exportFrame(const PinholeCamera& camera) {
    PinholeCamera frameCamera = camera;
    frameCamera.width = export_->width();
    frameCamera.height = export_->height();
    const WalkthroughRenderer::Frame frame = renderer_->render(frameCamera, state_.warp, true);
    state_.currentTriangle = frame.triangle;
    state_.references = frame.references;
    state_.referencesAvailable = frame.available;
    lastPose_.reset();
    try {
      export_->write(renderer_->warper().readPixels());
    } catch (const std::exception& error) {
      export_.reset();
      state_.exportFrames = 0;
      state_.walkPath.message = std::string("no video: ") + error.what();
      return;
    }
    state_.exportFrame = export_->framesWritten();
    if (export_->done()) {
      state_.walkPath.message = "exported " + std::to_string(export_->frames()) + " frames to " + state_.walkPath.videoFile;
      std::printf("%s\n", state_.walkPath.message.c_str());
      std::fflush(stdout);
      export_.reset();
      state_.exportFrames = 0;
    }
  }

  void toggleSidebar() {
    state_.sidebar = !state_.sidebar;
    preferences_.sidebar = state_.sidebar;
    writeViewerPreferences(preferences_);
  }

  // How wide the 3D view is, in ImGui's units: the window, or left of the sidebar.
  float sceneWidth(ImVec2 display) const { return state_.sidebar ? display.x - sidebarWidth(display) : display.x; }

  // The same in the window's pixels.
  int viewWidth(int framebufferWidth) const {
    if (!state_.sidebar) return framebufferWidth;
    const ImGuiIO& io = ImGui::GetIO();
    return std::max(16, framebufferWidth - int(sidebarWidth(io.DisplaySize) * io.DisplayFramebufferScale.x));
  }

  void drawHelpOverlay(ImVec2 display) {
    const float left = sceneWidth(display);
    ImGui::SetNextWindowPos(ImVec2(0.5f * left, 0.5f * display.y), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (ImGui::Begin("Keys and mouse (F1 or ? closes)", &state_.help,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings) &&
        ImGui::BeginTable("controls", 2, ImGuiTableFlags_RowBg)) {
      for (const ViewerControl& control : viewerControls()) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(control.keys);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(control.action);
      }
      ImGui::EndTable();
    }
    ImGui::End();
  }

  // waitForLoading: a scripted run's last frame.
  void update(double seconds, bool scripted, bool waitForLoading) {
    const ImGuiIO& io = ImGui::GetIO();
    if (state_.exportRequested) startExport();
    if (export_) {
      moveTo(state_.walk, export_->nextPose());
    } else if (!followPlayback(state_.walkPath, state_.clock, state_.walk) && !scripted) {
      walk_.update(context_.window(), seconds, !io.WantCaptureKeyboard, !io.WantCaptureMouse, state_.mesh, state_.walk);
    }
    recordFrame(state_.walkPath, state_.clock, state_.walk);
    state_.warp.showTrust = state_.overlay == ViewOverlay::Trust;
    if (state_.overlay == ViewOverlay::Error) updateErrorOverlay();
    if (state_.overlay == ViewOverlay::Trust) {
      state_.overlayNote = "the references within the blend interval, each by how well it saw the surface, over 3";
    }
    if (waitForLoading) waitForDecimation();
    const DecimationSession::Snapshot snapshot = session_->snapshot();
    if (snapshot.version != state_.snapshot.version) {
      const bool meshChanged = snapshot.triangles != state_.snapshot.triangles;
      state_.snapshot = snapshot;
      if (meshChanged) {
        state_.mesh = datasetTriangles(dataset_, snapshot.triangles);
        renderer_->setMesh(state_.mesh);
        ++meshVersion_;
        state_.selectedTriangle = -1;
        state_.inspection.reset();
      }
    }
    if (const auto inspection = session_->inspection();
        inspection && (!state_.inspection || inspection->triangle != state_.inspection->triangle)) {
      state_.inspection = inspection;
      state_.reconstructionImage.upload(inspection->reconstruction);
      state_.truthImage.upload(inspection->truth);
      state_.heatmapImage.upload(inspection->heatmap);
    }
    if (state_.stretchChanged) {
      // New stretch test: the panoramas are prepared again.
      state_.stretchChanged = false;
      warpOptions_.grazingAngleDegrees = state_.grazingAngleDegrees;
      warpOptions_.stretchTest = StretchTest::GrazingAngle;
      renderer_.reset();
      openWorkingSet();
      ++meshVersion_;
    }
  }

  // A scripted screenshot shows the decimation once it has settled: the
  // panoramas at the error width loaded, the map's triangles coloured,
  // nothing running; or, after kScreenshotWaitSeconds, as it stands (said).
  void waitForDecimation() {
    const auto start = std::chrono::steady_clock::now();
    for (DecimationSession::Snapshot snapshot = session_->snapshot(); snapshot.busy || snapshot.errorsLoading;
         snapshot = session_->snapshot()) {
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > kScreenshotWaitSeconds) {
        std::fprintf(stderr, "triwalk: warning: gave up waiting after %.0f s for the decimation's panoramas; the "
                     "screenshot shows them loading\n", kScreenshotWaitSeconds);
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }

  // A working set for warpOptions_ and its renderer; with simplified
  // meshes, the loader simplifies the walkthrough's references into the
  // data set's store while idle, nearest to the walker first, so that a
  // first walk does not wait for them; each also gets the walking mesh for
  // frames at the walk's lowest scale.
  void openWorkingSet() {
    cache_ = std::make_unique<PanoramaCache>(dataset_, warpOptions_, options_.cacheBytes, kMinimumWalkingScale);
    renderer_ = std::make_unique<WalkthroughRenderer>(state_.mesh, *cache_, options_.width, options_.height);
    std::vector<int> references = state_.mesh.vertices();
    const glm::dvec2 walker(state_.walk.position);
    std::stable_sort(references.begin(), references.end(), [&](int a, int b) {
      return glm::distance(state_.mesh.position(a), walker) < glm::distance(state_.mesh.position(b), walker);
    });
    cache_->simplifyWhenIdle(references);
  }

  // While anything changes (the walk, a setting), frames fit the budget;
  // once nothing does, one frame at the full render scale, then that frame
  // stays on screen without drawing it again.
  void renderWalkthrough(bool finalFrame) {
    int windowWidth = 0, height = 0;
    context_.framebufferSize(windowWidth, height);
    if (windowWidth <= 0 || height <= 0) return;
    const int width = viewWidth(windowWidth);
    PinholeCamera camera;
    camera.verticalFovDegrees = state_.verticalFovDegrees;
    camera.position = state_.walk.position;
    camera.yawDegrees = state_.walk.yawDegrees;
    camera.pitchDegrees = state_.walk.pitchDegrees;
    const auto sized = [&](float scale) {
      PinholeCamera scaled = camera;
      scaled.width = std::max(16, int(float(width) * scale));
      scaled.height = std::max(16, int(float(height) * scale));
      return scaled;
    };
    const PinholeCamera full = sized(state_.renderScale);
    const bool changed = !(lastPose_ && lastPose_->camera == full && lastPose_->settings == state_.warp &&
                           lastPose_->meshVersion == meshVersion_);
    const bool settled = !changed && state_.referencesAvailable >= 3 && state_.currentScale >= state_.renderScale;
    if (export_) {
      exportFrame(camera);
    } else if (!settled) {
      frameScale_.setBudgetMilliseconds(state_.frameBudgetMilliseconds);
      const float scale = changed && state_.holdFrameBudget && !finalFrame ? frameScale_.movingScale(state_.renderScale)
                                                                           : state_.renderScale;
      camera = sized(scale);
      glFinish();
      const auto start = std::chrono::steady_clock::now();
      const WalkthroughRenderer::Frame frame = renderer_->render(camera, state_.warp, finalFrame, false, scale);
      glFinish();
      if (frame.available > 0) {
        frameScale_.record(scale,
                           1000.0 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                           frame.available == 3);
      }
      state_.currentScale = scale;
      lastPose_ = RenderedPose{full, state_.warp, meshVersion_};
      state_.currentTriangle = frame.triangle;
      state_.references = frame.references;
      state_.referencesAvailable = frame.available;
      state_.frame = frame.statistics;
      state_.cache = cache_->statistics();
    }

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, windowWidth, height);
    glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (state_.referencesAvailable > 0) {
      const GpuWarper& warper = renderer_->warper();
      glBlitNamedFramebuffer(warper.outputFramebuffer(), 0, 0, 0, warper.width(), warper.height(), 0, 0, width, height,
                             GL_COLOR_BUFFER_BIT, GL_LINEAR);
    }
    if (state_.overlay == ViewOverlay::Error && shownOverlay_ && !state_.errorOverlayImage.empty()) {
      glViewport(0, 0, width, height);
      panoramaOverlay_->draw(GLuint(reinterpret_cast<intptr_t>(state_.errorOverlayImage.id())),
                             glm::ivec2(state_.errorOverlayImage.width(), state_.errorOverlayImage.height()),
                             overlayViewRecord(dataset_, shownOverlay_->view).yawDegrees, camera, float(width) / float(height),
                             kErrorOverlayOpacity);
      glViewport(0, 0, windowWidth, height);
    }
  }

  // Over the view's bottom: panoramas still loading, a video being
  // exported, a walk being recorded or played.
  void drawNotices() {
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    const float left = sceneWidth(size);
    char text[128];
    float y = size.y - (state_.overlay == ViewOverlay::None ? 40.0f : 96.0f);  // above an overlay's colour bar
    auto say = [&](ImU32 colour) {
      ImGui::GetForegroundDrawList()->AddText(ImVec2(left * 0.5f - 120.0f, y), colour, text);
      y -= 20.0f;
    };
    if (state_.referencesAvailable < 3) {
      std::snprintf(text, sizeof text, "loading %d of the 3 panoramas...", 3 - state_.referencesAvailable);
      say(IM_COL32(255, 200, 80, 255));
    }
    if (export_) {
      std::snprintf(text, sizeof text, "exporting the walk: frame %zu of %zu (Esc cancels)", export_->framesWritten() + 1,
                    export_->frames());
      say(IM_COL32(120, 200, 255, 255));
    } else if (state_.walkPath.playingSince) {
      std::snprintf(text, sizeof text, "playing the walk: %.1f of %.1f s (P or Esc stops)",
                    state_.clock - *state_.walkPath.playingSince, pathDuration(state_.walkPath.path, kPathFramesPerSecond));
      say(IM_COL32(120, 255, 140, 255));
    }
    if (state_.walkPath.recordingSince) {
      std::snprintf(text, sizeof text, "recording the walk: %.1f s (R ends it)", state_.clock - *state_.walkPath.recordingSince);
      say(IM_COL32(255, 90, 80, 255));
    }
  }

  void saveScreenshot(bool scriptedFinal) {
    state_.screenshotRequested = false;
    int width = 0, height = 0;
    context_.framebufferSize(width, height);
    std::filesystem::path path = options_.screenshot;
    if (!scriptedFinal || path.empty()) {
      char name[64];
      std::snprintf(name, sizeof name, "triwalk_screenshot_%03d.png", screenshots_++);
      path = name;
    }
    writePng(path, readWindow(width, height));
    std::printf("screenshot %s\n", path.c_str());
  }

  ViewerOptions options_;
  Dataset dataset_;
  std::optional<Selection> selection_;
  TriangleErrorSettings errorSettings_;
  GlfwWindowContext context_;
  std::unique_ptr<DecimationSession> session_;
  WarpOptions warpOptions_;
  std::unique_ptr<PanoramaCache> cache_;
  std::unique_ptr<WalkthroughRenderer> renderer_;
  ViewerPreferences preferences_ = readViewerPreferences();
  std::unique_ptr<PathVideoExport> export_;
  std::unique_ptr<PanoramaOverlay> panoramaOverlay_;
  // The error overlay: the view and triangle asked for, and those shown.
  struct OverlayKey {
    OverlayView view;
    Triangle triangle{};
    bool operator==(const OverlayKey&) const = default;
  };
  std::optional<OverlayKey> requestedOverlay_, shownOverlay_;
  ReconstructionError overlayError_;
  ViewerState state_;
  WalkController walk_;
  FrameScaleController frameScale_{kWalkFrameBudgetMilliseconds, kMinimumWalkingScale};
  // What the frame on screen shows: the camera at the full render scale.
  struct RenderedPose {
    PinholeCamera camera;
    GpuWarpSettings settings;
    uint64_t meshVersion = 0;
  };
  std::optional<RenderedPose> lastPose_;
  uint64_t meshVersion_ = 0;  // the walkthrough's mesh or its panoramas changed
  int screenshots_ = 0;
};

}  // namespace

int runViewer(const ViewerOptions& options) {
  Viewer viewer(options);
  return viewer.run();
}

}  // namespace triwalk
