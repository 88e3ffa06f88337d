#include "core/import/dataset_export.h"

#include "core/import/panorama_orientation.h"
#include "core/io/staged_directory.h"
#include "core/support/progress.h"

namespace triwalk {

int exportDataset(const Dataset& dataset, CaptureLayout layout, const std::filesystem::path& out, bool quiet) {
  StagedDirectory staging(out, "");
  const std::unique_ptr<LayoutWriter> writer = makeLayoutWriter(layout, staging.path());
  std::vector<const ViewRecord*> views;
  for (const ViewRecord& view : dataset.manifest().samples) views.push_back(&view);
  for (const ViewRecord& view : dataset.manifest().probes) views.push_back(&view);
  InterruptScope interruptScope;
  ProgressReporter progress("export", views.size(), quiet);
  for (const ViewRecord* view : views) {
    throwIfInterrupted();
    ExportView exported{std::filesystem::path(view->file).stem().string(), dataset.loadView(*view),
                        poseFromYaw(glm::dvec3(view->position), view->yawDegrees, UpAxis::PlusZ)};
    mirrorColumns(exported.panorama.color);
    mirrorColumns(exported.panorama.distance);
    writer->writeView(exported);
    progress.advance();
  }
  writer->finish();
  progress.finish();
  staging.commit();
  return int(views.size());
}

}  // namespace triwalk
