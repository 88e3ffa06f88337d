#include "app/decimation_options.h"

namespace triwalk {

void addErrorOptions(CLI::App& command, ErrorArguments& arguments) {
  command.add_option("--error-width", arguments.width,
                     "Panorama width triangle errors are computed at (divides the data set's width)")
      ->capture_default_str();
  command.add_option("--triangle-destinations", arguments.destinations,
                     "Where a triangle's error is measured: centroid (the paper's), quadrature (centroid and the "
                     "three sub-triangle centroids) or interior (up to 8 samples inside it)")
      ->capture_default_str()->check(CLI::IsMember({"centroid", "quadrature", "interior"}));
  addQualityOptions(command, arguments.quality);
}

TriangleErrorSettings triangleErrorSettings(const ErrorArguments& arguments) {
  TriangleErrorSettings settings;
  settings.width = arguments.width;
  settings.destinations = parseTriangleDestinations(arguments.destinations);
  settings.synthesis = synthesisOptions(arguments.quality);
  settings.error = errorOptions(arguments.quality);
  return settings;
}

std::string describeErrorSettings(const TriangleErrorSettings& settings) {
  return "errors at " + std::to_string(settings.width) + "x" + std::to_string(settings.width / 2) + ", " +
         (settings.destinations == TriangleDestinations::Centroid     ? "centroid"
          : settings.destinations == TriangleDestinations::Quadrature ? "quadrature"
                                                                       : "interior") +
         " destinations; " +
         describeQuality(settings.synthesis, settings.error);
}

}  // namespace triwalk
