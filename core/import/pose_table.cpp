#include "core/import/pose_table.h"

#include "core/io/atomic_file.h"
#include "core/io/json_fields.h"
#include "core/support/errors.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace triwalk {

namespace {

std::string trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::optional<double> parseNumber(const std::string& text) {
  const std::string field = trim(text);
  double value = 0.0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || error != std::errc() || end != field.data() + field.size()) return std::nullopt;
  return value;
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(trim(field));
  return fields;
}

void addPose(PoseTable& table, const std::string& name, const ViewPose& pose, const std::string& subject) {
  if (name.empty()) throw InputError(subject, "empty view name");
  if (!table.emplace(name, pose).second) throw InputError(subject, "view '" + name + "' has a pose twice");
}

ViewPose poseFromFields(const std::vector<double>& numbers, PoseMatrix matrixKind, UpAxis up, const std::string& subject) {
  for (double number : numbers) {
    if (!std::isfinite(number)) throw InputError(subject, "non-finite number");
  }
  if (numbers.size() == 4) return poseFromYaw({numbers[0], numbers[1], numbers[2]}, numbers[3], up);
  return poseFromMatrix(matrixFromRows(numbers), matrixKind, subject);
}

PoseTable readCsv(const std::filesystem::path& path, PoseMatrix matrixKind, UpAxis up) {
  std::stringstream text(readTextFile(path));
  PoseTable table;
  std::string line;
  bool firstContent = true;
  for (int row = 1; std::getline(text, line); ++row) {
    const std::string content = trim(line.substr(0, line.find('#')));
    if (content.empty()) continue;
    const std::string subject = path.string() + ":" + std::to_string(row);
    const std::vector<std::string> fields = splitFields(content);
    // Only the first row may be a header: its second field is a column name, not a number.
    const bool header = firstContent && fields.size() > 1 && !parseNumber(fields[1]);
    firstContent = false;
    if (header) continue;
    if (fields.size() != 5 && fields.size() != 17) {
      throw InputError(subject, std::to_string(fields.size()) +
                                    " fields; expected name,x,y,z,yaw_deg (5) or name and a 4x4 matrix (17)");
    }
    std::vector<double> numbers;
    for (size_t i = 1; i < fields.size(); ++i) {
      const std::optional<double> number = parseNumber(fields[i]);
      if (!number) throw InputError(subject, "field " + std::to_string(i + 1) + " '" + fields[i] + "' is not a number");
      numbers.push_back(*number);
    }
    addPose(table, fields[0], poseFromFields(numbers, matrixKind, up, subject), subject);
  }
  return table;
}

std::vector<double> matrixNumbers(const nlohmann::json& value, const std::string& subject) {
  std::vector<double> numbers;
  const auto take = [&](const nlohmann::json& number) {
    if (!number.is_number()) throw InputError(subject, "matrix entries must be numbers");
    numbers.push_back(number.get<double>());
  };
  if (!value.is_array()) throw InputError(subject, "matrix must be an array");
  for (const nlohmann::json& row : value) {
    if (row.is_array()) {
      if (row.size() != 4) throw InputError(subject, "matrix rows must have 4 numbers");
      for (const nlohmann::json& number : row) take(number);
    } else {
      take(row);
    }
  }
  if (numbers.size() != 16) throw InputError(subject, "matrix must have 16 numbers (4 rows of 4)");
  return numbers;
}

PoseTable readJson(const std::filesystem::path& path, PoseMatrix matrixKind, UpAxis up) {
  const nlohmann::json document = readJsonFile(path);
  const nlohmann::json& views = document.is_object() && document.contains("views") ? document.at("views") : document;
  if (!views.is_array()) throw InputError(path.string(), "expected an array of views (or {\"views\": [...]})");
  PoseTable table;
  for (size_t i = 0; i < views.size(); ++i) {
    if (!views[i].is_object()) throw InputError(path.string(), "views[" + std::to_string(i) + "] is not an object");
    const JsonObject view(views[i], path.string(), "views[" + std::to_string(i) + "]");
    const std::string subject = path.string() + ": " + view.where("name");
    const std::string name = view.string("name");
    std::vector<double> numbers;
    if (view.has("matrix")) {
      numbers = matrixNumbers(view.json().at("matrix"), subject);
    } else {
      const glm::vec3 position = view.vec3("position");
      numbers = {position.x, position.y, position.z, view.numberOr("yaw_degrees", 0.0)};
    }
    addPose(table, name, poseFromFields(numbers, matrixKind, up, subject + " (" + name + ")"), subject);
  }
  return table;
}

}  // namespace

PoseTable readPoseTable(const std::filesystem::path& path, PoseMatrix matrixKind, UpAxis up) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path.string(), "pose file does not exist");
  PoseTable table = path.extension() == ".json" ? readJson(path, matrixKind, up) : readCsv(path, matrixKind, up);
  if (table.empty()) throw InputError(path.string(), "no poses");
  return table;
}

std::vector<double> readNumberFile(const std::filesystem::path& path, size_t count) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path.string(), "file does not exist");
  std::string text = readTextFile(path);
  for (char& c : text) {
    if (c == ',') c = ' ';
  }
  std::stringstream stream(text);
  std::vector<double> numbers;
  std::string token;
  while (stream >> token) {
    const std::optional<double> number = parseNumber(token);
    if (!number) throw InputError(path.string(), "'" + token + "' is not a number");
    if (!std::isfinite(*number)) throw InputError(path.string(), "non-finite number");
    numbers.push_back(*number);
  }
  if (numbers.size() != count) {
    throw InputError(path.string(), std::to_string(numbers.size()) + " numbers; expected " + std::to_string(count));
  }
  return numbers;
}

glm::dmat4 matrixFromRows(const std::vector<double>& rowMajor) {
  TRIWALK_CHECK(rowMajor.size() == 16, "a 4x4 matrix needs 16 numbers");
  glm::dmat4 matrix(0.0);
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) matrix[column][row] = rowMajor[size_t(row * 4 + column)];
  }
  return matrix;
}

std::vector<double> matrixRows(const glm::dmat4& matrix) {
  std::vector<double> rowMajor;
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) rowMajor.push_back(matrix[column][row]);
  }
  return rowMajor;
}

}  // namespace triwalk
