#pragma once
// GLSL sources from shaders/, compiled into the binary (see
// cmake/EmbedShaders.cmake). Empty view for an unknown name.

#include <string_view>

namespace triwalk {

std::string_view embeddedShaderSource(std::string_view name);

}  // namespace triwalk
