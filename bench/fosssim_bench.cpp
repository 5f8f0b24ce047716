// fosssim-bench: milliseconds per step by phase on the scalable scenes (bench_scenes.h), and
// narrow-phase queries per second, on one core. Prints a table; --csv also writes the figures.
//
//   fosssim-bench [--sizes 1000,10000,100000] [--scenes rain,gas,chains,bullets] [--collision hybrid]
//                 [--integrator NAME]
//                 [--steps K] [--repeats R] [--all-pairs] [--compat] [--threads T] [--csv FILE] [--no-queries]
//                 [--no-steps] [--alternatives] [--seed S] [--blocks] [--blocks-csv FILE]
//                                                    (fosssim-bench -h says what each does)
// --alternatives also times the broad-phase designs that were measured before choosing one
// (broad_phase_alternatives.h) on the rain, gas and bullets scenes.
//
// Every scene and size runs in a child process of its own, so that its memory figure (peak
// resident memory grown since the child started, per particle) is its own. A run is a short
// warm-up (discarded), then R runs of the scene's full length from its initial state; the
// figures are those of the fastest run (the machine may be shared). Query rates are CPU time of
// this thread, best of R.
//
// Runs of 1,000 steps or more (the dense-pile family's) also get a table per block of 100 steps
// (block_table.h): ms per step, the failsafe's part, the share of particles in failsafe zones
// and the share at rest, so that a cost that creeps or a pile that rests expensively shows.
#include "bench_options.h"
#include "bench_scenes.h"
#include "block_table.h"
#include "broad_phase_alternatives.h"
#include "query_rates.h"

#include "cli_values.h"
#include "fosssim/core/simulator.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace fosssim::bench {
namespace {

/// What a child reports about one scene and size (plain data: it crosses a pipe).
struct Figures {
  int particles = 0, edges = 0;
  long steps = 0;  ///< steps of the run reported (fewer than asked when it hit --time-limit)
  bool stopped = false;  ///< the run hit --time-limit
  double integrate = 0, broad = 0, narrow = 0, response = 0, failsafe = 0, total = 0;  ///< seconds, whole run
  double candidates = 0, queries = 0, collisions = 0, passes = 0, rounds = 0;  ///< summed over the run
  long failsafeSteps = 0;
  int largestZone = 0;
  double zoneParticles = 0;  ///< particles in failsafe zones at the ends of steps, summed over the run
  long rigidSteps = 0;       ///< steps in which some zone moved rigidly (or stopped)
  double jammedParticles = 0;  ///< particles a jam stopped for the rest of their step, summed over the run
  double heldParticles = 0;    ///< particles a budget-ended solve held at rest for the rest of their step, summed
  double zoneUpdates = 0;      ///< the failsafe's Gauss-Seidel updates, summed over the run
  double bytesPerParticle = 0;  ///< peak resident memory grown while building and running
  double growthBytes = 0;       ///< resident memory grown from a tenth into the first run to its end
  Block blocks[kMaxBlocks];  ///< the fastest run's blocks of kBlockSteps steps (the first kMaxBlocks)
  int blockCount = 0;
  double restSpeed = 0;
  bool ok = false;
  char error[200] = {};
};

long residentBytes() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * sysconf(_SC_PAGESIZE);
}

long peakResidentBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss * 1024L;
}

/// Where the figures come from: the machine and how busy it was at the start.
void printMachine() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(cpuinfo, line))
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  std::ifstream loadavg("/proc/loadavg");
  double load1 = 0, load5 = 0;
  loadavg >> load1 >> load5;
  std::printf("machine: %s, %ld hardware threads, load average %.2f (1 min) %.2f (5 min) at the start\n", model.c_str(),
              sysconf(_SC_NPROCESSORS_ONLN), load1, load5);
}

