#pragma once
// A linked GLSL program built from embedded sources (shaders/). Lines
// `#include "file.glsl"` are replaced by that embedded file. Compile and
// link errors throw GlUnavailable with the info log.

#include "render/gl/gl_api.h"

#include <glm/glm.hpp>

#include <string>
#include <string_view>
#include <unordered_map>

namespace triwalk {

class ShaderProgram {
public:
  ShaderProgram(std::string_view vertexShader, std::string_view fragmentShader);
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&&) = delete;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const { glUseProgram(program_); }
  GLuint get() const { return program_; }

  // Uniform setters; a name the linker optimized away is ignored.
  void set(const char* name, int value);
  void set(const char* name, float value);
  void set(const char* name, glm::vec2 value);
  void set(const char* name, glm::ivec2 value);
  void set(const char* name, glm::vec3 value);
  void set(const char* name, glm::vec4 value);
  void set(const char* name, const glm::mat4& value);
  void setArray(const char* name, const float* values, int count);
  void setArray(const char* name, const glm::vec3* values, int count);

private:
  GLint location(const char* name);

  GLuint program_ = 0;
  std::string name_;
  std::unordered_map<std::string, GLint> locations_;
};

// The embedded source with its #include lines expanded.
std::string expandedShaderSource(std::string_view name);

}  // namespace triwalk
