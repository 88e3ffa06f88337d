#include "core/selection/selection.h"

#include "core/io/json_fields.h"
#include "core/io/replaceable_output.h"
#include "core/support/errors.h"
#include "core/support/input_limits.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <set>
#include <sstream>

namespace triwalk {

namespace {

const std::map<std::string, PlacementKind> kPlacementKinds = {
    {"first", PlacementKind::First},           {"second", PlacementKind::Second},
    {"midpoint", PlacementKind::Midpoint},     {"one-ring", PlacementKind::OneRing},
    {"relocation", PlacementKind::Relocation}, {"removal", PlacementKind::Removal}};

nlohmann::json trianglesToJson(const std::vector<Triangle>& triangles, const Dataset& dataset) {
  nlohmann::json array = nlohmann::json::array();
  for (const Triangle& t : triangles) array.push_back({dataset.sample(t[0]).id, dataset.sample(t[1]).id, dataset.sample(t[2]).id});
  return array;
}

// A choice a settings object names, parsed by the function that parses
// the command-line option setting it. That one names the option when the
// name is unknown; here the file is at fault.
template <typename Parse>
auto namedChoice(const JsonObject& settings, const std::string& key, Parse parse) {
  const std::string name = settings.string(key);
  try {
    return parse(name);
  } catch (const InputError& error) {
    settings.fail(error.problem());
  }
}

// A number a settings object gives, within the range of the command-line
// option that sets it.
double numberWithin(const JsonObject& settings, const std::string& key, OptionRange range) {
  const double value = settings.number(key);
  if (!range.contains(value)) {
    std::ostringstream problem;
    problem << key << " must be from " << range.lowest << " to " << range.highest << ", not " << value;
    settings.fail(problem.str());
  }
  return value;
}

// A float option as the decimal people wrote (1.15, not the double
// 1.149999976158142 nearest the float): its shortest decimal form, which
// reads back as the same float.
double asWritten(float value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  double written = 0.0;
  std::from_chars(text, end, written);
  return written;
}

}  // namespace

DecimationOptions readDecimationOptions(const JsonObject& settings) {
  DecimationOptions options;
  options.cost = namedChoice(settings, "cost", parseCollapseCost);
  if (settings.has("one_ring")) options.oneRingCandidates = settings.boolean("one_ring");
  if (settings.has("fixed_boundary")) options.fixedBoundary = settings.boolean("fixed_boundary");
  if (settings.has("area_weighted_cost")) options.areaWeightedCost = settings.boolean("area_weighted_cost");
  if (settings.has("priced_samples")) {
    options.pricedSamples = settings.integer("priced_samples");
    if (options.pricedSamples < 0) settings.fail("priced_samples must not be negative");
  }
  if (settings.has("recosting")) options.lazyRecosting = namedChoice(settings, "recosting", parseLazyRecosting);
  return options;
}

// The ranges are the command-line options' (kGrazingAngleRange and the
// others, beside WarpOptions and BlendOptions).
std::optional<TriangleErrorSettings> readSelectionErrors(const JsonObject& settings, const Dataset& dataset) {
  const nlohmann::json keys = describeSelectionErrors(TriangleErrorSettings{});
  if (std::none_of(keys.items().begin(), keys.items().end(), [&](const auto& key) { return settings.has(key.key()); })) {
    return std::nullopt;
  }
  TriangleErrorSettings errors = selectionErrorDefaults(dataset);
  if (settings.has("error_width")) {
    errors.width = settings.integer("error_width");
    if (errors.width <= 0 || dataset.largestWidthAtMost(errors.width) != errors.width) {
      settings.fail("error_width " + std::to_string(errors.width) + " does not divide the data set's width " +
                    std::to_string(dataset.manifest().width));
    }
  }
  if (settings.has("error_stride")) errors.stride = settings.integer("error_stride");
  if (settings.has("destinations")) errors.destinations = namedChoice(settings, "destinations", parseTriangleDestinations);
  WarpOptions& warp = errors.synthesis.warp;
  if (settings.has("point_warp")) warp.method = settings.boolean("point_warp") ? WarpMethod::Point : WarpMethod::Mesh;
  if (settings.has("stretch_test")) warp.stretchTest = namedChoice(settings, "stretch_test", parseStretchTest);
  if (settings.has("grazing_angle")) {
    warp.grazingAngleDegrees = float(numberWithin(settings, "grazing_angle", kGrazingAngleRange));
  }
  if (settings.has("depth_ratio")) warp.maxDepthRatio = float(numberWithin(settings, "depth_ratio", kDepthRatioRange));
  if (settings.has("source_mesh")) warp.mesh = namedChoice(settings, "source_mesh", parseSourceMesh);
  if (settings.has("mesh_tolerance")) {
    warp.meshTolerancePixels = float(numberWithin(settings, "mesh_tolerance", kMeshToleranceRange));
  }
  BlendOptions& blend = errors.synthesis.blend;
  if (settings.has("epsilon")) blend.epsilon = float(numberWithin(settings, "epsilon", kEpsilonRange));
  if (settings.has("min_weight_distance")) {
    blend.minimumWeightDistance = float(numberWithin(settings, "min_weight_distance", kMinimumWeightDistanceRange));
  }
  if (settings.has("blend_weights")) blend.weights = namedChoice(settings, "blend_weights", parseBlendWeights);
  if (settings.has("holes")) {
    errors.synthesis.holes = namedChoice(settings, "holes", [](const std::string& name) { return parseHoleMode(name); });
  }
  if (settings.has("alpha")) errors.error.alpha = numberWithin(settings, "alpha", kErrorWeightRange);
  if (settings.has("beta")) errors.error.beta = numberWithin(settings, "beta", kErrorWeightRange);
  if (settings.has("delta")) errors.error.delta = numberWithin(settings, "delta", kBadPixelToleranceRange);
  if (settings.has("pixel_weighting")) errors.error.weighting = namedChoice(settings, "pixel_weighting", parsePixelWeighting);
  try {
    checkErrorStride(errors, "error_stride", "holes");
  } catch (const InputError& error) {
    settings.fail(error.what());  // names error_stride
  }
  return errors;
}

double readThreshold(const JsonObject& settings, const std::string& key, OptionRange range) {
  const double value = settings.has(key) ? settings.number(key) : 0.0;
  if (value != 0.0 && !range.contains(value)) {
    std::ostringstream problem;
    problem << key << " must be 0 (none) or from " << range.lowest << " to " << range.highest << ", not " << value;
    settings.fail(problem.str());
  }
  return value;
}

RefinementOptions readRefinementOptions(const JsonObject& settings) {
  RefinementOptions options;
  if (settings.has("refine_radius") && !settings.json().at("refine_radius").is_string()) {
    options.radius = settings.number("refine_radius");
    if (!(*options.radius >= 0.0 && *options.radius <= kMaxCoordinateMetres)) settings.fail("refine_radius out of range");
  }
  if (settings.has("exchanges") && !settings.json().at("exchanges").is_string()) {
    options.maxExchanges = settings.integer("exchanges");
    if (*options.maxExchanges < 0) settings.fail("exchanges must not be negative");
  }
  if (settings.has("refine_screen")) options.screenedShare = numberWithin(settings, "refine_screen", OptionRange{0.0f, 1.0f});
  if (settings.has("refine_priced")) {
    options.pricedSamples = settings.integer("refine_priced");
    if (options.pricedSamples < 0) settings.fail("refine_priced must not be negative");
  }
  return options;
}

namespace {

class SelectionReader {
public:
  SelectionReader(const Dataset& dataset, const std::string& file) : dataset_(dataset), file_(file) {}

