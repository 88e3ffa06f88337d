#pragma once
// Pose files of imported captures: a table of named poses (CSV or JSON),
// a 4x4 matrix file, a file holding one number.
//
// CSV, one view per row, '#' starts a comment, an optional header row:
//   name,x,y,z,yaw_deg             position and yaw about the up axis
//   name,m00,m01,...,m33           a 4x4 matrix, row by row
// JSON: an array (or {"views": [...]}) of
//   {"name": "a", "position": [x, y, z], "yaw_degrees": 0}   or
//   {"name": "a", "matrix": [[m00, m01, m02, m03], ... 4 rows]}  (or 16 numbers)

#include "core/import/view_pose.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace triwalk {

using PoseTable = std::map<std::string, ViewPose>;

// Poses by view name, in the source's axes. Throws InputError naming the
// file and row for a malformed row, a non-finite number, a matrix that is
// not rigid, or a name given twice.
PoseTable readPoseTable(const std::filesystem::path& path, PoseMatrix matrixKind, UpAxis up);

// All numbers of a text file separated by spaces, commas or line breaks;
// throws unless there are exactly count, all finite.
std::vector<double> readNumberFile(const std::filesystem::path& path, size_t count);

// A 4x4 matrix from 16 numbers given row by row, and back.
glm::dmat4 matrixFromRows(const std::vector<double>& rowMajor);
std::vector<double> matrixRows(const glm::dmat4& matrix);

}  // namespace triwalk
