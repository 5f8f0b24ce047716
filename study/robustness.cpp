#include "robustness.h"

#include "csv.h"
#include "experiments.h"

#include "fosssim/core/collision_handler.h"

#include <algorithm>
#include <cmath>

namespace fosssim::study {
namespace {

constexpr double kDiskRadius = 0.02, kEdgeRadius = 0.01, kReach = kDiskRadius + kEdgeRadius, kDiskMass = 1.0;

}  // namespace

const char* edgeOutcomeName(EdgeOutcome outcome) {
  switch (outcome) {
    case EdgeOutcome::Bounced: return "bounced";
    case EdgeOutcome::Tunnelled: return "tunnelled";
    case EdgeOutcome::Stuck: return "stuck";
    case EdgeOutcome::Unstable: return "unstable";
  }
  return "unstable";
}

SceneBuilder edgeThrowScene(const Method& method, double speed, double dt, double* startHeight) {
  const double h = kReach + std::max(0.1, 5.37 * speed * dt);
  if (startHeight) *startHeight = h;
  SceneBuilder x;
  x.duration(2 * h / speed).method(method, dt);
  const int a = x.particle(Vec2(-1, 0), Vec2(0, 0), 1.0, true, kEdgeRadius);
  const int b = x.particle(Vec2(1, 0), Vec2(0, 0), 1.0, true, kEdgeRadius);
  x.edge(a, b, kEdgeRadius);
  x.particle(Vec2(0, h), Vec2(0, -speed), kDiskMass, false, kDiskRadius);
  return x;
}

EdgeThrow throwAtEdge(const Method& method, double speed, double dt) {
  EdgeThrow out;
  SceneFile file;
  if (Status s = edgeThrowScene(method, speed, dt, &out.startHeight).build("thin-edge.xml", file); !s) {
    out.run.outcome = Outcome::Error;
    out.run.message = s.message();
    return out;
  }
  out.run = runScene(file, RunOptions{});
  if (!out.run.ok()) return out;
  const Vec2 x = at(out.run.final.x, 2), v = at(out.run.final.v, 2);
  // Distance from the disk's centre to the edge's segment (the edge never moves).
  const double distance = (x - Vec2(std::clamp(x.x(), -1.0, 1.0), 0)).norm();
  if (distance < kReach)
    out.outcome = EdgeOutcome::Stuck;
  else if (x.y() < 0)
    out.outcome = EdgeOutcome::Tunnelled;
  else
    out.outcome = v.y() > 0 ? EdgeOutcome::Bounced : EdgeOutcome::Stuck;
  return out;
}

Status runRobustness(const StudyOptions& options) {
  CsvWriter csv;
  if (Status s = csv.open(options.outDir + "/robustness.csv",
                          {"method", "collision", "k", "speed", "dt", "speed_dt", "outcome", "steps",
                           "exit_speed_ratio", "max_overlap", "max_overlap_rel", "overlap_steps", "collisions",
                           "run_outcome", "disk_radius", "edge_radius", "disk_mass", "penalty_k", "thickness",
                           "maxiters", "default_k", "cor", "message"});
      !s)
    return s;
  std::vector<double> speeds, dts;
  // Quarter decades: speeds 0.1 .. 1000 m/s, time steps 1e-4 .. 0.1 s (quick: two of each, with
  // few steps per run).
  const int speedStep = options.quick ? 8 : 1, dtStep = options.quick ? 8 : 1;
  for (int e = options.quick ? 0 : -4; e <= 12; e += speedStep) speeds.push_back(std::pow(10.0, e / 4.0));
  for (int e = options.quick ? -12 : -16; e <= -4; e += dtStep) dts.push_back(std::pow(10.0, e / 4.0));
  for (const Method& m : collisionMethods()) {
    if (options.log) *options.log << "robustness: " << m.label << std::flush;
    SceneFile settings;  // the method's settings as the scene resolves them (the table's defaults)
    if (Status s = edgeThrowScene(m, 1.0, 1e-3).build("thin-edge.xml", settings); !s) return s;
    const CollisionSettings& c = settings.scene.collision;
    for (double speed : speeds) {
      for (double dt : dts) {
        const EdgeThrow t = throwAtEdge(m, speed, dt);
        const RunResult& r = t.run;
        const EdgeOutcome outcome = r.ok() ? t.outcome : EdgeOutcome::Unstable;
        const double exitRatio = r.ok() ? at(r.final.v, 2).norm() / speed : kNotApplicable;
        csv << m.label << m.collision.type << (m.collision.k >= 0 ? m.collision.k : kNotApplicable) << speed << dt
            << speed * dt << edgeOutcomeName(outcome) << r.steps << exitRatio << r.overlap.deepest
            << r.overlap.deepest / kReach << r.overlap.stepsWithOverlap << r.collisions << outcomeName(r.outcome)
            << kDiskRadius << kEdgeRadius << kDiskMass << c.penaltyK << c.penaltyThickness << c.maxIterations
            << collisionEntry(c.type).defaultK << c.cor << r.message;
        if (Status s = csv.endRow(); !s) return s;
      }
      if (options.log) *options.log << "." << std::flush;
    }
    if (options.log) *options.log << "\n";
  }
  return runShots(options);
}

}  // namespace fosssim::study
