// The GLUT backend. GLUT reports events through plain function callbacks, so the window's state
// lives in one object that the callbacks reach through a file-level pointer (one window at a time).
#include "fosssim/render/glut_window.h"

#include "gl_painter.h"
#include "step_pacer.h"
#include "x_display.h"

#include "fosssim/io/staged_file.h"
#include "fosssim/render/camera.h"
#include "fosssim/render/path_trails.h"
#include "fosssim/render/picture.h"
#include "fosssim/render/png_writer.h"
#include "fosssim/render/svg_writer.h"
#include "fosssim/render/window_overlay.h"

#include <GL/freeglut.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#undef Status  // Xlib's macro for int would hide fosssim::Status

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace fosssim::render {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kZoomFactor = 1.25;
constexpr double kPanFraction = 0.1;    // of the visible height per arrow key press
constexpr int kTickMs = 10;             // timer period: fine enough for 100 steps/s and up
constexpr double kMaxStepTimePerTick = 0.05;  // seconds: keep the window responsive
constexpr double kNoteSeconds = 3;      // a note ("saved ...") stays this long
constexpr double kErrorSeconds = 3;     // a failed run's error shows this long before the window closes

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

class Window {
 public:
  Window(const WindowSettings& settings, const SceneFile& file, const State& state, const std::function<Status()>& step)
      : settings_(settings), file_(file), state_(state), step_(step), painter_(gl_),
        trails_(file.look.paths, file.scene.dt), pacer_(settings.stepsPerSecond, Clock::now()) {
    view_.width = settings.width;
    view_.height = settings.height;
    camera_.start(file, state, view_.width, view_.height);
    view_.camera = camera_.camera();
    trails_.record(state);
    paused_ = settings.startPaused;
  }

  Status loadGl() {
    const GlProcLookup lookup = [](const char* name) { return reinterpret_cast<GlProc>(glutGetProcAddress(name)); };
    return loadGlFunctions(lookup, "GLUT window", gl_);
  }
  const Status& status() const { return status_; }

  void display() {
    view_.camera = camera_.update(file_.scene, state_, view_.width, view_.height);
    Picture pic = makePicture(file_, state_, trails_, view_);
    const std::string status = statusText();
    WindowOverlay overlay;
    overlay.status = status + "  (h: keys)";
    if (Clock::now() < noteUntil_) overlay.note = note_;
    if (!status_) overlay.error = status_.message();
    overlay.help = help_;
    addWindowOverlay(pic, overlay);
    painter_.paint(pic);
    if (screenshotDue_) saveScreenshot();  // the back buffer, before the swap leaves it undefined
    glutSwapBuffers();
    const std::string title = "FOSSSim: " + status;
    if (title != title_) {
      glutSetWindowTitle(title.c_str());
      title_ = title;
    }
    // The course's window closed when the scene ended: a scripted -p 0 run returns.
    if (status_ && finished() && !settings_.keepOpen) glutLeaveMainLoop();
  }

  void reshape(int w, int h) {
    view_.width = std::max(w, 1);
    view_.height = std::max(h, 1);
    glutPostRedisplay();
  }

  void key(unsigned char k, int, int) {
    if (help_ && k != 'h' && k != 'H' && k != '?') help_ = false;  // any other key also closes the help
    switch (k) {
      case ' ':
        paused_ = !paused_;
        pacer_.restart(Clock::now());
        break;
      case 's':
      case 'S':
        paused_ = true;
        advance(1);
        break;
      case 'q':
      case 'Q':
      case 27:
        glutLeaveMainLoop();
        return;
      case 'c':
      case 'C':
        // Back to the scene's viewport, or fit the particles where they are now and follow them.
        camera_.refit(file_, state_, view_.width, view_.height);
        view_.camera = camera_.camera();
        break;
      case '+':
      case '=':
        view_.camera.size /= kZoomFactor;
        camera_.take(view_.camera);
        break;
      case '-':
      case '_':
        view_.camera.size *= kZoomFactor;
        camera_.take(view_.camera);
        break;
      case 'r':
      case 'R':
        restart();
        break;
      case 'h':
      case 'H':
      case '?':
        help_ = !help_;
        break;
      case 'i':
      case 'I':
        saveSvg();
        break;
      case 'p':
      case 'P':
        screenshotDue_ = true;  // taken by the next display()
        break;
      default:
        glutPostRedisplay();  // the help may have closed
        return;
    }
    glutPostRedisplay();
  }

  void special(int k, int, int) {
    const double step = kPanFraction * 2 * view_.camera.size;
    if (k == GLUT_KEY_LEFT) view_.camera.cx -= step;
    else if (k == GLUT_KEY_RIGHT) view_.camera.cx += step;
    else if (k == GLUT_KEY_UP) view_.camera.cy += step;
    else if (k == GLUT_KEY_DOWN) view_.camera.cy -= step;
    else return;
    camera_.take(view_.camera);
    glutPostRedisplay();
  }

  void mouse(int button, int buttonState, int x, int y) {
    if (button == GLUT_LEFT_BUTTON) {
      dragging_ = buttonState == GLUT_DOWN;
      dragX_ = x;
      dragY_ = y;
    } else if (buttonState == GLUT_DOWN && (button == 3 || button == 4)) {  // freeglut's wheel
      view_.camera.size = button == 3 ? view_.camera.size / kZoomFactor : view_.camera.size * kZoomFactor;
      camera_.take(view_.camera);
      glutPostRedisplay();
    }
  }

  void motion(int x, int y) {
    if (!dragging_) return;
    // The world point under the cursor follows it (window y grows downwards).
    view_.camera.cx -= (x - dragX_) / view_.scale();
    view_.camera.cy += (y - dragY_) / view_.scale();
    camera_.take(view_.camera);
    dragX_ = x;
    dragY_ = y;
    glutPostRedisplay();
  }

  void tick() {
    glutTimerFunc(kTickMs, [](int) { if (current) current->tick(); }, 0);
    if (stopRequested()) return;
    const auto now = Clock::now();
    if (!note_.empty() && now >= noteUntil_) {
      note_.clear();
      glutPostRedisplay();
    }
    if (!status_ && !settings_.keepOpen && seconds(now - failedAt_) > kErrorSeconds) {
      glutLeaveMainLoop();
      return;
    }
    if (paused_ || finished()) {
      updateRate();
      return;
    }
    const long n = pacer_.due(now, settings_.totalSteps - stepsTaken_);
    const auto begin = Clock::now();
    long done = 0;
    while (done < n && !finished() && seconds(Clock::now() - begin) < kMaxStepTimePerTick)
      if (advance(1)) ++done;
      else break;
    pacer_.took(done);
    updateRate();
  }

  static Window* current;

 private:
  bool finished() const { return stepsTaken_ >= settings_.totalSteps || !status_; }

  /// The caller asks the window to close (a signal): it leaves the loop as q does.
  bool stopRequested() {
    if (!settings_.stopRequested || !settings_.stopRequested()) return false;
    glutLeaveMainLoop();
    return true;
  }

  /// Takes up to n steps; false when it could not (finished or failed).
  bool advance(long n) {
    bool any = false;
    for (long k = 0; k < n && !finished() && !stopRequested(); ++k) {
      status_ = step_();
      if (settings_.stepsRenderOffscreen) restoreContext();
      if (!status_) {  // shown in the window, and runWindow returns it for the caller to report
        failedAt_ = Clock::now();
        glutPostRedisplay();
        return false;
      }
      ++stepsTaken_;
      trails_.record(state_);
      any = true;
    }
    if (any) glutPostRedisplay();
    return any;
  }

  void showNote(const std::string& note) {
    note_ = note;
    noteUntil_ =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kNoteSeconds));
    glutPostRedisplay();
  }

  /// r: the caller resets the state (and its simulator); the window starts its run over.
  void restart() {
    if (!settings_.restart) {
      showNote(settings_.noRestart.empty() ? "r: no restart here" : settings_.noRestart);
      return;
    }
    status_ = settings_.restart();
    if (!status_) failedAt_ = Clock::now();
    stepsTaken_ = 0;
    pacer_.restart(Clock::now());
    trails_.clear();
    trails_.record(state_);
    camera_.refit(file_, state_, view_.width, view_.height);
    view_.camera = camera_.camera();
    showNote(status_ ? "restarted from t = 0" : "the restart failed");
  }

  /// Saved pictures go to the current folder, named after the scene and the step.
  std::string savedName(const char* extension) const {
    char step[32];
    std::snprintf(step, sizeof step, "_step%06ld.", state_.step);
    return std::filesystem::path(file_.path).stem().string() + step + extension;
  }

  void saved(const Status& s, const std::string& path) {
    const std::string text = s ? "saved " + path : s.message();
    std::fprintf(stderr, "FOSSSim: %s\n", text.c_str());
    showNote(text);
  }

  /// i (the course's key): the picture shown, as SVG, without the window's status line.
  void saveSvg() {
    const std::string path = savedName("svg");
    const Picture picture = makePicture(file_, state_, trails_, view_);
    saved(io::writeStaged(path, "the window's SVG", [&](const std::string& to) { return writeSvg(to, picture); }),
          path);
  }

  /// p: the window's pixels as they are about to be shown, as PNG.
  void saveScreenshot() {
    screenshotDue_ = false;
    Image image;
    image.width = view_.width;
    image.height = view_.height;
    std::vector<std::uint8_t> rows(3 * static_cast<std::size_t>(image.width) * image.height);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.ReadPixels(0, 0, image.width, image.height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    const std::size_t row = 3 * static_cast<std::size_t>(image.width);
    image.rgb.resize(rows.size());
    for (int y = 0; y < image.height; ++y)  // OpenGL's rows start at the bottom, PNG's at the top
      std::copy_n(rows.data() + row * (image.height - 1 - y), row, image.rgb.data() + row * y);
    const std::string path = savedName("png");
    // Under a partial name, then renamed: a script that picks the file up as soon as it
    // appears never reads it half written.
    saved(io::writeStaged(path, "the window's screenshot", [&](const std::string& to) { return writePng(to, image); }),
          path);
  }

  /// A step may draw off-screen frames (-g, --movie) through OSMesa on this thread, which leaves
  /// Mesa's dispatch pointing at the off-screen context; re-binding ours puts the window back.
  void restoreContext() {
    Display* dpy = glXGetCurrentDisplay();
    const GLXDrawable drawable = glXGetCurrentDrawable();
    const GLXContext context = glXGetCurrentContext();
    if (!dpy || !context) return;
    glXMakeCurrent(dpy, None, nullptr);
    glXMakeCurrent(dpy, drawable, context);
  }

  void updateRate() {
    if (pacer_.measure(Clock::now(), stepsTaken_)) glutPostRedisplay();
  }

  std::string statusText() const {
    char text[256];
    const char* mode = !status_ ? "failed" : finished() ? "done" : paused_ ? "paused" : "running";
    std::snprintf(text, sizeof text, "%s  step %ld/%ld  %s  %.0f steps/s  %s", settings_.sceneName.c_str(), state_.step,
                  settings_.totalSteps, timeText(state_.time, file_.scene.dt).c_str(), pacer_.rate(), mode);
    return text;
  }

  WindowSettings settings_;
  const SceneFile& file_;
  const State& state_;
  const std::function<Status()>& step_;
  GlFunctions gl_;
  GlPainter painter_;
  View view_;
  FollowCamera camera_;
  bool help_ = false;
  bool screenshotDue_ = false;
  std::string note_;
  Clock::time_point noteUntil_;
  Clock::time_point failedAt_;
  PathTrails trails_;
  Status status_ = Status::ok();
  bool paused_ = true;
  long stepsTaken_ = 0;
  StepPacer pacer_;  // steps due, and the steps per second shown
  bool dragging_ = false;
  int dragX_ = 0, dragY_ = 0;
  std::string title_;
};

