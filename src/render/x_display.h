// The X display behind the window: whether it can show OpenGL windows (checked with Xlib before
// glutInit, which ends the process when it cannot open a display), and a sanitizer-build detail.
#pragma once

#include <string>

typedef struct _XDisplay Display;  // Xlib's, without Xlib's macros (its Status would hide ours)

namespace fosssim::render {

/// Opens a connection to the X display after checking that it can show OpenGL windows (GLX, a
/// double-buffered RGBA visual); null with the reason otherwise. Close it with XCloseDisplay.
Display* openCheckedDisplay(std::string& why);

/// Sanitizer builds: keeps the GL driver modules loaded until exit (see x_display.cpp); a no-op
/// otherwise.
void pinDriverModules();

}  // namespace fosssim::render
