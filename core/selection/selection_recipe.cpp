#include "core/selection/selection_recipe.h"

#include "core/io/dataset.h"
#include "core/selection/selection.h"

namespace triwalk {

nlohmann::json describeSelectionRecipe(const SelectionRecipe& recipe) {
  const SelectionSettings& settings = recipe.selection;
  const RefinementOptions& refinement = settings.refinement;
  nlohmann::json description = describeDecimationOptions(settings.decimation);
  description.update({{"preset", recipe.preset},
                      {"max_error", settings.decimation.maxError},
                      {"relative_error", settings.relativeError},
                      {"target", settings.decimation.targetSamples},
                      {"refine_radius", refinement.radius ? nlohmann::json(*refinement.radius) : nlohmann::json("auto")},
                      {"exchanges",
                       refinement.maxExchanges ? nlohmann::json(*refinement.maxExchanges) : nlohmann::json("auto")},
                      {"refine_screen", refinement.screenedShare},
                      {"refine_priced", refinement.pricedSamples}});
  description.update(describeSelectionErrors(recipe.errors));
  return description;
}

SelectionRecipe readSelectionRecipe(const JsonObject& settings, const Dataset& dataset) {
  SelectionRecipe recipe;
  const std::optional<TriangleErrorSettings> errors = readSelectionErrors(settings, dataset);
  if (!errors) settings.fail("names no error settings");
  recipe.errors = *errors;
  recipe.preset = settings.stringOr("preset", recipe.preset);
  SelectionSettings& selection = recipe.selection;
  selection.decimation = readDecimationOptions(settings);
  selection.decimation.maxError = readThreshold(settings, "max_error", kMaxErrorRange);
  selection.relativeError = readThreshold(settings, "relative_error", kRelativeErrorRange);
  selection.decimation.targetSamples = settings.integerOr("target", 0);
  if (selection.decimation.targetSamples < 0 || selection.decimation.targetSamples > dataset.sampleCount()) {
    settings.fail("target " + std::to_string(selection.decimation.targetSamples) + " is not a count of the data set's " +
                  std::to_string(dataset.sampleCount()) + " samples");
  }
  selection.refinement = readRefinementOptions(settings);
  return recipe;
}

}  // namespace triwalk
