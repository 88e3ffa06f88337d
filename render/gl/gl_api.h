#pragma once
// The OpenGL 4.5 core entry points triwalk uses, loaded at run time through
// the current context's getProcAddress (EGL, OSMesa or GLFW), so one binary
// runs on any of the three. The pointers live in namespace triwalk: code in
// that namespace calls glClear(...) as usual, and the names never clash
// with the gl* symbols that libOSMesa or libGL export.

#include <GL/glcorearb.h>

#define TRIWALK_GL_FUNCTIONS(X)                                            \
  X(PFNGLGETSTRINGPROC, glGetString)                                       \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                                   \
  X(PFNGLGETERRORPROC, glGetError)                                         \
  X(PFNGLVIEWPORTPROC, glViewport)                                         \
  X(PFNGLSCISSORPROC, glScissor)                                           \
  X(PFNGLCLEARPROC, glClear)                                               \
  X(PFNGLCLEARCOLORPROC, glClearColor)                                     \
  X(PFNGLCLEARDEPTHPROC, glClearDepth)                                     \
  X(PFNGLENABLEPROC, glEnable)                                             \
  X(PFNGLDISABLEPROC, glDisable)                                           \
  X(PFNGLISENABLEDPROC, glIsEnabled)                                       \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                       \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                                       \
  X(PFNGLCULLFACEPROC, glCullFace)                                         \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                                       \
  X(PFNGLCLIPCONTROLPROC, glClipControl)                                   \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                                   \
  X(PFNGLREADPIXELSPROC, glReadPixels)                                     \
  X(PFNGLFINISHPROC, glFinish)                                             \
  X(PFNGLFLUSHPROC, glFlush)                                               \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                     \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                                 \
  X(PFNGLMULTIDRAWELEMENTSPROC, glMultiDrawElements)                       \
  X(PFNGLCREATETEXTURESPROC, glCreateTextures)                             \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                             \
  X(PFNGLTEXTURESTORAGE2DPROC, glTextureStorage2D)                         \
  X(PFNGLTEXTURESUBIMAGE2DPROC, glTextureSubImage2D)                       \
  X(PFNGLTEXTURESUBIMAGE3DPROC, glTextureSubImage3D)                       \
  X(PFNGLTEXTUREPARAMETERIPROC, glTextureParameteri)                       \
  X(PFNGLTEXTUREPARAMETERFPROC, glTextureParameterf)                       \
  X(PFNGLGENERATETEXTUREMIPMAPPROC, glGenerateTextureMipmap)               \
  X(PFNGLBINDTEXTUREUNITPROC, glBindTextureUnit)                           \
  X(PFNGLGETTEXTUREIMAGEPROC, glGetTextureImage)                           \
  X(PFNGLGETTEXTURESUBIMAGEPROC, glGetTextureSubImage)                     \
  X(PFNGLCREATESAMPLERSPROC, glCreateSamplers)                             \
  X(PFNGLDELETESAMPLERSPROC, glDeleteSamplers)                             \
  X(PFNGLSAMPLERPARAMETERIPROC, glSamplerParameteri)                       \
  X(PFNGLBINDSAMPLERPROC, glBindSampler)                                   \
  X(PFNGLCREATEBUFFERSPROC, glCreateBuffers)                               \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                               \
  X(PFNGLNAMEDBUFFERDATAPROC, glNamedBufferData)                           \
  X(PFNGLNAMEDBUFFERSTORAGEPROC, glNamedBufferStorage)                     \
  X(PFNGLNAMEDBUFFERSUBDATAPROC, glNamedBufferSubData)                     \
  X(PFNGLBINDBUFFERBASEPROC, glBindBufferBase)                             \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                                     \
  X(PFNGLCREATEVERTEXARRAYSPROC, glCreateVertexArrays)                     \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                     \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                           \
  X(PFNGLVERTEXARRAYVERTEXBUFFERPROC, glVertexArrayVertexBuffer)           \
  X(PFNGLVERTEXARRAYELEMENTBUFFERPROC, glVertexArrayElementBuffer)         \
  X(PFNGLENABLEVERTEXARRAYATTRIBPROC, glEnableVertexArrayAttrib)           \
  X(PFNGLDISABLEVERTEXARRAYATTRIBPROC, glDisableVertexArrayAttrib)         \
  X(PFNGLVERTEXARRAYATTRIBFORMATPROC, glVertexArrayAttribFormat)           \
  X(PFNGLVERTEXARRAYATTRIBBINDINGPROC, glVertexArrayAttribBinding)         \
  X(PFNGLCREATEFRAMEBUFFERSPROC, glCreateFramebuffers)                     \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                     \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                           \
  X(PFNGLNAMEDFRAMEBUFFERTEXTUREPROC, glNamedFramebufferTexture)           \
  X(PFNGLNAMEDFRAMEBUFFERTEXTURELAYERPROC, glNamedFramebufferTextureLayer) \
  X(PFNGLNAMEDFRAMEBUFFERDRAWBUFFERSPROC, glNamedFramebufferDrawBuffers)   \
  X(PFNGLNAMEDFRAMEBUFFERREADBUFFERPROC, glNamedFramebufferReadBuffer)     \
  X(PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC, glCheckNamedFramebufferStatus)   \
  X(PFNGLCLEARNAMEDFRAMEBUFFERFVPROC, glClearNamedFramebufferfv)           \
  X(PFNGLCLEARNAMEDFRAMEBUFFERUIVPROC, glClearNamedFramebufferuiv)         \
  X(PFNGLBLITNAMEDFRAMEBUFFERPROC, glBlitNamedFramebuffer)                 \
  X(PFNGLCREATESHADERPROC, glCreateShader)                                 \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                                 \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                               \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                   \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                         \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                                 \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                               \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                                 \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                   \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                 \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                       \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                               \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                                     \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                     \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                                       \
  X(PFNGLUNIFORM2IPROC, glUniform2i)                                       \
  X(PFNGLUNIFORM1FPROC, glUniform1f)                                       \
  X(PFNGLUNIFORM2FPROC, glUniform2f)                                       \
  X(PFNGLUNIFORM3FPROC, glUniform3f)                                       \
  X(PFNGLUNIFORM4FPROC, glUniform4f)                                       \
  X(PFNGLUNIFORM1FVPROC, glUniform1fv)                                     \
  X(PFNGLUNIFORM3FVPROC, glUniform3fv)                                     \
  X(PFNGLUNIFORM4FVPROC, glUniform4fv)                                     \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)

namespace triwalk {

#define TRIWALK_DECLARE_GL_POINTER(type, name) extern type name;
TRIWALK_GL_FUNCTIONS(TRIWALK_DECLARE_GL_POINTER)
#undef TRIWALK_DECLARE_GL_POINTER

using GlProcAddressResolver = void* (*)(const char* name);

// Resolves every entry point of the list for the current context. Returns
// the name of the first one that is missing, or an empty string.
const char* loadGlFunctions(GlProcAddressResolver resolve);

}  // namespace triwalk
