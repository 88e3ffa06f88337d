#pragma once
// Downsampled copies of a data set's panoramas kept beside them
// (docs/DESIGN.md, "Downsampled panoramas"). Decimation, evaluation and
// the viewer's live decimation read every view at the error width
// (256x128), and decoding a 1024x512 EXR to downsample it cost the main
// job's decimation 7 s of its loading on every run (OpenEXR and zlib, then
// the downsampling). A copy depends only on the view's file and the width,
// so it is kept in DATASET/downsampled/, one file per view and width, under
// a key of the file's bytes; the key costs a read of the file and XXH3, a
// fifteenth of decoding it. Capture and import keep the copies at the
// default error width as they write each view, so the first decimation
// finds them. A copy whose key, size or checksum does not match, or whose
// values a panorama may not have, is made again from the file and replaced:
// it is a cache, never input the user must mend (core/io/derived_files.h).
// A change to downsamplePanorama must change the files' magic.

#include "core/image/image.h"
#include "core/io/dataset.h"
#include "core/io/derived_files.h"

#include <glm/glm.hpp>

#include <atomic>
#include <filesystem>
#include <optional>

namespace triwalk {

class DownsampledPanoramaStore {
public:
  explicit DownsampledPanoramaStore(const Dataset& dataset);
  // The store of the data set being written into datasetDirectory (capture,
  // import) with panoramas of fullSize, before its manifest exists.
  DownsampledPanoramaStore(const std::filesystem::path& datasetDirectory, glm::ivec2 fullSize);

  // view's panorama at width, a width that divides the data set's by a whole
  // number (Dataset::downsamplingFactor): the kept copy if it was made from
  // the view's file as it is now, else the file read and validated
  // (readPanoramaExr; InputError naming it) and downsampled, and the copy
  // kept. The full width is read from the file and never kept.
  Panorama load(const ViewRecord& view, int width);

  // Keeps the copy at width of full, the panorama just written as view's
  // file (writePanoramaExr), and returns it: the copy load would make from
  // the file, bit for bit. At the full width it only returns the panorama
  // as the file holds it.
  Panorama keep(const ViewRecord& view, const Panorama& full, int width);

  // Where view's copy at width is kept.
  std::filesystem::path file(const ViewRecord& view, int width) const;

  // Copies read from the store, and made here from the view's file.
  int loaded() const { return loaded_; }
  int downsampled() const { return downsampled_; }

private:
  int factorOf(int width) const;
  std::optional<uint64_t> keyOf(const ViewRecord& view, int width) const;
  std::optional<Panorama> read(const std::filesystem::path& path, uint64_t key, int width) const;
  void store(const std::filesystem::path& path, uint64_t key, const Panorama& copy);

  std::filesystem::path datasetDirectory_;
  glm::ivec2 fullSize_;
  DerivedFiles files_;
  std::atomic<int> loaded_ = 0, downsampled_ = 0;
};

}  // namespace triwalk
