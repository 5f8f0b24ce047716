#include "signals.h"

#include <csignal>
#include <cstring>
#include <initializer_list>
#include <unistd.h>

namespace fosssim::app {
namespace {

// Written by the handler, read by the step loops: a lock-free atomic is async-signal-safe.
volatile std::sig_atomic_t requested = 0;

extern "C" void onStopSignal(int signal) {
  if (requested != 0) {
    // The second one: the default action (the process ends by the signal, as without FOSSSim's handler).
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  requested = signal;
  // write() is async-signal-safe; stdio is not.
  const char* text = signal == SIGINT ? "\nFOSSSim: SIGINT: stopping after the current step (again to stop at once)\n"
                                      : "\nFOSSSim: SIGTERM: stopping after the current step (again to stop at once)\n";
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

}  // namespace

void installStopHandlers() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  // Restarted system calls: library code (file writes, the X connection, waitpid) need not
  // expect EINTR because of a signal that only sets a flag.
  action.sa_flags = SA_RESTART;
  for (int signal : {SIGINT, SIGTERM}) {
    struct sigaction previous {};
    // A signal ignored by whoever started us (nohup, a shell's background job) stays ignored.
    if (sigaction(signal, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
    sigaction(signal, &action, nullptr);
  }
}

int stopSignal() { return requested; }

const char* signalName(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    default: return "a signal";
  }
}

}  // namespace fosssim::app
