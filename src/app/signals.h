// SIGINT and SIGTERM end a run cleanly: the handler only records the signal; the step loops
// (headless in main.cpp, the window's timer) look at it between steps, so the current step
// finishes, every output is closed after whole records, and the process exits 128 + the signal
// (130 for SIGINT, 143 for SIGTERM). A second signal while the first is being honoured ends the
// process at once, the ordinary way (for a step that takes too long).
#pragma once

namespace fosssim::app {

/// Installs the handlers for SIGINT and SIGTERM (once; later calls do nothing).
void installStopHandlers();

/// The signal that asked the run to stop, or 0.
int stopSignal();

/// "SIGINT", "SIGTERM" or "signal N", for messages.
const char* signalName(int signal);

}  // namespace fosssim::app
