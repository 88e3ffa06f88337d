#include "render/gl/shader_program.h"

#include "render/gl/embedded_shaders.h"
#include "render/gl/gl_context.h"

#include <glm/gtc/type_ptr.hpp>

#include <sstream>
#include <utility>
#include <vector>

namespace triwalk {

namespace {

// The info log of a shader or program (the two share the query shape).
template <typename GetParameter, typename GetLog>
std::string infoLog(GLuint object, GetParameter getParameter, GetLog getLog) {
  GLint length = 0;
  getParameter(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(size_t(std::max(length, 1)));
  getLog(object, GLsizei(log.size()), nullptr, log.data());
  return log.data();
}

GLuint compileShader(GLenum stage, std::string_view name) {
  const std::string source = expandedShaderSource(name);
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = infoLog(shader, glGetShaderiv, glGetShaderInfoLog);
    glDeleteShader(shader);
    throw GlUnavailable("shader " + std::string(name) + " does not compile: " + log);
  }
  return shader;
}

}  // namespace

std::string expandedShaderSource(std::string_view name) {
  const std::string_view source = embeddedShaderSource(name);
  if (source.empty()) throw GlUnavailable("no embedded shader named " + std::string(name));
  std::istringstream lines{std::string(source)};
  std::ostringstream expanded;
  std::string line;
  while (std::getline(lines, line)) {
    const std::string directive = "#include \"";
    if (line.rfind(directive, 0) == 0) {
      const std::string included = line.substr(directive.size(), line.find('"', directive.size()) - directive.size());
      expanded << expandedShaderSource(included) << "\n";
    } else {
      expanded << line << "\n";
    }
  }
  return expanded.str();
}

ShaderProgram::ShaderProgram(std::string_view vertexShader, std::string_view fragmentShader)
    : name_(std::string(vertexShader) + "+" + std::string(fragmentShader)) {
  const GLuint vertex = compileShader(GL_VERTEX_SHADER, vertexShader);
  GLuint fragment = 0;
  try {
    fragment = compileShader(GL_FRAGMENT_SHADER, fragmentShader);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = infoLog(program_, glGetProgramiv, glGetProgramInfoLog);
    glDeleteProgram(program_);
    throw GlUnavailable("program " + name_ + " does not link: " + log);
  }
}

ShaderProgram::~ShaderProgram() {
  if (program_) glDeleteProgram(program_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept
    : program_(std::exchange(other.program_, 0)), name_(std::move(other.name_)),
      locations_(std::move(other.locations_)) {}

GLint ShaderProgram::location(const char* name) {
  auto it = locations_.find(name);
  if (it == locations_.end()) it = locations_.emplace(name, glGetUniformLocation(program_, name)).first;
  return it->second;
}

void ShaderProgram::set(const char* name, int value) { glUniform1i(location(name), value); }
void ShaderProgram::set(const char* name, float value) { glUniform1f(location(name), value); }
void ShaderProgram::set(const char* name, glm::vec2 value) { glUniform2f(location(name), value.x, value.y); }
void ShaderProgram::set(const char* name, glm::ivec2 value) { glUniform2i(location(name), value.x, value.y); }
void ShaderProgram::set(const char* name, glm::vec3 value) { glUniform3f(location(name), value.x, value.y, value.z); }
void ShaderProgram::set(const char* name, glm::vec4 value) {
  glUniform4f(location(name), value.x, value.y, value.z, value.w);
}
void ShaderProgram::set(const char* name, const glm::mat4& value) {
  glUniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::setArray(const char* name, const float* values, int count) {
  glUniform1fv(location(name), count, values);
}
void ShaderProgram::setArray(const char* name, const glm::vec3* values, int count) {
  glUniform3fv(location(name), count, glm::value_ptr(values[0]));
}

}  // namespace triwalk
