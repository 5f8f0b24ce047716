// The few OpenGL 1.1 entry points the painter uses, called through pointers that each backend
// fetches from its own context (OSMesaGetProcAddress, glutGetProcAddress). Calling gl* symbols
// directly would bind them to whichever of libGL (GLVND) and libOSMesa the dynamic linker sees
// first, and one of the two backends would then draw into nothing.
#pragma once

#include "fosssim/core/status.h"

#include <GL/gl.h>

#include <functional>

namespace fosssim::render {

struct GlFunctions {
  void(APIENTRY* Viewport)(GLint, GLint, GLsizei, GLsizei) = nullptr;
  void(APIENTRY* ClearColor)(GLclampf, GLclampf, GLclampf, GLclampf) = nullptr;
  void(APIENTRY* Clear)(GLbitfield) = nullptr;
  void(APIENTRY* MatrixMode)(GLenum) = nullptr;
  void(APIENTRY* LoadIdentity)() = nullptr;
  void(APIENTRY* Ortho)(GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble) = nullptr;
  void(APIENTRY* Enable)(GLenum) = nullptr;
  void(APIENTRY* Disable)(GLenum) = nullptr;
  void(APIENTRY* BlendFunc)(GLenum, GLenum) = nullptr;
  void(APIENTRY* EnableClientState)(GLenum) = nullptr;
  void(APIENTRY* DisableClientState)(GLenum) = nullptr;
  void(APIENTRY* VertexPointer)(GLint, GLenum, GLsizei, const GLvoid*) = nullptr;
  void(APIENTRY* ColorPointer)(GLint, GLenum, GLsizei, const GLvoid*) = nullptr;
  void(APIENTRY* DrawArrays)(GLenum, GLint, GLsizei) = nullptr;
  void(APIENTRY* ReadPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, GLvoid*) = nullptr;
  void(APIENTRY* PixelStorei)(GLenum, GLint) = nullptr;
  void(APIENTRY* Finish)() = nullptr;
  GLenum(APIENTRY* GetError)() = nullptr;
};

/// A backend's way of looking up an entry point by name (null when it has none).
using GlProc = void (*)();
using GlProcLookup = std::function<GlProc(const char*)>;

/// Fills `gl` through `lookup`; fails naming the first missing entry point. `backend` names the
/// backend in the message.
Status loadGlFunctions(const GlProcLookup& lookup, const char* backend, GlFunctions& gl);

}  // namespace fosssim::render
