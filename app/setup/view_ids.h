#pragma once
// Views named on the command line: "12" is sample 12, "p3" is probe 3.

#include "core/io/dataset.h"

#include <string>
#include <vector>

namespace triwalk {

const ViewRecord& findView(const Dataset& dataset, const std::string& name, const std::string& option);

// Samples only (references must be samples).
int findSampleIndex(const Dataset& dataset, const std::string& name, const std::string& option);

}  // namespace triwalk
