#include "gl_painter.h"

#include <cstdio>
#include <string>
#include <type_traits>

namespace fosssim::render {

Status loadGlFunctions(const GlProcLookup& lookup, const char* backend, GlFunctions& gl) {
  bool ok = true;
  std::string missing;
  auto load = [&](auto& fn, const char* name) {
    const GlProc p = lookup(name);
    if (!p && ok) {
      ok = false;
      missing = name;
    }
    fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(p);
  };
  load(gl.Viewport, "glViewport");
  load(gl.ClearColor, "glClearColor");
  load(gl.Clear, "glClear");
  load(gl.MatrixMode, "glMatrixMode");
  load(gl.LoadIdentity, "glLoadIdentity");
  load(gl.Ortho, "glOrtho");
  load(gl.Enable, "glEnable");
  load(gl.Disable, "glDisable");
  load(gl.BlendFunc, "glBlendFunc");
  load(gl.EnableClientState, "glEnableClientState");
  load(gl.DisableClientState, "glDisableClientState");
  load(gl.VertexPointer, "glVertexPointer");
  load(gl.ColorPointer, "glColorPointer");
  load(gl.DrawArrays, "glDrawArrays");
  load(gl.ReadPixels, "glReadPixels");
  load(gl.PixelStorei, "glPixelStorei");
  load(gl.Finish, "glFinish");
  load(gl.GetError, "glGetError");
  if (!ok) return Status::error(std::string(backend) + ": OpenGL entry point " + missing + " not found");
  return Status::ok();
}

void GlPainter::paint(const Picture& pic) {
  const View& view = pic.view;
  gl_.Viewport(0, 0, view.width, view.height);
  gl_.MatrixMode(GL_PROJECTION);
  gl_.LoadIdentity();
  gl_.Ortho(0, view.width, 0, view.height, -1, 1);  // the tessellator works in pixels
  gl_.MatrixMode(GL_MODELVIEW);
  gl_.LoadIdentity();
  gl_.Disable(GL_DEPTH_TEST);
  gl_.Disable(GL_DITHER);  // exact colours: tests and users compare them with the scene file's
  gl_.ClearColor(static_cast<GLclampf>(pic.background.r), static_cast<GLclampf>(pic.background.g),
                 static_cast<GLclampf>(pic.background.b), 1.0f);
  gl_.Clear(GL_COLOR_BUFFER_BIT);

  mesh_.clear();
  tessellate(pic, mesh_);
  if (mesh_.vertexCount() == 0) return;
  gl_.Enable(GL_BLEND);
  gl_.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  gl_.EnableClientState(GL_VERTEX_ARRAY);
  gl_.EnableClientState(GL_COLOR_ARRAY);
  gl_.VertexPointer(2, GL_FLOAT, 0, mesh_.xy.data());
  gl_.ColorPointer(4, GL_FLOAT, 0, mesh_.rgba.data());
  gl_.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(mesh_.vertexCount()));
  gl_.DisableClientState(GL_COLOR_ARRAY);
  gl_.DisableClientState(GL_VERTEX_ARRAY);
  gl_.Disable(GL_BLEND);
}

Status GlPainter::check(const char* what) const {
  const GLenum error = gl_.GetError();
  if (error == GL_NO_ERROR) return Status::ok();
  return Status::error(std::string(what) + ": OpenGL error 0x" + [&] {
    char hex[16];
    std::snprintf(hex, sizeof hex, "%04x", static_cast<unsigned>(error));
    return std::string(hex);
  }());
}

}  // namespace fosssim::render
