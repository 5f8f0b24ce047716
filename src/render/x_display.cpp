#include "x_display.h"

#include "fosssim/render/glut_window.h"

#include <GL/glx.h>
#include <X11/Xlib.h>
#include <dlfcn.h>
#include <link.h>
#undef Status  // Xlib's macro for int would hide fosssim::Status

#include <chrono>
#include <cstdlib>
#include <thread>

namespace fosssim::render {

#if defined(__SANITIZE_ADDRESS__)
/// Sanitizer builds only: pins the GL driver modules (*_dri.so) that GLX loaded, so that they are
/// still mapped when LeakSanitizer reports at exit and its suppressions (osmesa_context.cpp) can
/// name Mesa's lifetime allocations instead of showing them as "<unknown module>".
void pinDriverModules() {
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void*) {
        const std::string name = info->dlpi_name ? info->dlpi_name : "";
        if (name.find("_dri.so") != std::string::npos) dlopen(name.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
      },
      nullptr);
}
#else
void pinDriverModules() {}
#endif

/// A few retries: Xvfb started without -noreset resets itself when its last
/// client leaves, and refuses connections for a moment while it does.
Display* openCheckedDisplay(std::string& why) {
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name) {
    why = "DISPLAY is not set";
    return nullptr;
  }
  Display* dpy = nullptr;
  for (int attempt = 0; attempt < 5 && !dpy; ++attempt) {
    if (attempt > 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    dpy = XOpenDisplay(nullptr);
  }
  if (!dpy) {
    why = std::string("cannot open the X display \"") + name + "\"";
    return nullptr;
  }
  int errorBase = 0, eventBase = 0;
  if (!glXQueryExtension(dpy, &errorBase, &eventBase)) {
    why = std::string("the X display \"") + name + "\" has no GLX (OpenGL) extension";
    XCloseDisplay(dpy);
    return nullptr;
  }
  int attributes[] = {GLX_RGBA, GLX_DOUBLEBUFFER, None};
  XVisualInfo* visual = glXChooseVisual(dpy, DefaultScreen(dpy), attributes);
  if (!visual) {
    why = std::string("the X display \"") + name + "\" offers no double-buffered RGBA OpenGL visual";
    XCloseDisplay(dpy);
    return nullptr;
  }
  XFree(visual);
  return dpy;
}


bool windowAvailable(std::string& why) {
  Display* dpy = openCheckedDisplay(why);
  if (dpy) XCloseDisplay(dpy);
  return dpy != nullptr;
}

}  // namespace fosssim::render
