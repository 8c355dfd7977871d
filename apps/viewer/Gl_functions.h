// The OpenGL 3.3 core functions the viewer uses, loaded at run time through the context's own
// loader (glfwGetProcAddress for the window, OSMesaGetProcAddress offscreen), so that one binary
// drives both kinds of context without linking libGL.
#ifndef CGAL_POLICIES_APPS_VIEWER_GL_FUNCTIONS_H
#define CGAL_POLICIES_APPS_VIEWER_GL_FUNCTIONS_H

#include <GL/glcorearb.h>

#include <functional>

#define CGAL_POLICIES_VIEWER_GL_FUNCTIONS(X)                   \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                     \
  X(PFNGLATTACHSHADERPROC, AttachShader)                       \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                           \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                         \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                 \
  X(PFNGLBLENDFUNCPROC, BlendFunc)                             \
  X(PFNGLBUFFERDATAPROC, BufferData)                           \
  X(PFNGLCLEARCOLORPROC, ClearColor)                           \
  X(PFNGLCLEARPROC, Clear)                                     \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                     \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                     \
  X(PFNGLCREATESHADERPROC, CreateShader)                       \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                     \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                     \
  X(PFNGLDELETESHADERPROC, DeleteShader)                       \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                   \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)           \
  X(PFNGLDISABLEPROC, Disable)                                 \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                           \
  X(PFNGLDRAWELEMENTSPROC, DrawElements)                       \
  X(PFNGLENABLEPROC, Enable)                                   \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
  X(PFNGLFINISHPROC, Finish)                                   \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                           \
  X(PFNGLGENTEXTURESPROC, GenTextures)                         \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                 \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)             \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                       \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)               \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                         \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)           \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                         \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                         \
  X(PFNGLPOLYGONMODEPROC, PolygonMode)                         \
  X(PFNGLPOLYGONOFFSETPROC, PolygonOffset)                     \
  X(PFNGLREADPIXELSPROC, ReadPixels)                           \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                       \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                           \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                     \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                             \
  X(PFNGLUNIFORM2FPROC, Uniform2f)                             \
  X(PFNGLUNIFORM3FPROC, Uniform3f)                             \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)               \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                           \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)         \
  X(PFNGLVIEWPORTPROC, Viewport)

namespace apps {

using Gl_proc = void (*)();
using Gl_loader = std::function<Gl_proc(const char* name)>;

struct Gl_functions {
#define CGAL_POLICIES_VIEWER_GL_MEMBER(type, name) type name = nullptr;
  CGAL_POLICIES_VIEWER_GL_FUNCTIONS(CGAL_POLICIES_VIEWER_GL_MEMBER)
#undef CGAL_POLICIES_VIEWER_GL_MEMBER

  // Loads every function with the current context's loader; throws naming the first one missing.
  explicit Gl_functions(const Gl_loader& load);
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_GL_FUNCTIONS_H
