#include "block_table.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sys/stat.h>
#include <utility>
#include <vector>

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

// Cells of side 2 (1 + kTouchingGap) max r: two touching disks lie in the same or in adjacent
// cells. The particles sorted by cell, each looks in its own cell and the 8 around it for higher
// indices, so every pair is counted once.
long touchingPairs(const Scene& scene, const VecX& x) {
  const int n = scene.numParticles();
  double largest = 0;
  for (int i = 0; i < n; ++i) largest = std::max(largest, scene.radius[i]);
  const double side = 2 * (1 + kTouchingGap) * largest;
  if (!(side > 0)) return 0;
  std::vector<std::pair<std::pair<long, long>, int>> cells;  // (cell, particle), sorted
  cells.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double cx = std::floor(x[2 * i] / side), cy = std::floor(x[2 * i + 1] / side);
    if (!std::isfinite(cx) || !std::isfinite(cy) || std::abs(cx) > 1e15 || std::abs(cy) > 1e15) continue;
    cells.push_back({{static_cast<long>(cx), static_cast<long>(cy)}, i});
  }
  std::sort(cells.begin(), cells.end());
  long pairs = 0;
  for (const auto& [cell, i] : cells)
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy) {
        const std::pair<long, long> near{cell.first + dx, cell.second + dy};
        auto it = std::lower_bound(cells.begin(), cells.end(), std::make_pair(near, 0));
        for (; it != cells.end() && it->first == near; ++it) {
          const int j = it->second;
          if (j <= i) continue;
          const double reach = (1 + kTouchingGap) * (scene.radius[i] + scene.radius[j]);
          pairs += (x.segment<2>(2 * j) - x.segment<2>(2 * i)).squaredNorm() <= reach * reach;
        }
      }
  return pairs;
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
  std::printf("  %11s %9s %9s %9s %8s %7s %9s\n", "steps", "ms/step", "failsafe", "in zones", "at rest", "awake",
              "touching");
  for (int b = 0; b < count; ++b) {
    const Block& k = blocks[b];
    char failsafe[16] = "-";
    if (k.failsafeMs >= 0) std::snprintf(failsafe, sizeof failsafe, "%.3f", k.failsafeMs);
    char steps[24];
    std::snprintf(steps, sizeof steps, "%ld-%ld", k.first, k.last);
    char touching[24] = "-";
    if (k.touching >= 0) std::snprintf(touching, sizeof touching, "%ld", k.touching);
    std::printf("  %11s %9.3f %9s %9s %8s %7s %9s\n", steps, k.msPerStep, failsafe, percent(k.inZones).c_str(),
                percent(k.atRest).c_str(), percent(k.awake).c_str(), touching);
  }
  std::fflush(stdout);
}

bool appendBlocksCsv(const std::string& path, const RunLabel& run, const Block* blocks, int count) {
  struct stat info{};
  const bool fresh = stat(path.c_str(), &info) != 0 || info.st_size == 0;
  std::ofstream csv(path, std::ios::app);
  if (!csv) return false;
  if (fresh)
    csv << "engine,scene,n,seed,first_step,last_step,ms_per_step,failsafe_ms_per_step,zone_share,rest_share,"
           "awake_share,touching_pairs\n";
  // Figures an engine does not have stay empty.
  const auto optional = [](auto x) { return x < 0 ? std::string() : std::to_string(x); };
  for (int b = 0; b < count; ++b) {
    const Block& k = blocks[b];
    csv << run.engine << "," << run.scene << "," << run.particles << "," << run.seed << "," << k.first << "," << k.last
        << "," << k.msPerStep << "," << optional(k.failsafeMs) << "," << optional(k.inZones) << "," << k.atRest << ","
        << optional(k.awake) << "," << optional(k.touching) << "\n";
  }
  return static_cast<bool>(csv.flush());
}

}  // namespace fosssim::bench
