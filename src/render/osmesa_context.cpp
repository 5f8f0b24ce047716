// The OSMesa backend: an off-screen OpenGL context rendering into a buffer we own.
#include "fosssim/render/offscreen_renderer.h"

#include "gl_painter.h"

#include <GL/osmesa.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

// Mesa keeps a few small allocations for the life of the process (OSMesa's framebuffers, the
// GLX/DRI driver's screen state; the DRI driver is unloaded before LeakSanitizer looks, hence
// "<unknown module>"). They are not ours and not growing, so sanitizer builds of every program
// that links the renderer suppress them here rather than in each test's environment.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\nleak:libGLX_mesa.so\nleak:swrast_dri.so\nleak:libgallium\nleak:<unknown module>\n";
}

namespace fosssim::render {
namespace {

// Mesa crashes (SIGSEGV inside libOSMesa, exit 139) when one of its allocations fails, in
// OSMesaCreateContextExt or at the first frame, where our own fail cleanly (std::bad_alloc: "out
// of memory"). So what Mesa will need is checked before it is asked for anything. Measured under
// `ulimit -v` (Mesa 22.3 llvmpipe, gcc 12 Release; the least limit at which a one-step -g 1 run
// completes): the context took 79 MiB over a run without frames, and each of llvmpipe's
// rasterizer threads 115 to 213 MiB more (a stack, a malloc arena, LLVM's state); every pixel of
// the frame size took 11 bytes: our RGBA buffer (4, held before the check), our RGB frame (3) and
// Mesa's colour buffer (4). At 10000x10000 and 1.2 GB the run crashed; 8000x8000 crashed at some
// limits between 650 and 750 MB, inside OSMesaCreateContextExt.
constexpr std::size_t kMiB = std::size_t{1} << 20;

/// llvmpipe's rasterizer threads: LP_NUM_THREADS, else one per processor, at most 32.
std::size_t rasterizerThreads() {
  if (const char* given = std::getenv("LP_NUM_THREADS"))
    return static_cast<std::size_t>(std::max(0L, std::atol(given)));
  return static_cast<std::size_t>(std::clamp(sysconf(_SC_NPROCESSORS_ONLN), 1L, 32L));
}

/// What creating the context and drawing the first frame take, the RGBA buffer already held.
std::size_t bytesMesaNeeds(int width, int height) {
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  return 128 * kMiB + rasterizerThreads() * 160 * kMiB + pixels * (3 + 4);
}

Status outOfMemory(int width, int height, std::size_t needed, const std::string& detail, const char* smaller) {
  return Status::error("out of memory for " + std::to_string(width) + "x" + std::to_string(height) +
                       " frames: OSMesa and the frames need about " + std::to_string(needed / kMiB) + " MiB more, " +
                       detail + "; try a smaller " + smaller);
}

/// Under an address-space limit (ulimit -v) the room left is known: the limit less what the
/// process maps now (/proc/self/statm). Without one, the frame's share is allocated and given
/// back (malloc fails at once where memory is not overcommitted).
Status checkMemory(int width, int height, const char* smaller) {
  const std::size_t needed = bytesMesaNeeds(width, height);
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    unsigned long pages = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
      if (std::fscanf(f, "%lu", &pages) != 1) pages = 0;
      std::fclose(f);
    }
    const std::size_t mapped = pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    const std::size_t room = limit.rlim_cur > mapped ? limit.rlim_cur - mapped : 0;
    if (pages > 0 && room < needed)
      return outOfMemory(width, height, needed, "and the address-space limit (ulimit -v) leaves " +
                                                    std::to_string(room / kMiB) + " MiB",
                         smaller);
  }
  const std::size_t frameBytes =
      static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * (3 + 4) + 64 * kMiB;
  void* volatile probe = std::malloc(frameBytes);  // volatile: the compiler may not drop an unused malloc
  if (!probe)
    return outOfMemory(width, height, needed, "and " + std::to_string(frameBytes / kMiB) + " MiB cannot be had",
                       smaller);
  std::free(probe);
  return Status::ok();
}

}  // namespace

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

Status OffscreenRenderer::create(int width, int height, std::unique_ptr<OffscreenRenderer>& out, const char* smaller) {
  if (width <= 0 || height <= 0) return Status::error("OSMesa: frame size must be positive");
  auto impl = std::make_unique<Impl>();
  impl->width = width;
  impl->height = height;
  impl->rgba.assign(static_cast<std::size_t>(width) * height * 4, 0);
  if (Status s = checkMemory(width, height, smaller); !s) return s;
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
