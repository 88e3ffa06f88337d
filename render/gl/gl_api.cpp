#include "render/gl/gl_api.h"

namespace triwalk {

#define TRIWALK_DEFINE_GL_POINTER(type, name) type name = nullptr;
TRIWALK_GL_FUNCTIONS(TRIWALK_DEFINE_GL_POINTER)
#undef TRIWALK_DEFINE_GL_POINTER

const char* loadGlFunctions(GlProcAddressResolver resolve) {
#define TRIWALK_LOAD_GL_POINTER(type, name)                  \
  name = reinterpret_cast<type>(resolve(#name));             \
  if (!name) return #name;
  TRIWALK_GL_FUNCTIONS(TRIWALK_LOAD_GL_POINTER)
#undef TRIWALK_LOAD_GL_POINTER
  return "";
}

}  // namespace triwalk
