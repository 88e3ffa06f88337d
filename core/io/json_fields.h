#pragma once
// Reading external JSON (manifests, selections, scene descriptions) with a
// clear one-line error naming the file and the field when something is off.

#include "core/support/errors.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace triwalk {

// Parses a JSON file; missing file and malformed JSON become InputError.
nlohmann::json readJsonFile(const std::filesystem::path& path);

// A JSON integer that fits an int, read at full width; InputError naming
// file and where ("field 'samples[0].id'") otherwise.
int jsonInteger(const nlohmann::json& value, const std::string& file, const std::string& where);

// Writes pretty-printed JSON atomically.
void writeJsonFile(const std::filesystem::path& path, const nlohmann::json& document);

// A view of one JSON object that knows which file it came from and where
// in it it is ("samples[3]"), so every error says file, place and problem.
class JsonObject {
public:
  JsonObject(const nlohmann::json& value, std::string file, std::string place = "");

  bool has(const std::string& key) const;
  JsonObject object(const std::string& key) const;
  const nlohmann::json& array(const std::string& key) const;
  JsonObject element(const std::string& key, size_t index) const;  // array(key)[index] as an object

  std::string string(const std::string& key) const;
  double number(const std::string& key) const;
  int integer(const std::string& key) const;
  bool boolean(const std::string& key) const;
  glm::vec3 vec3(const std::string& key) const;
  glm::vec2 vec2(const std::string& key) const;
  glm::vec4 vec4(const std::string& key) const;

  double numberOr(const std::string& key, double fallback) const;
  int integerOr(const std::string& key, int fallback) const;
  std::string stringOr(const std::string& key, const std::string& fallback) const;
  glm::vec3 vec3Or(const std::string& key, glm::vec3 fallback) const;

  [[noreturn]] void fail(const std::string& problem) const;
  const nlohmann::json& json() const { return value_; }
  const std::string& file() const { return file_; }
  std::string where(const std::string& key) const;

private:
  const nlohmann::json& field(const std::string& key) const;
  std::vector<float> numbers(const std::string& key, size_t count) const;

  const nlohmann::json& value_;
  std::string file_;
  std::string place_;
};

}  // namespace triwalk