Window* Window::current = nullptr;

}  // namespace

Status runWindow(const WindowSettings& settings, const SceneFile& file, const State& state,
                 const std::function<Status()>& step) {
  if (Window::current) return Status::error("a FOSSSim window is already open");
  // Checked again (and held open until GLUT has its own connection): glutInit ends the process
  // when it cannot open the display, and our connection keeps a fresh Xvfb from resetting.
  std::string why;
  Display* probe = openCheckedDisplay(why);
  if (!probe) return Status::error("cannot open a window: " + why);

  int argc = 1;
  char program[] = "FOSSSim";
  char* argv[] = {program, nullptr};
  glutInit(&argc, argv);
  glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
  glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE);
  glutInitWindowSize(settings.width, settings.height);
  Window window(settings, file, state, step);
  const int id = glutCreateWindow(("FOSSSim: " + settings.sceneName).c_str());
  XCloseDisplay(probe);
  pinDriverModules();
  if (Status s = window.loadGl(); !s) {
    glutDestroyWindow(id);
    glutExit();
    return s;
  }
  Window::current = &window;
  glutDisplayFunc([] { Window::current->display(); });
  glutReshapeFunc([](int w, int h) { Window::current->reshape(w, h); });
  glutKeyboardFunc([](unsigned char k, int x, int y) { Window::current->key(k, x, y); });
  glutSpecialFunc([](int k, int x, int y) { Window::current->special(k, x, y); });
  glutMouseFunc([](int b, int s, int x, int y) { Window::current->mouse(b, s, x, y); });
  glutMotionFunc([](int x, int y) { Window::current->motion(x, y); });
  glutTimerFunc(kTickMs, [](int) { if (Window::current) Window::current->tick(); }, 0);
  glutMainLoop();
  Window::current = nullptr;
  if (glutGetWindow() != 0) glutDestroyWindow(id);
  glutExit();
  return window.status();
}

}  // namespace fosssim::render