  int sample(const nlohmann::json& value, const std::string& where) const {
    const int id = jsonInteger(value, file_, where + ": sample id");
    const int index = dataset_.sampleIndexOfId(id);
    if (index < 0) {
      throw InputError(file_, where + ": sample id " + std::to_string(id) + " is not in " + dataset_.manifestPath().string());
    }
    return index;
  }

  std::vector<Triangle> triangles(const JsonObject& object, const std::string& key) const {
    std::vector<Triangle> result;
    const nlohmann::json& array = object.array(key);
    for (size_t i = 0; i < array.size(); ++i) {
      const std::string where = object.where(key) + "[" + std::to_string(i) + "]";
      if (!array[i].is_array() || array[i].size() != 3) throw InputError(file_, where + ": a triangle is three sample ids");
      Triangle t{sample(array[i][0], where), sample(array[i][1], where), sample(array[i][2], where)};
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) throw InputError(file_, where + ": repeats a sample");
      const glm::dvec2 a(dataset_.sample(t[0]).position), b(dataset_.sample(t[1]).position), c(dataset_.sample(t[2]).position);
      if (orientation(a, b, c) <= 0) throw InputError(file_, where + ": not counter-clockwise (or flat)");
      result.push_back(canonicalTriangle(t));
    }
    std::sort(result.begin(), result.end());
    return result;
  }

private:
  const Dataset& dataset_;
  std::string file_;
};

}  // namespace

