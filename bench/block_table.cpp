#include "block_table.h"

#include <fstream>
#include <sys/stat.h>

namespace fosssim::bench {

double restSpeed(double radius, double dt) { return 1e-3 * radius / dt; }

double atRestShare(const Scene& scene, const VecX& v) {
  int movable = 0, resting = 0;
  for (int i = 0; i < scene.numParticles(); ++i) {
    if (scene.isFixed(i)) continue;
    ++movable;
    resting += v.segment<2>(2 * i).norm() < restSpeed(scene.radius[i], scene.dt);
  }
  return movable ? static_cast<double>(resting) / movable : 1.0;
}

namespace {

/// A share as a percentage, or "-" where the engine has no such figure.
std::string percent(double share) {
  if (share < 0) return "-";
  char text[16];
  std::snprintf(text, sizeof text, "%.1f%%", 100.0 * share);
  return text;
}

}  // namespace

RunLabel runLabel(const std::string& engine, const BenchScene& s, unsigned seed) {
  const int n = s.scene.numParticles();
  return RunLabel{engine, s.name, n, seed, n ? restSpeed(s.scene.radius[0], s.scene.dt) : 0.0};
}

void printBlocks(const RunLabel& run, const Block* blocks, int count) {
  std::printf("  %s, %s N=%d seed %u, per block of %ld steps (at rest: |v| < %g m/s):\n", run.engine.c_str(),
              run.scene.c_str(), run.particles, run.seed, kBlockSteps, run.restSpeed);
  std::printf("  %11s %9s %9s %9s %8s %7s\n", "steps", "ms/step", "failsafe", "in zones", "at rest", "awake");
  for (int b = 0; b < count; ++b) {
    const Block& k = blocks[b];
    char failsafe[16] = "-";
    if (k.failsafeMs >= 0) std::snprintf(failsafe, sizeof failsafe, "%.3f", k.failsafeMs);
    char steps[24];
    std::snprintf(steps, sizeof steps, "%ld-%ld", k.first, k.last);
    std::printf("  %11s %9.3f %9s %9s %8s %7s\n", steps, k.msPerStep, failsafe, percent(k.inZones).c_str(),
                percent(k.atRest).c_str(), percent(k.awake).c_str());
  }
  std::fflush(stdout);
}

bool appendBlocksCsv(const std::string& path, const RunLabel& run, const Block* blocks, int count) {
  struct stat info{};
  const bool fresh = stat(path.c_str(), &info) != 0 || info.st_size == 0;
  std::ofstream csv(path, std::ios::app);
  if (!csv) return false;
  if (fresh) csv << "engine,scene,n,seed,first_step,last_step,ms_per_step,failsafe_ms_per_step,zone_share,rest_share,awake_share\n";
  // Figures an engine does not have stay empty.
  const auto optional = [](double x) { return x < 0 ? std::string() : std::to_string(x); };
  for (int b = 0; b < count; ++b) {
    const Block& k = blocks[b];
    csv << run.engine << "," << run.scene << "," << run.particles << "," << run.seed << "," << k.first << "," << k.last
        << "," << k.msPerStep << "," << optional(k.failsafeMs) << "," << optional(k.inZones) << "," << k.atRest << ","
        << optional(k.awake) << "\n";
  }
  return static_cast<bool>(csv.flush());
}

}  // namespace fosssim::bench
