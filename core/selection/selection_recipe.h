#pragma once
// Every setting of a selection as one value: the errors its decimation
// reads (width, lattice, warp, blend, error), the decimation and its
// stopping rule, the refinement, and the preset it started from. Written
// into selection.json and tile plans as data, and read back into the same
// value: what is written, read and written again is the same, byte for
// byte.

#include "core/io/json_fields.h"
#include "core/selection/reference_selection.h"
#include "core/selection/triangle_error.h"

#include <nlohmann/json.hpp>

#include <string>

namespace triwalk {

class Dataset;

struct SelectionRecipe {
  TriangleErrorSettings errors;
  SelectionSettings selection;
  std::string preset = "default";  // informative: every setting is written too
};

// The "settings" object of a selection file.
nlohmann::json describeSelectionRecipe(const SelectionRecipe& recipe);

// Reads what describeSelectionRecipe wrote; a missing field keeps the
// value's default. InputError naming the file and field for a bad value
// or settings that name no error option.
SelectionRecipe readSelectionRecipe(const JsonObject& settings, const Dataset& dataset);

}  // namespace triwalk