std::vector<glm::dvec2> samplePositions(const Dataset& dataset) {
  std::vector<glm::dvec2> positions;
  for (int i = 0; i < dataset.sampleCount(); ++i) positions.emplace_back(dataset.sample(i).position);
  return positions;
}

ViewMesh datasetMesh(const Dataset& dataset, std::span<const int> samples, const std::string& subject) {
  const WalkableRegion region = dataset.walkableRegion();
  return ViewMesh::delaunay(samplePositions(dataset), samples, subject, &region);
}

nlohmann::json describeDecimationOptions(const DecimationOptions& options) {
  return {{"one_ring", options.oneRingCandidates},
          {"cost", collapseCostName(options.cost)},
          {"fixed_boundary", options.fixedBoundary},
          {"area_weighted_cost", options.areaWeightedCost},
          {"priced_samples", options.pricedSamples},
          {"recosting", recostingName(options.lazyRecosting)}};
}

nlohmann::json describeSelectionErrors(const TriangleErrorSettings& errors) {
  const WarpOptions& warp = errors.synthesis.warp;
  const BlendOptions& blend = errors.synthesis.blend;
  return {{"error_width", errors.width},
          {"error_stride", errors.stride},
          {"destinations", triangleDestinationsName(errors.destinations)},
          {"point_warp", warp.method == WarpMethod::Point},
          {"stretch_test", stretchTestName(warp.stretchTest)},
          {"grazing_angle", asWritten(warp.grazingAngleDegrees)},
          {"depth_ratio", asWritten(warp.maxDepthRatio)},
          {"source_mesh", sourceMeshName(warp.mesh)},
          {"mesh_tolerance", asWritten(warp.meshTolerancePixels)},
          {"epsilon", asWritten(blend.epsilon)},
          {"min_weight_distance", asWritten(blend.minimumWeightDistance)},
          {"blend_weights", blendWeightsName(blend.weights)},
          {"holes", holeModeName(errors.synthesis.holes)},
          {"alpha", errors.error.alpha},
          {"beta", errors.error.beta},
          {"delta", errors.error.delta},
          {"pixel_weighting", pixelWeightingName(errors.error.weighting)}};
}

void writeSelection(const std::filesystem::path& path, const Selection& selection, const Dataset& dataset) {
  nlohmann::json samples = nlohmann::json::array();
  for (int s : selection.samples) samples.push_back(dataset.sample(s).id);
  nlohmann::json collapses = nlohmann::json::array();
  for (const Collapse& c : selection.collapses) {
    nlohmann::json entry = {{"first", dataset.sample(c.first).id},
                            {"placement", dataset.sample(c.placement).id},
                            {"kind", placementName(c.kind)},
                            {"cost", c.cost},
                            {"error", c.error},
                            {"removed", trianglesToJson(c.removed, dataset)},
                            {"added", trianglesToJson(c.added, dataset)}};
    if (c.kind != PlacementKind::Relocation) entry["second"] = dataset.sample(c.second).id;
    collapses.push_back(std::move(entry));
  }
  nlohmann::json document = {{"format", outputFormat(OutputKind::Selection)},
                             {"version", kSelectionFormatVersion},
                             {"method", selection.method},
                             {"dataset",
                              {{"scene", dataset.manifest().scene},
                               {"samples", dataset.sampleCount()},
                               {"fingerprint", dataset.fingerprint()}}},
                             {"settings", selection.settings},
                             {"stop_reason", selection.stopReason},
                             {"samples", samples},
                             {"triangles", trianglesToJson(selection.triangles, dataset)}};
  if (std::isfinite(selection.nextCost)) document["next_cost"] = selection.nextCost;
  if (!selection.initialTriangles.empty()) {
    document["initial_triangles"] = trianglesToJson(selection.initialTriangles, dataset);
    document["collapses"] = collapses;
  }
  writeJsonFile(path, document);
}