Figures runScene(const Options& o, const std::string& kind, int n) {
  Figures f;
  const long before = residentBytes();
  BenchScene s;
  if (!makeScene(kind, n, o.collision, o.seed, s)) {
    std::snprintf(f.error, sizeof f.error, "unknown scene %s", kind.c_str());
    return f;
  }
  if (!o.integrator.empty()) s.scene.integrator = o.integrator;
  f.particles = s.scene.numParticles();
  f.edges = static_cast<int>(s.scene.edges.size());
  f.steps = o.steps > 0 ? o.steps : s.scene.numSteps();
  f.restSpeed = runLabel("", s, o.seed).restSpeed;
  SimulatorOptions options;
  options.handler.allPairs = o.allPairs;
  options.handler.compat = o.compat;
  options.handler.threads = o.threads;
  options.handler.sleep = !o.noSleep;
  options.handler.hold = !o.noHold;
  std::unique_ptr<Simulator> sim;
  if (Status st = Simulator::create(s.scene, options, sim); !st) {
    std::snprintf(f.error, sizeof f.error, "%s", st.message().c_str());
    return f;
  }
  sim->setTiming(true);
  long early = 0;  // resident memory a tenth into a run: the run's growth is measured from here
  // Timed by blocks of kBlockSteps steps; the share at rest is taken between blocks, untimed.
  auto run = [&](long steps, Figures& into) -> bool {
    State state = s.state;
    into = Figures{};
    Block block;
    int blockZone = 0;  // particle-steps in zones in this block
    double blockFailsafe = 0;
    auto start = std::chrono::steady_clock::now();
    for (long k = 0; k < steps; ++k) {
      if (k == steps / 10) early = residentBytes();
      if (Status st = sim->step(s.scene, state); !st) {
        std::snprintf(f.error, sizeof f.error, "%s", st.message().c_str());
        return false;
      }
      const StepStats& st = sim->stats();
      into.integrate += st.integrate;
      into.broad += st.broadPhase;
      into.narrow += st.narrowPhase;
      into.response += st.response;
      into.failsafe += st.failsafe;
      into.candidates += static_cast<double>(st.candidatePairs);
      into.queries += static_cast<double>(st.queries[0] + st.queries[1] + st.queries[2]);
      into.collisions += static_cast<double>(st.collisions);
      into.passes += st.impulsePasses;
      into.rounds += st.failsafeRounds;
      into.failsafeSteps += st.failsafeUsed;
      into.largestZone = std::max(into.largestZone, st.largestZone);
      into.zoneParticles += st.zoneParticles;
      into.rigidSteps += st.rigidZones > 0;
      into.jammedParticles += st.jammedParticles;
      into.heldParticles += st.heldParticles;
      into.zoneUpdates += static_cast<double>(st.zoneUpdates);
      blockZone += st.zoneParticles;
      blockFailsafe += st.failsafe;
      if ((k + 1) % kBlockSteps == 0 || k + 1 == steps) {
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        into.total += seconds;
        const long first = k / kBlockSteps * kBlockSteps + 1, inBlock = k + 1 - first + 1;
        if (into.blockCount < kMaxBlocks) {
          Block& b = into.blocks[into.blockCount++];
          b.first = first;
          b.last = k + 1;
          b.msPerStep = 1000 * seconds / static_cast<double>(inBlock);
          b.failsafeMs = 1000 * blockFailsafe / static_cast<double>(inBlock);
          b.inZones = static_cast<double>(blockZone) / (static_cast<double>(inBlock) * s.scene.numParticles());
          b.atRest = atRestShare(s.scene, state.v);
          // Awake: not asleep after the block's last step (the default mode's sleepers; Box2D's
          // column of the same name).
          b.awake = 1.0 - static_cast<double>(st.asleep) / s.scene.numParticles();
          b.touching = touchingPairs(s.scene, state.x);
        }
        blockZone = 0;
        blockFailsafe = 0;
        into.steps = k + 1;
        if (o.timeLimit > 0 && into.total > o.timeLimit && k + 1 < steps) {
          into.stopped = true;
          break;
        }
        start = std::chrono::steady_clock::now();
      }
    }
    into.steps = into.steps ? into.steps : steps;
    return true;
  };
  Figures trial;
  if (!run(std::min<long>(5, f.steps), trial)) return f;  // warm-up
  const int repeats = o.repeats > 0 ? o.repeats : (n >= 100000 ? 1 : 3);
  Figures best;
  long growth = 0;
  for (int r = 0; r < repeats; ++r) {
    if (!run(f.steps, trial)) return f;
    if (r == 0) growth = residentBytes() - early;
    // Per step: runs stopped at --time-limit may differ in length.
    if (r == 0 || trial.total / static_cast<double>(trial.steps) < best.total / static_cast<double>(best.steps))
      best = trial;
  }
  best.particles = f.particles;
  best.edges = f.edges;
  best.restSpeed = f.restSpeed;
  best.bytesPerParticle = static_cast<double>(peakResidentBytes() - before) / f.particles;
  best.growthBytes = static_cast<double>(growth);
  best.ok = true;
  return best;
}

