#pragma once
// Bounds on what triwalk accepts from outside (files and options), each
// set where the computation stops being meaningful or the machine stops
// coping, and checked where the value enters: a value past them is refused
// in one line before any work, instead of reaching a float that overflows
// or an allocation that cannot be met.

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace triwalk {

// Positions are float metres. Beyond 100 km from the origin the step
// between neighbouring floats exceeds 7 mm, coarser than the warp needs,
// and at about 1e19 m the squared distances the warp forms overflow (a
// view at x = 1e30 turned every warped pixel into NaN). A capture far
// from the origin (UTM coordinates, say) must be moved near it first.
inline constexpr double kMaxCoordinateMetres = 1e5;
inline constexpr const char* kCoordinateBoundText = "100 km (1e5 m)";
// False for NaN and infinities too.
inline bool withinCoordinateBound(double coordinate) { return std::abs(coordinate) <= kMaxCoordinateMetres; }

// A view's yaw, degrees: any turn is within one revolution; past a
// million degrees a float's step exceeds a tenth of a degree.
inline constexpr double kMaxYawDegrees = 36000.0;

// The largest text file triwalk reads (JSON manifests, selections,
// regions and scene descriptions; camera paths, pose tables): a
// 10,000-view manifest is about 2 MB and its selection with the collapse
// log about 4 MB; 256 MiB leaves room for a million views and refuses a
// symlink to /dev/zero before reading it.
inline constexpr std::uintmax_t kMaxTextFileBytes = std::uintmax_t(256) << 20;

// Views of one data set (samples plus probes): ids are int, and a
// capture's plan holds a record per view before the first is rendered.
inline constexpr std::size_t kMaxViews = 10'000'000;

}  // namespace triwalk
