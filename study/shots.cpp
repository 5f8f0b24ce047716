#include "shots.h"

#include "csv.h"
#include "experiments.h"
#include "problems.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

namespace fosssim::study {
namespace {

constexpr double kDisk = 0.02, kEdge = 0.01, kReach = kDisk + kEdge;
constexpr double kDeg = M_PI / 180;
// Relative, on energy ratios: a gain or loss beyond COR's bounds by less than 0.1 % is not counted
// (the hybrid's penalty layer, integrated by symplectic Euler, moves the energy by about that).
constexpr double kTolerance = 1e-3;
constexpr double kFrozen = 1e-6;  // kinetic energy at the end over its start
constexpr int kSlotCrossings = 6;

using Segment = std::pair<Vec2, Vec2>;

std::vector<Segment> segments(const Shot& s) {
  switch (s.target) {
    case ShotTarget::EdgeFace: return {{Vec2(-1, 0), Vec2(1, 0)}};
    case ShotTarget::EdgeEnd: return {{Vec2(-1, 0), Vec2(0, 0)}};
    case ShotTarget::Joint:
      return {{Vec2(-1, 0), Vec2(0, 0)}, {Vec2(0, 0), Vec2(std::cos(s.jointAngle), std::sin(s.jointAngle))}};
    case ShotTarget::Slot: {
      const double y = s.offset + kReach;  // the walls' lines: the centre is free for |y| < offset
      return {{Vec2(-20, -y), Vec2(20, -y)}, {Vec2(-20, y), Vec2(20, y)}};
    }
  }
  return {};
}

double segmentDistance(const Segment& seg, const Vec2& p) {
  const Vec2 d = seg.second - seg.first;
  const double t = std::clamp((p - seg.first).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (p - seg.first - t * d).norm();
}

Vec2 direction(double angle) { return Vec2(std::cos(angle), std::sin(angle)); }

/// Flight before the aim point: beyond the hybrid's penalty layer (0.1) and three steps.
double approach(const Shot& s) { return 0.3 + 3 * s.speed * s.dt; }

Vec2 startOf(const Shot& s) {
  const Vec2 d = direction(s.angle);
  switch (s.target) {
    case ShotTarget::EdgeFace: return Vec2(s.offset, kReach) - approach(s) * d;
    case ShotTarget::EdgeEnd:
    case ShotTarget::Joint: {
      // The path passes the end (the joint) at `offset` from its centre, across the direction.
      const Vec2 across(-d.y(), d.x());
      return s.offset * across - approach(s) * d;
    }
    case ShotTarget::Slot: return Vec2(0, 0);
  }
  return Vec2(0, 0);
}

/// Whether a drawn shot is a fair one: it starts clear of the edges and beyond the hybrid's layer,
/// and (joint) inside the wedge the two edges make.
bool fair(const Shot& s) {
  if (s.target == ShotTarget::Slot) return true;
  const Vec2 start = startOf(s);
  if (shotClearance(s, start) < 0.15) return false;
  if (s.target == ShotTarget::EdgeFace) return start.y() > 0;
  if (s.target == ShotTarget::Joint) {
    const Vec2 rise = direction(s.jointAngle);
    return start.y() > 0 && cross(rise, start) > 0;
  }
  return true;
}

/// Whether the centre moved across an edge's segment between a and b.
bool crosses(const Segment& seg, const Vec2& a, const Vec2& b) {
  const Vec2 d = seg.second - seg.first;
  const double sa = cross(d, a - seg.first), sb = cross(d, b - seg.first);
  if ((sa > 0) == (sb > 0) || sa == sb) return false;
  const Vec2 p = a + (b - a) * (sa / (sa - sb));
  const double t = (p - seg.first).dot(d) / d.squaredNorm();
  return t >= 0 && t <= 1;
}

}  // namespace

const char* shotTargetName(ShotTarget target) {
  switch (target) {
    case ShotTarget::EdgeFace: return "edge face";
    case ShotTarget::EdgeEnd: return "edge end";
    case ShotTarget::Joint: return "joint";
    case ShotTarget::Slot: return "slot";
  }
  return "";
}

const char* shotOutcomeName(ShotOutcome outcome) {
  switch (outcome) {
    case ShotOutcome::Bounced: return "bounced";
    case ShotOutcome::Gained: return "gained energy";
    case ShotOutcome::Lost: return "lost energy";
    case ShotOutcome::Tunnelled: return "tunnelled";
    case ShotOutcome::Overlapped: return "overlapped";
    case ShotOutcome::Froze: return "froze";
    case ShotOutcome::Unstable: return "unstable";
  }
  return "";
}

Shot randomShot(ShotTarget target, int i) {
  // One generator per target and shot: a shot does not depend on how many were drawn before it.
  std::mt19937_64 rng(0x5eed0000u + 1000u * static_cast<unsigned>(target) + static_cast<unsigned>(i));
  // Called once a statement (or in a ?: branch): two calls in one expression, as in
  // uniform(...) * uniform(...), come in an order the compiler picks (gcc right to left, clang left
  // to right), and a shot must be the same under both.
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  for (;;) {
    Shot s;
    s.target = target;
    s.speed = std::pow(10.0, uniform(std::log10(0.3), std::log10(30.0)));
    s.dt = std::pow(10.0, uniform(-3, -2));
    s.cor = uniform(0, 1) < 0.5 ? 1.0 : uniform(0.5, 1.0);
    switch (target) {
      case ShotTarget::EdgeFace:
        s.offset = uniform(-0.8, 0.8);
        s.angle = -M_PI / 2 + uniform(-60, 60) * kDeg;  // within 60 degrees of head-on
        break;
      case ShotTarget::EdgeEnd:
        s.offset = uniform(-0.95, 0.95) * kReach;
        s.angle = uniform(-170, -10) * kDeg;  // from above, head-on to grazing from either side
        break;
      case ShotTarget::Joint:
        s.jointAngle = uniform(0, 60) * kDeg;
        s.offset = uniform(-1, 1) * kReach;
        s.angle = uniform(-170, -10) * kDeg;
        break;
      case ShotTarget::Slot:
        s.offset = uniform(0.005, 0.05);
        s.angle = uniform(10, 80) * kDeg;
        s.angle *= uniform(0, 1) < 0.5 ? -1 : 1;
        break;
    }
    if (fair(s)) return s;
  }
}

double shotClearance(const Shot& shot, const Vec2& centre) {
  double d = INFINITY;
  for (const Segment& seg : segments(shot)) d = std::min(d, segmentDistance(seg, centre));
  return d - kReach;
}

SceneBuilder shotScene(const Shot& shot, const Method& method) {
  Method m = method;
  m.collision.cor = shot.cor;
  double duration = 0;
  if (shot.target == ShotTarget::Slot)
    duration = kSlotCrossings * 2 * shot.offset / (shot.speed * std::abs(std::sin(shot.angle)));
  else
    duration = 3.5 * approach(shot) / shot.speed;  // out again by at least COR x 2.5 x the approach
  SceneBuilder x;
  x.duration(duration).method(m, shot.dt);
  std::vector<Vec2> ends;  // fixed particles, shared where edges meet
  auto endpoint = [&](const Vec2& p) {
    for (size_t i = 0; i < ends.size(); ++i)
      if (ends[i] == p) return static_cast<int>(i);
    ends.push_back(p);
    return x.particle(p, Vec2::Zero(), 1.0, true, kEdge);
  };
  for (const Segment& seg : segments(shot)) {
    const int a = endpoint(seg.first), b = endpoint(seg.second);
    x.edge(a, b, kEdge);
  }
  x.particle(startOf(shot), shot.speed * direction(shot.angle), 1.0, false, kDisk);
  return x;
}

ShotResult fireShot(const Shot& shot, const Method& method, bool compat) {
  ShotResult out;
  SceneFile file;
  if (Status s = shotScene(shot, method).build("shot.xml", file); !s) {
    out.run.outcome = Outcome::Error;
    out.run.message = s.message();
    return out;
  }
  const int disk = file.scene.numParticles() - 1;
  const std::vector<Segment> segs = segments(shot);
  bool crossed = false;
  Vec2 last = at(file.initial.x, disk);
  RunOptions options;
  options.compat = compat;
  options.measureOverlap = false;
  out.run = runScene(file, options, [&](const Scene&, const State& s) {
    const Vec2 now = at(s.x, disk);
    for (const Segment& seg : segs) crossed = crossed || crosses(seg, last, now);
    last = now;
  });
  // COR's bounds on E_end / E_0: every contact keeps the tangential velocity and scales the normal
  // one by COR, so it keeps between COR^2 and all of the kinetic energy. One contact on a single
  // (convex) edge; at most two in the joint's wedge (its inner angle is 120 degrees or more); in
  // the slot the velocity along it never changes.
  const double e2 = shot.cor * shot.cor;
  switch (shot.target) {
    case ShotTarget::EdgeFace:
    case ShotTarget::EdgeEnd: out.lowBound = e2; break;
    case ShotTarget::Joint: out.lowBound = e2 * e2; break;
    case ShotTarget::Slot: out.lowBound = std::pow(std::cos(shot.angle), 2); break;
  }
  out.highBound = 1;
  const State& end = out.run.final;
  out.clearance = shotClearance(shot, at(end.x, disk));
  if (!out.run.ok()) {
    out.outcome = ShotOutcome::Unstable;
    return out;
  }
  const double e0 = mechanicalEnergy(file.scene, file.initial);
  out.energyRatio = mechanicalEnergy(file.scene, end) / e0;
  const double kinetic = kineticEnergy(file.scene, end.v) / kineticEnergy(file.scene, file.initial.v);
  // A single edge or the joint must turn the disk; in the slot an even number of elastic bounces
  // gives the start's velocity back, so only a crossing tells there.
  const bool untouched = shot.target != ShotTarget::Slot &&
                         (at(end.v, disk) - at(file.initial.v, disk)).norm() <= 1e-12 * shot.speed;
  if (crossed || untouched)
    out.outcome = ShotOutcome::Tunnelled;
  else if (out.clearance < -1e-9)
    out.outcome = ShotOutcome::Overlapped;
  else if (kinetic < kFrozen)
    out.outcome = ShotOutcome::Froze;
  else if (out.energyRatio > out.highBound * (1 + kTolerance))
    out.outcome = ShotOutcome::Gained;
  else if (out.energyRatio < out.lowBound * (1 - kTolerance))
    out.outcome = ShotOutcome::Lost;
  else
    out.outcome = ShotOutcome::Bounced;
  return out;
}

std::vector<Method> shotMethods() {
  std::vector<Method> out;
  for (const Method& m : collisionMethods())
    if (m.label != "penalty k=1e2" && m.label != "penalty k=1e6") out.push_back(m);
  return out;
}

Status runShots(const StudyOptions& options) {
  CsvWriter csv;
  if (Status s = csv.open(options.outDir + "/robustness_shots.csv",
                          {"target", "method", "collision", "mode", "shot", "speed", "dt", "speed_dt", "angle_deg",
                           "offset", "joint_angle_deg", "cor", "outcome", "energy_ratio", "low_bound", "high_bound",
                           "clearance_end", "steps", "run_outcome", "message", "disk_radius", "edge_radius",
                           "tolerance"});
      !s)
    return s;
  const int shots = options.quick ? 4 : 100;
  for (ShotTarget target : {ShotTarget::EdgeFace, ShotTarget::EdgeEnd, ShotTarget::Joint, ShotTarget::Slot}) {
    if (options.log) *options.log << "robustness shots: " << shotTargetName(target) << std::flush;
    std::vector<Shot> drawn;
    for (int i = 0; i < shots; ++i) drawn.push_back(randomShot(target, i));
    for (bool compat : {false, true}) {
      for (const Method& m : shotMethods()) {
        for (int i = 0; i < shots; ++i) {
          const Shot& s = drawn[i];
          const ShotResult r = fireShot(s, m, compat);
          csv << shotTargetName(target) << m.label << m.collision.type << (compat ? "compat" : "default")
              << static_cast<long>(i) << s.speed << s.dt << s.speed * s.dt << s.angle / kDeg << s.offset
              << s.jointAngle / kDeg << s.cor << shotOutcomeName(r.outcome) << r.energyRatio << r.lowBound
              << r.highBound << r.clearance << r.run.steps << outcomeName(r.run.outcome) << r.run.message << kDisk
              << kEdge << kTolerance;
          if (Status st = csv.endRow(); !st) return st;
        }
        if (options.log) *options.log << "." << std::flush;
      }
    }
    if (options.log) *options.log << "\n";
  }
  return Status::ok();
}

}  // namespace fosssim::study
