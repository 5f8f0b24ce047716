// The OSMesa backend: an off-screen OpenGL context rendering into a buffer we own.
#include "fosssim/render/offscreen_renderer.h"

#include "gl_painter.h"

#include <GL/osmesa.h>

#include <cstring>
#include <vector>

// Mesa keeps a few small allocations for the life of the process (OSMesa's framebuffers, the
// GLX/DRI driver's screen state; the DRI driver is unloaded before LeakSanitizer looks, hence
// "<unknown module>"). They are not ours and not growing, so sanitizer builds of every program
// that links the renderer suppress them here rather than in each test's environment.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\nleak:libGLX_mesa.so\nleak:swrast_dri.so\nleak:libgallium\nleak:<unknown module>\n";
}

namespace fosssim::render {

struct OffscreenRenderer::Impl {
  OSMesaContext context = nullptr;
  int width = 0, height = 0;
  std::vector<GLubyte> rgba;  // the colour buffer OSMesa draws into, top row first (see below)
  GlFunctions gl;
  std::unique_ptr<GlPainter> painter;

  ~Impl() {
    if (context) OSMesaDestroyContext(context);
  }

  Status makeCurrent() {
    if (!OSMesaMakeCurrent(context, rgba.data(), GL_UNSIGNED_BYTE, width, height))
      return Status::error("OSMesa: cannot make the off-screen context current");
    // Row 0 of our buffer is the top of the picture: the buffer is then already in the order of
    // PNG rows and ffmpeg frames, and nothing needs flipping.
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    return Status::ok();
  }
};

OffscreenRenderer::OffscreenRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
OffscreenRenderer::~OffscreenRenderer() = default;
int OffscreenRenderer::width() const { return impl_->width; }
int OffscreenRenderer::height() const { return impl_->height; }

Status OffscreenRenderer::create(int width, int height, std::unique_ptr<OffscreenRenderer>& out) {
  if (width <= 0 || height <= 0) return Status::error("OSMesa: frame size must be positive");
  auto impl = std::make_unique<Impl>();
  impl->width = width;
  impl->height = height;
  impl->rgba.assign(static_cast<std::size_t>(width) * height * 4, 0);
  impl->context = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  if (!impl->context) return Status::error("OSMesa: cannot create an off-screen OpenGL context");
  if (Status s = impl->makeCurrent(); !s) return s;
  GLint maxSize[2] = {0, 0};
  OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &maxSize[0]);
  OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &maxSize[1]);
  if ((maxSize[0] > 0 && width > maxSize[0]) || (maxSize[1] > 0 && height > maxSize[1]))
    return Status::error("OSMesa: frame size " + std::to_string(width) + "x" + std::to_string(height) +
                         " exceeds the maximum " + std::to_string(maxSize[0]) + "x" + std::to_string(maxSize[1]));
  const GlProcLookup lookup = [](const char* name) { return reinterpret_cast<GlProc>(OSMesaGetProcAddress(name)); };
  if (Status s = loadGlFunctions(lookup, "OSMesa", impl->gl); !s) return s;
  impl->painter = std::make_unique<GlPainter>(impl->gl);
  out.reset(new OffscreenRenderer(std::move(impl)));
  return Status::ok();
}

Status OffscreenRenderer::render(const Picture& picture, Image& out) {
  Impl& m = *impl_;
  if (picture.view.width != m.width || picture.view.height != m.height)
    return Status::error("OSMesa: picture size does not match the off-screen buffer");
  if (Status s = m.makeCurrent(); !s) return s;
  m.painter->paint(picture);
  m.gl.Finish();
  if (Status s = m.painter->check("OSMesa"); !s) return s;
  out.width = m.width;
  out.height = m.height;
  const std::size_t pixels = static_cast<std::size_t>(m.width) * m.height;
  out.rgb.resize(3 * pixels);
  const GLubyte* src = m.rgba.data();
  std::uint8_t* dst = out.rgb.data();
  for (std::size_t k = 0; k < pixels; ++k, src += 4, dst += 3) std::memcpy(dst, src, 3);
  return Status::ok();
}

}  // namespace fosssim::render