/// Runs one scene and size in a child process; its figures come back through a pipe.
Figures inChild(const Options& o, const std::string& kind, int n) {
  int fds[2];
  Figures f;
  if (pipe(fds) != 0) return runScene(o, kind, n);
  std::fflush(stdout);
  const pid_t child = fork();
  if (child == 0) {
    close(fds[0]);
    const Figures mine = runScene(o, kind, n);
    const ssize_t written = write(fds[1], &mine, sizeof mine);
    _exit(written == static_cast<ssize_t>(sizeof mine) ? 0 : 1);
  }
  close(fds[1]);
  // The figures are larger than PIPE_BUF: a read may return part of them.
  ssize_t got = 0;
  while (got < static_cast<ssize_t>(sizeof f)) {
    const ssize_t part = read(fds[0], reinterpret_cast<char*>(&f) + got, sizeof f - got);
    if (part < 0 && errno == EINTR) continue;
    if (part <= 0) break;
    got += part;
  }
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (got != static_cast<ssize_t>(sizeof f)) {
    f = Figures{};
    std::snprintf(f.error, sizeof f.error, "the benchmark child failed");
  }
  return f;
}

}  // namespace
}  // namespace fosssim::bench

int main(int argc, char** argv) {
  using namespace fosssim::bench;
  Options o;
  CLI::App app("", "fosssim-bench");
  defineOptions(app, o);
  if (const int status = fosssim::cli::parseCommandLine(app, argc, argv); status >= 0) return status;
  std::ofstream csv;
  if (!o.csv.empty()) {
    csv.open(o.csv);
    if (!csv) {
      std::fprintf(stderr, "fosssim-bench: cannot write %s: %s\n", o.csv.c_str(), std::strerror(errno));
      return 1;
    }
    csv << "section,scene,n,particles,edges,steps,integrate_ms,broad_ms,narrow_ms,response_ms,failsafe_ms,other_ms,"
           "total_ms,candidates_per_step,queries_per_step,collisions_per_step,passes_per_step,failsafe_steps,"
           "rounds_per_failsafe,"
           "largest_zone,bytes_per_particle,rss_growth_bytes,threads,queries_per_second,hit_rate\n";
  }
  printMachine();
  if (o.stepTable) {
    std::printf("ms per step by phase (%s handling%s%s, %d thread%s%s%s%s%s, seed %u; fastest of the repeated runs)\n",
                o.collision.c_str(), o.integrator.empty() ? "" : ", ", o.integrator.c_str(), o.threads,
                o.threads == 1 ? "" : "s", o.allPairs ? ", all pairs" : "", o.compat ? ", --compat" : "",
                o.noSleep && !o.compat ? ", no sleeping" : "", o.noHold && !o.compat ? ", no holding" : "", o.seed);
    std::printf("%-16s %7s %6s %9s %7s %7s %7s %7s %8s %8s | %9s %9s %6s %5s %6s %6s %6s %5s %5s %5s %7s %6s %8s\n",
                "scene", "N", "steps", "integrate", "broad", "narrow", "respond", "failsafe", "other", "total",
                "cand/step", "coll/step", "passes", "fs%", "rounds", "zone", "inzn%", "rgd%", "jam%", "held%", "B/part",
                "grow/p", "gs/step");
    for (const std::string& kind : o.scenes) {
      for (int n : o.sizes) {
        const Figures f = inChild(o, kind, n);
        if (!f.ok) {
          std::printf("%-16s %7d  failed: %s\n", kind.c_str(), n, f.error);
          continue;
        }
        const double per = 1000.0 / static_cast<double>(f.steps);
        const double other = f.total - f.integrate - f.broad - f.narrow - f.response - f.failsafe;
        const double steps = static_cast<double>(f.steps);
        std::printf(
            "%-16s %7d %6ld %9.3f %7.3f %7.3f %7.3f %8.3f %8.3f %8.3f | %9.0f %9.1f %6.2f %5.1f %6.1f %6d %6.1f "
            "%5.1f %5.2f %5.1f %7.0f %6.1f %8.0f\n",
            kind.c_str(), f.particles, f.steps, f.integrate * per, f.broad * per, f.narrow * per, f.response * per,
            f.failsafe * per, other * per, f.total * per, f.candidates / steps, f.collisions / steps, f.passes / steps,
            100.0 * static_cast<double>(f.failsafeSteps) / steps,
            f.failsafeSteps ? f.rounds / static_cast<double>(f.failsafeSteps) : 0.0, f.largestZone,
            100.0 * f.zoneParticles / (steps * f.particles), 100.0 * static_cast<double>(f.rigidSteps) / steps,
            100.0 * f.jammedParticles / (steps * f.particles), 100.0 * f.heldParticles / (steps * f.particles),
            f.bytesPerParticle, f.growthBytes / f.particles, f.zoneUpdates / steps);
        if (f.stopped) std::printf("  (stopped at --time-limit %g s after %ld steps)\n", o.timeLimit, f.steps);
        std::fflush(stdout);
        if (f.steps >= 1000 || f.stopped || o.blocks || !o.blocksCsv.empty()) {
          const RunLabel label{o.compat ? "FOSSSim --compat" : "FOSSSim", kind, f.particles, o.seed, f.restSpeed};
          if (f.steps >= 1000 || f.stopped || o.blocks) printBlocks(label, f.blocks, f.blockCount);
          if (!o.blocksCsv.empty() && !appendBlocksCsv(o.blocksCsv, label, f.blocks, f.blockCount)) {
            std::fprintf(stderr, "fosssim-bench: cannot write %s: %s\n", o.blocksCsv.c_str(), std::strerror(errno));
            return 1;
          }
        }
        if (csv) {
          csv << "steps," << kind << "," << n << "," << f.particles << "," << f.edges << "," << f.steps << ","
              << f.integrate * per << "," << f.broad * per << "," << f.narrow * per << "," << f.response * per << ","
              << f.failsafe * per << "," << other * per << "," << f.total * per << "," << f.candidates / steps << ","
              << f.queries / steps << "," << f.collisions / steps << "," << f.passes / steps << "," << f.failsafeSteps
              << "," << (f.failsafeSteps ? f.rounds / static_cast<double>(f.failsafeSteps) : 0.0) << ","
              << f.largestZone << "," << f.bytesPerParticle << "," << f.growthBytes << "," << o.threads << ",,\n";
        }
      }
    }
  }
  if (o.queries) {
    std::printf("\nnarrow-phase queries per second, one core (CPU time, best of 5)\n");
    for (const QueryRate& q : measureQueryRates()) {
      std::printf("  %-62s %7.2f M/s  %6.1f ns  (hits %4.1f%%)\n", q.name.c_str(), q.perSecond / 1e6, 1e9 / q.perSecond,
                  100.0 * q.hitRate);
      if (csv)
        csv << "queries," << q.name << ",,,,,,,,,,,,,,,,,,,,,," << o.threads << "," << q.perSecond << "," << q.hitRate
            << "\n";
    }
  }
  if (o.alternatives) {
    std::printf("\nbroad-phase designs: ordered candidates of every row from one step's swept boxes (best of 3)\n");
    std::printf("%-8s %7s %-5s %9s %9s %9s %10s\n", "scene", "N", "method", "build ms", "query ms", "total ms",
                "pairs");
    std::vector<std::string> scenes;
    for (const std::string& s : o.scenes)
      if (s != "chains") scenes.push_back(s);  // particle boxes only: chains are mostly edges
    for (const BroadPhaseTiming& t : compareBroadPhases(scenes, o.sizes, 3)) {
      std::printf("%-8s %7d %-5s %9.3f %9.3f %9.3f %10ld\n", t.scene.c_str(), t.n, t.method.c_str(), t.buildMs,
                  t.queryMs, t.buildMs + t.queryMs, t.pairs);
      std::fflush(stdout);
      if (csv)
        csv << "broadphase," << t.scene << "," << t.n << ",,,,,,,,,,," << t.pairs << ",,,,,,,,,," << t.method << ","
            << t.buildMs << "," << t.queryMs << "\n";
    }
  }
  return 0;
}
