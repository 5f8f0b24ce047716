// FOSSSim's command line: load, then grade (-i), show (window) or run headless.
#include "frontends.h"
#include "options.h"
#include "output_files.h"
#include "outputs.h"
#include "scene_report.h"
#include "signals.h"
#include "stats_output.h"
#include "verify_output.h"

#include "fosssim/core/simulator.h"
#include "fosssim/io/grader.h"
#include "fosssim/io/scene_file.h"

#include <cstdio>
#include <new>
#include <iostream>

namespace fosssim::app {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;  ///< bad input, failed simulation, failed grade
constexpr int kExitUsage = 2;    ///< bad command line

int fail(const std::string& message) {
  std::fprintf(stderr, "FOSSSim: error: %s\n", message.c_str());
  return kExitFailure;
}

/// Runs every step without a window, feeding the observers. SIGINT and SIGTERM (signals.h) end
/// the run between steps.
int runHeadless(SceneFile& file, Simulator& simulator, ObserverList& observers) {
  State state = file.initial;
  Status status = Status::ok();
  for (auto& o : observers.items)
    if (status) status = o->start(file, state, simulator.layout());
  for (long k = 0, steps = file.scene.numSteps(); status && k < steps && !stopSignal(); ++k) {
    status = simulator.step(file.scene, state, &observers);
    for (auto& o : observers.items)
      if (status) status = o->afterStep(file, state, simulator.log());
  }
  return endRun(observers, status, state, file.scene.numSteps());
}

int run(int argc, char** argv) {
  Options options;
  std::string error;
  if (!parseOptions(argc, argv, options, error)) {
    std::fprintf(stderr, "FOSSSim: %s\n", error.c_str());
    return kExitUsage;
  }
  if (options.help) {
    std::fputs(usage().c_str(), stdout);
    return kExitOk;
  }
  if (options.version) {
    std::printf("%s\n", versionText().c_str());
    return kExitOk;
  }
  for (const auto& w : options.warnings) std::fprintf(stderr, "FOSSSim: warning: %s\n", w.c_str());

  SceneFile file;
  const Status loaded = loadScene(options.scene, file);
  if (const int status = reportScene(options, loaded, file); status >= 0) return status;  // errors, --strict, --check
  if (!options.quiet && !file.description.empty()) std::fprintf(stderr, "%s\n", file.description.c_str());

  SimulatorOptions simOptions;
  simOptions.handler.compat = options.compat;
  simOptions.handler.threads = options.threads;
  simOptions.handler.sleep = !options.noSleep;
  simOptions.logPolynomials = (!options.output.empty() && !options.compact) || !options.input.empty();
  std::unique_ptr<Simulator> simulator;
  if (Status s = Simulator::create(file.scene, simOptions, simulator); !s) return fail(s.message());

  if (!options.input.empty()) {
    if (Status s = checkGradedFile(options); !s) return fail(s.message());
    const GradeReport report = gradeFile(file.scene, file.initial, *simulator, simOptions, options.input, std::cout);
    if (report.unreadable) return fail(report.structuralError);  // one error, no verdicts on nothing
    return report.passed(GradeTolerances{}) ? kExitOk : kExitFailure;
  }

  // Before any output is opened: none may be an input.
  if (Status s = checkOutputsAgainstInputs(options); !s) return fail(s.message());
  // A conflict of the command line with the scene: a usage error, as the options' own conflicts.
  if (Status s = checkFrameEvery(options, file.scene.numSteps()); !s) {
    std::fprintf(stderr, "FOSSSim: %s\n", s.message().c_str());
    return kExitUsage;
  }
  for (const std::string& w : earlierFrameWarnings(options, file.scene.numSteps() / options.frameEvery))
    std::fprintf(stderr, "FOSSSim: warning: %s\n", w.c_str());
  installStopHandlers();
  ObserverList observers;
  if (!options.output.empty())
    observers.items.push_back(std::make_unique<TrajectoryOutput>(options.output, options.compact));
  if (options.verify) observers.items.push_back(std::make_unique<VerifyOutput>(*simulator));
  if (!options.stats.empty()) observers.items.push_back(std::make_unique<StatsOutput>(options.stats, *simulator));
  if (Status s = addPictureOutputs(options, file, observers); !s) return fail(s.message());

  if (options.display) {
    std::string why;
    if (windowAvailable(why)) return runWindow(options, file, *simulator, observers);
    std::fprintf(stderr, "FOSSSim: no window (%s); running headless\n", why.c_str());
  }
  if (!options.quiet) observers.items.push_back(std::make_unique<ProgressOutput>());
  return runHeadless(file, *simulator, observers);
}

}  // namespace
}  // namespace fosssim::app

int main(int argc, char** argv) {
  // Any allocation may fail (a scene's size is bounded, but memory is shared): a clear error and
  // exit 1, not std::terminate's abort (exit 134).
  try {
    return fosssim::app::run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr,
                 "FOSSSim: error: out of memory (an allocation failed); try a smaller scene or fewer outputs\n");
    return 1;
  }
}
