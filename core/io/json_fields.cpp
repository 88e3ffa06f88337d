#include "core/io/json_fields.h"

#include "core/io/atomic_file.h"

#include <cstdint>
#include <limits>

#include <cmath>

namespace triwalk {

nlohmann::json readJsonFile(const std::filesystem::path& path) {
  const std::string text = readTextFile(path);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& error) {
    // Syntax errors, and numbers that overflow a double (found by the
    // manifest fuzzer). nlohmann's message starts with its own id in brackets; keep the readable part.
    std::string message = error.what();
    const size_t bracket = message.find("] ");
    if (bracket != std::string::npos) message = message.substr(bracket + 2);
    throw InputError(path.string(), "malformed JSON: " + message);
  }
}

void writeJsonFile(const std::filesystem::path& path, const nlohmann::json& document) {
  writeTextFileAtomically(path, document.dump(2) + "\n");
}

JsonObject::JsonObject(const nlohmann::json& value, std::string file, std::string place)
    : value_(value), file_(std::move(file)), place_(std::move(place)) {
  if (!value_.is_object()) fail(place_.empty() ? "top level is not a JSON object" : "is not a JSON object");
}

std::string JsonObject::where(const std::string& key) const { return place_.empty() ? key : place_ + "." + key; }

void JsonObject::fail(const std::string& problem) const {
  throw InputError(file_, place_.empty() ? problem : place_ + ": " + problem);
}

bool JsonObject::has(const std::string& key) const { return value_.contains(key); }

const nlohmann::json& JsonObject::field(const std::string& key) const {
  auto it = value_.find(key);
  if (it == value_.end()) throw InputError(file_, "missing field '" + where(key) + "'");
  return *it;
}

JsonObject JsonObject::object(const std::string& key) const {
  const nlohmann::json& value = field(key);
  if (!value.is_object()) throw InputError(file_, "field '" + where(key) + "' is not an object");
  return JsonObject(value, file_, where(key));
}

const nlohmann::json& JsonObject::array(const std::string& key) const {
  const nlohmann::json& value = field(key);
  if (!value.is_array()) throw InputError(file_, "field '" + where(key) + "' is not an array");
  return value;
}

JsonObject JsonObject::element(const std::string& key, size_t index) const {
  const nlohmann::json& value = array(key).at(index);
  const std::string place = where(key) + "[" + std::to_string(index) + "]";
  if (!value.is_object()) throw InputError(file_, "'" + place + "' is not an object");
  return JsonObject(value, file_, place);
}

std::string JsonObject::string(const std::string& key) const {
  const nlohmann::json& value = field(key);
  if (!value.is_string()) throw InputError(file_, "field '" + where(key) + "' is not a string");
  return value.get<std::string>();
}

double JsonObject::number(const std::string& key) const {
  const nlohmann::json& value = field(key);
  if (!value.is_number()) throw InputError(file_, "field '" + where(key) + "' is not a number");
  const double number = value.get<double>();
  if (!std::isfinite(number)) throw InputError(file_, "field '" + where(key) + "' is not finite");
  return number;
}

int jsonInteger(const nlohmann::json& value, const std::string& file, const std::string& where) {
  if (!value.is_number_integer()) throw InputError(file, where + " is not an integer");
  // Read at full width first: get<int>() would keep the low 32 bits, so
  // 4294967301 would read as 5.
  const bool inRange = value.is_number_unsigned()
                           ? value.get<std::uint64_t>() <= std::uint64_t(std::numeric_limits<int>::max())
                           : value.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
                                 value.get<std::int64_t>() <= std::numeric_limits<int>::max();
  if (!inRange) throw InputError(file, where + " " + value.dump() + " is out of range (at most 2147483647 in size)");
  return value.get<int>();
}

int JsonObject::integer(const std::string& key) const { return jsonInteger(field(key), file_, "field '" + where(key) + "'"); }

bool JsonObject::boolean(const std::string& key) const {
  const nlohmann::json& value = field(key);
  if (!value.is_boolean()) throw InputError(file_, "field '" + where(key) + "' is not true or false");
  return value.get<bool>();
}

std::vector<float> JsonObject::numbers(const std::string& key, size_t count) const {
  const nlohmann::json& value = field(key);
  if (!value.is_array() || value.size() != count) {
    throw InputError(file_, "field '" + where(key) + "' is not an array of " + std::to_string(count) + " numbers");
  }
  std::vector<float> result;
  for (const nlohmann::json& element : value) {
    // Finite as a double and as the float it is kept in (1e39 is not).
    if (!element.is_number() || !std::isfinite(element.get<double>()) || !std::isfinite(element.get<float>())) {
      throw InputError(file_, "field '" + where(key) + "' holds a value that is not a finite number");
    }
    result.push_back(element.get<float>());
  }
  return result;
}

glm::vec2 JsonObject::vec2(const std::string& key) const {
  const auto v = numbers(key, 2);
  return {v[0], v[1]};
}

glm::vec3 JsonObject::vec3(const std::string& key) const {
  const auto v = numbers(key, 3);
  return {v[0], v[1], v[2]};
}

glm::vec4 JsonObject::vec4(const std::string& key) const {
  const auto v = numbers(key, 4);
  return {v[0], v[1], v[2], v[3]};
}

double JsonObject::numberOr(const std::string& key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

int JsonObject::integerOr(const std::string& key, int fallback) const { return has(key) ? integer(key) : fallback; }

std::string JsonObject::stringOr(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

glm::vec3 JsonObject::vec3Or(const std::string& key, glm::vec3 fallback) const {
  return has(key) ? vec3(key) : fallback;
}

}  // namespace triwalk
