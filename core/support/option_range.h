#pragma once
// The values a numeric option may take, held once for every place that
// reads it: a command line (app/setup/quality_options.cpp) and a
// selection file's settings (core/selection/selection.cpp), so the two
// never disagree about what a valid file holds.

namespace triwalk {

struct OptionRange {
  float lowest, highest;

  bool contains(double value) const { return value >= lowest && value <= highest; }
};

}  // namespace triwalk