Selection readSelection(const std::filesystem::path& path, const Dataset& dataset) {
  const nlohmann::json document = readJsonFile(path);
  const std::string file = path.string();
  const JsonObject root(document, file);
  if (root.stringOr("format", "") != outputFormat(OutputKind::Selection)) root.fail("not a triwalk selection (format field)");
  const int version = root.integer("version");
  if (version != kSelectionFormatVersion) {
    root.fail("unknown selection version " + std::to_string(version) + " (this triwalk reads version " +
              std::to_string(kSelectionFormatVersion) + ")");
  }
  // Made for another data set: said as such, before anything in it is read against this one.
  if (root.has("dataset")) {
    const JsonObject made = root.object("dataset");
    if (made.has("fingerprint") && made.string("fingerprint") != dataset.fingerprint()) {
      const std::string scene = made.stringOr("scene", "");
      const int samples = made.has("samples") ? made.integer("samples") : 0;
      if (scene == dataset.manifest().scene && samples == dataset.sampleCount()) {
        // The likely cases: a recapture with other positions, or a file
        // written before the fingerprint named the samples alone (it held
        // the panorama size too); either way its indices cannot be trusted.
        root.fail("made for another data set: the scene and sample count of " + dataset.manifestPath().string() +
                  " but other sample ids or positions (fingerprint " + made.string("fingerprint") + ", the data set's " +
                  dataset.fingerprint() + "); run decimate on this data set again");
      }
      root.fail("made for another data set (scene '" + scene + "', " + std::to_string(samples) + " samples) than " +
                dataset.manifestPath().string() + " (scene '" + dataset.manifest().scene + "', " +
                std::to_string(dataset.sampleCount()) + " samples)");
    }
  }
  const SelectionReader reader(dataset, file);
  Selection selection;
  selection.method = root.string("method");
  selection.stopReason = root.stringOr("stop_reason", "");
  selection.nextCost = root.numberOr("next_cost", std::numeric_limits<double>::infinity());
  if (root.has("settings")) {
    const JsonObject settings = root.object("settings");
    selection.settings = settings.json();
    selection.errors = readSelectionErrors(settings, dataset);
    selection.maxError = readThreshold(settings, "max_error", kMaxErrorRange);
    selection.relativeError = readThreshold(settings, "relative_error", kRelativeErrorRange);
    if (settings.has("cost")) selection.decimation = readDecimationOptions(settings);
  }
  const nlohmann::json& samples = root.array("samples");
  std::set<int> kept;
  for (size_t i = 0; i < samples.size(); ++i) {
    const int index = reader.sample(samples[i], "samples[" + std::to_string(i) + "]");
    if (!kept.insert(index).second) {
      root.fail("samples: id " + std::to_string(dataset.sample(index).id) + " appears twice");
    }
  }
  selection.samples.assign(kept.begin(), kept.end());
  if (selection.samples.size() < 3) root.fail("a selection needs at least 3 samples");
  selection.triangles = reader.triangles(root, "triangles");
  if (selection.triangles.empty()) root.fail("a selection needs at least one triangle");
  for (const Triangle& t : selection.triangles) {
    for (int v : t) {
      if (!kept.count(v)) root.fail("triangles use sample " + std::to_string(dataset.sample(v).id) + " that is not among samples");
    }
  }
  if (root.has("initial_triangles")) {
    selection.initialTriangles = reader.triangles(root, "initial_triangles");
    const nlohmann::json& collapses = root.array("collapses");
    for (size_t i = 0; i < collapses.size(); ++i) {
      const JsonObject entry = root.element("collapses", i);
      Collapse c;
      const std::string where = entry.where("");
      const auto kind = kPlacementKinds.find(entry.string("kind"));
      if (kind == kPlacementKinds.end()) entry.fail("unknown placement kind '" + entry.string("kind") + "'");
      c.kind = kind->second;
      c.first = reader.sample(entry.json().at("first"), where + "first");
      if (c.kind != PlacementKind::Relocation) c.second = reader.sample(entry.json().at("second"), where + "second");
      c.placement = reader.sample(entry.json().at("placement"), where + "placement");
      c.cost = entry.number("cost");
      c.error = entry.numberOr("error", c.cost);
      c.removed = reader.triangles(entry, "removed");
      c.added = reader.triangles(entry, "added");
      selection.collapses.push_back(std::move(c));
    }
    // The log must lead from the initial to the final triangles.
    std::vector<Triangle> replayed = selection.initialTriangles;
    for (size_t i = 0; i < selection.collapses.size(); ++i) {
      for (const Triangle& t : selection.collapses[i].removed) {
        if (!std::binary_search(replayed.begin(), replayed.end(), t)) {
          root.fail("collapses[" + std::to_string(i) + "] removes a triangle the mesh does not have at that step");
        }
      }
      replayed = replayForward(std::move(replayed), std::span(selection.collapses).subspan(i, 1), 1);
    }
    if (replayed != selection.triangles) root.fail("replaying the collapses does not give the final triangles");
  }
  return selection;
}

ViewMesh selectionMesh(const Selection& selection, const Dataset& dataset) {
  return datasetTriangles(dataset, selection.triangles);
}

ViewMesh datasetTriangles(const Dataset& dataset, std::vector<Triangle> triangles) {
  return ViewMesh(samplePositions(dataset), std::move(triangles),
                  std::make_shared<const WalkableRegion>(dataset.walkableRegion()));
}

}  // namespace triwalk
