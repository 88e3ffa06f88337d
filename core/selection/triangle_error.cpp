#include "core/selection/triangle_error.h"

#include "core/image/color.h"
#include "core/io/downsampled_panorama_store.h"
#include "core/support/errors.h"
#include "core/support/progress.h"
#include "core/synthesis/blended_row_error.h"
#include "core/synthesis/simplified_mesh_store.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <limits>

namespace triwalk {

int errorWidthFor(const Dataset& dataset, int requested) {
  const int width = requested > 0 ? requested : dataset.largestWidthAtMost(kDefaultErrorWidth);
  dataset.downsamplingFactor(width, "error_width");
  return width;
}

std::string describeErrorPanorama(int width, int stride) {
  const std::string lattice = stride == 1   ? std::string()
                              : stride == 2 ? std::string(" (every other row and column)")
                                            : " (every " + std::to_string(stride) + "th row and column)";
  return "errors at " + std::to_string(width) + "x" + std::to_string(width / 2) + lattice;
}

void checkErrorStride(const TriangleErrorSettings& settings, const std::string& strideName, const std::string& holesName) {
  if (!std::has_single_bit(unsigned(settings.stride)) || (settings.width / 2) % settings.stride != 0) {
    throw InputError(strideName, "must be a power of two dividing the error panorama's height (" +
                                     std::to_string(settings.width / 2) + "), not " + std::to_string(settings.stride));
  }
  if (settings.stride > 1 && settings.synthesis.holes == HoleMode::Fill) {
    throw InputError(strideName, "a lattice of pixels cannot be hole-filled: use it with " + holesName + " black or mark");
  }
}

DatasetTriangleErrors::DatasetTriangleErrors(const Dataset& dataset, const TriangleErrorSettings& settings,
                                             LoadedViews views, bool quiet)
    : dataset_(dataset), settings_(settings), layerCache_(settings.layerCacheBytes.value_or(0)) {
  dataset.downsamplingFactor(settings.width, "error_width");
  checkErrorStride(settings);
  const int samples = dataset.sampleCount();
  const int probes = views == LoadedViews::SamplesAndProbes ? dataset.probeCount() : 0;
  sources_.resize(size_t(samples));
  sampleDisplay_.resize(size_t(samples));
  probeDisplay_.resize(size_t(probes));
  for (int i = 0; i < samples; ++i) positions_.emplace_back(dataset.sample(i).position);

  ProgressReporter progress("load " + std::to_string(settings.width) + "x" + std::to_string(settings.width / 2),
                            size_t(samples + probes), quiet);
  SimplifiedMeshStore meshStore(dataset);
  DownsampledPanoramaStore panoramaStore(dataset);
  tbb::parallel_for(0, samples + probes, [&](int i) {
    if (interruptRequested()) return;
    const bool isSample = i < samples;
    const ViewRecord& view = isSample ? dataset.sample(i) : dataset.probe(i - samples);
    const Panorama panorama = panoramaStore.load(view, settings.width);
    if (isSample) {
      sources_[size_t(i)] = std::make_unique<WarpSource>(meshStore.source(view, panorama, settings.synthesis.warp));
      sampleDisplay_[size_t(i)] = toDisplayColors(panorama.color);
    } else {
      probeDisplay_[size_t(i - samples)] = toDisplayColors(panorama.color);
    }
    progress.advance();
  });
  progress.finish();
  throwIfInterrupted();
  loads_ = {panoramaStore.loaded(), panoramaStore.downsampled(), meshStore.loaded(), meshStore.simplified()};
  if (!settings.layerCacheBytes) budgetByMachineMemory(layerCache_);
}

const ColorImage& DatasetTriangleErrors::probeDisplay(int probe) const {
  TRIWALK_CHECK(probe >= 0 && size_t(probe) < probeDisplay_.size(), "probe not loaded (LoadedViews::SamplesAndProbes)");
  return probeDisplay_[size_t(probe)];
}

SynthesisOptions withSelectionDefaults(SynthesisOptions synthesis) {
  synthesis.holes = kDefaultErrorHoles;
  synthesis.warp.mesh = kSelectionSourceMesh;
  synthesis.blend.weights = kSelectionBlendWeights;
  return synthesis;
}

TriangleErrorSettings selectionErrorDefaults(glm::ivec2 panoramaSize) {
  TriangleErrorSettings settings;
  settings.width = largestWidthAtMost(panoramaSize, kDefaultErrorWidth);
  settings.stride = kSelectionErrorStride;
  settings.synthesis = withSelectionDefaults(settings.synthesis);
  return settings;
}

TriangleErrorSettings selectionErrorDefaults(const Dataset& dataset) {
  return selectionErrorDefaults(glm::ivec2(dataset.manifest().width, dataset.manifest().height));
}

TriangleDestinations parseTriangleDestinations(const std::string& name) {
  if (name == "centroid") return TriangleDestinations::Centroid;
  if (name == "quadrature") return TriangleDestinations::Quadrature;
  if (name == "interior") return TriangleDestinations::Interior;
  throw InputError("destinations", "unknown choice '" + name + "' (use centroid, quadrature or interior)");
}

const char* triangleDestinationsName(TriangleDestinations destinations) {
  switch (destinations) {
    case TriangleDestinations::Centroid: return "centroid";
    case TriangleDestinations::Quadrature: return "quadrature";
    case TriangleDestinations::Interior: return "interior";
  }
  return "?";
}

std::vector<std::pair<int, double>> triangleDestinations(std::span<const glm::dvec2> positions, const Triangle& triangle,
                                                         TriangleDestinations kind) {
  const glm::dvec2 a = positions[size_t(triangle[0])], b = positions[size_t(triangle[1])], c = positions[size_t(triangle[2])];
  const glm::dvec2 centroid = (a + b + c) / 3.0;
  if (kind == TriangleDestinations::Interior) {
    std::vector<int> inside;
    for (int s = 0; s < int(positions.size()); ++s) {
      if (s == triangle[0] || s == triangle[1] || s == triangle[2]) continue;
      const glm::dvec2 p = positions[size_t(s)];
      if (orientation(a, b, p) > 0 && orientation(b, c, p) > 0 && orientation(c, a, p) > 0) inside.push_back(s);
    }
    if (!inside.empty()) {
      // Spread: the sample nearest the centroid, then each next farthest
      // from those chosen (ties: the lower index).
      std::vector<int> chosen;
      std::vector<double> nearest(inside.size(), std::numeric_limits<double>::max());
      size_t next = 0;
      for (size_t i = 1; i < inside.size(); ++i) {
        if (glm::length(positions[size_t(inside[i])] - centroid) < glm::length(positions[size_t(inside[next])] - centroid)) next = i;
      }
      while (chosen.size() < std::min<size_t>(inside.size(), kMaxInteriorDestinations)) {
        chosen.push_back(inside[next]);
        size_t farthest = 0;
        for (size_t i = 0; i < inside.size(); ++i) {
          nearest[i] = std::min(nearest[i], glm::length(positions[size_t(inside[i])] - positions[size_t(inside[next])]));
          if (nearest[i] > nearest[farthest]) farthest = i;
        }
        next = farthest;
      }
      std::vector<std::pair<int, double>> destinations;
      for (int sample : chosen) destinations.emplace_back(sample, 1.0 / double(chosen.size()));
      return destinations;
    }
  }
  std::vector<glm::dvec2> points = {centroid};
  if (kind == TriangleDestinations::Quadrature) {
    points.push_back((centroid + a + b) / 3.0);
    points.push_back((centroid + b + c) / 3.0);
    points.push_back((centroid + c + a) / 3.0);
  }
  std::vector<std::pair<int, double>> destinations;
  for (const glm::dvec2& point : points) {
    int best = -1;
    double bestDistance = std::numeric_limits<double>::max();
    for (int s = 0; s < int(positions.size()); ++s) {
      if (s == triangle[0] || s == triangle[1] || s == triangle[2]) continue;
      const double d = glm::length(positions[size_t(s)] - point);
      if (d < bestDistance) bestDistance = d, best = s;
    }
    TRIWALK_CHECK(best >= 0, "a triangle needs a destination sample besides its vertices");
    const auto same = std::find_if(destinations.begin(), destinations.end(), [&](const auto& d) { return d.first == best; });
    if (same != destinations.end()) {
      same->second += 1.0 / double(points.size());
    } else {
      destinations.emplace_back(best, 1.0 / double(points.size()));
    }
  }
  return destinations;
}

JudgedReconstruction DatasetTriangleErrors::reconstruct(std::span<const int> references, glm::vec3 position,
                                                        const ColorImage& truthDisplay, PerPixelError perPixel) const {
  std::vector<const WarpSource*> sources;
  for (int reference : references) sources.push_back(sources_[size_t(reference)].get());
  return reconstructAndJudge(sources, position, settings_.width, truthDisplay, settings_.synthesis, settings_.error,
                             perPixel);
}

double DatasetTriangleErrors::sampleError(const Triangle& triangle, int destination) {
  const glm::vec3 position = dataset_.sample(destination).position;
  const int stride = settings_.stride;
  const DestinationCamera camera = DestinationCamera::panoramaLattice(position, settings_.width, settings_.width / 2, stride);
  const LayerReliability reliability = settings_.synthesis.blend.weights == BlendWeights::Reliability
                                           ? LayerReliability::Computed
                                           : LayerReliability::Omitted;
  std::shared_ptr<const CompactLayer> layers[3];
  glm::vec3 sourcePositions[3];
  for (int k = 0; k < 3; ++k) {
    const WarpSource& source = *sources_[size_t(triangle[size_t(k)])];
    layers[k] = layerCache_.get(triangle[size_t(k)], destination, [&] {
      return warpToCamera(source, camera, settings_.synthesis.warp.method, reliability);
    });
    sourcePositions[k] = source.position();
  }
  const std::vector<float> weights = blendWeights(position, sourcePositions, settings_.synthesis.blend);
  const ColorImage& truth = sampleDisplay_[size_t(destination)];
  ErrorAccumulator accumulator(truth.width, truth.height, settings_.error, stride);
  if (settings_.synthesis.holes == HoleMode::Fill) {
    // The fill needs the whole blended image.
    DecodedLayerRow whole[3];
    for (int k = 0; k < 3; ++k) layers[k]->decodeRow(0, layers[k]->pixelCount(), whole[k]);
    const DecodedLayerRow* pointers[3] = {&whole[0], &whole[1], &whole[2]};
    BlendedView view = blendLayersOf<DecodedLayerRow>(pointers, weights, truth.width, truth.height, settings_.synthesis.blend);
    fillHoles(view, settings_.synthesis.blend.epsilon);
    tbb::parallel_for(0, truth.height, [&](int y) {
      for (int x = 0; x < truth.width; ++x) {
        const size_t i = size_t(y) * size_t(truth.width) + size_t(x);
        accumulator.add(y, displayColorFast(view.color.pixels[i]), view.hole[i] != 0, truth.pixels[i]);
      }
    });
    return accumulator.result().total;
  }
  // Blend and compare row by row of the lattice, without building the
  // blended image.
  const size_t layerWidth = size_t(camera.layerWidth());
  tbb::parallel_for(tbb::blocked_range<int>(0, camera.layerHeight()), [&](const tbb::blocked_range<int>& rows) {
    DecodedLayerRow decoded[3];
    const DecodedLayerRow* pointers[3] = {&decoded[0], &decoded[1], &decoded[2]};
    for (int row = rows.begin(); row != rows.end(); ++row) {
      for (int k = 0; k < 3; ++k) layers[k]->decodeRow(size_t(row) * layerWidth, layerWidth, decoded[k]);
      const int y = row * stride;
      addBlendedRowError(pointers, weights, settings_.synthesis.blend, &truth.pixels[size_t(y) * size_t(truth.width)],
                         size_t(stride), y, accumulator);
    }
  });
  return accumulator.result().total;
}

void DatasetTriangleErrors::computeErrors(std::span<const Triangle> triangles, std::span<double> errors) {
  tbb::parallel_for(size_t(0), triangles.size(), [&](size_t i) {
    const Triangle& triangle = triangles[i];
    double error = 0.0;
    for (const auto& [destination, weight] : destinationsOf(triangle)) error += weight * sampleError(triangle, destination);
    errors[i] = error;
    ++evaluations_;
  });
}

void DatasetTriangleErrors::computeReconstructionErrors(std::span<const SampleReconstruction> requests,
                                                        std::span<double> errors) {
  tbb::parallel_for(size_t(0), requests.size(), [&](size_t i) {
    errors[i] = sampleError(requests[i].references, requests[i].destination);
    ++evaluations_;
  });
}

namespace {

// Both caches: answer what is known under the lock, compute the rest
// outside it (the long part, in parallel inside the source), then store.
template <class Request, class Key, class KeyOf, class Compute>
void serveFromCache(std::mutex& mutex, std::map<Key, double>& known, std::span<const Request> requests,
                    std::span<double> errors, KeyOf keyOf, Compute compute) {
  std::vector<Request> missing;
  std::vector<size_t> missingAt;
  {
    std::lock_guard lock(mutex);
    for (size_t i = 0; i < requests.size(); ++i) {
      const auto found = known.find(keyOf(requests[i]));
      if (found != known.end()) {
        errors[i] = found->second;
      } else {
        missing.push_back(requests[i]);
        missingAt.push_back(i);
      }
    }
  }
  if (missing.empty()) return;
  std::vector<double> computed(missing.size());
  compute(missing, computed);
  std::lock_guard lock(mutex);
  for (size_t j = 0; j < missing.size(); ++j) {
    errors[missingAt[j]] = computed[j];
    known[keyOf(missing[j])] = computed[j];
  }
}

}  // namespace

void CachingTriangleErrors::computeErrors(std::span<const Triangle> triangles, std::span<double> errors) {
  serveFromCache(mutex_, known_, triangles, errors, sortedTriangle,
                 [&](std::span<const Triangle> missing, std::span<double> computed) { source_.computeErrors(missing, computed); });
}

void CachingReconstructionErrors::computeReconstructionErrors(std::span<const SampleReconstruction> requests,
                                                              std::span<double> errors) {
  serveFromCache(
      mutex_, known_, requests, errors, [](const SampleReconstruction& request) { return request; },
      [&](std::span<const SampleReconstruction> missing, std::span<double> computed) {
        source_.computeReconstructionErrors(missing, computed);
      });
}

}  // namespace triwalk
