// The scene as the Python module holds it: a SceneFile (physics, initial state, appearance) built
// from a file or in code. Building keeps the loader's invariants (one colour per body, forces in
// the format's summation order, the penalty force that the collision type makes), so that a scene
// built in code behaves as, and writes to, the same file.
#pragma once

#include "fosssim/io/scene_file.h"

#include <memory>
#include <optional>
#include <string>

namespace fosssim::py {

struct PyScene {
  SceneFile file;

  static std::shared_ptr<PyScene> load(const std::string& path);
  static std::shared_ptr<PyScene> fromXml(const std::string& text, const std::string& name);
  /// A deep copy (through the writer and the loader, which round-trip exactly). A scene without
  /// particles has none: SceneError, `what` naming the caller.
  std::shared_ptr<PyScene> copy(const char* what = "Scene.copy") const;
  std::string toXml() const;

  int addParticle(const Vec2& x, const Vec2& v, double mass, double radius, bool fixed);
  int addEdge(int i, int j, double radius);
  int addHalfplane(const Vec2& point, const Vec2& normal);
  /// Inserts `force` after the last force of the same or an earlier kind in the format's order.
  void addForce(std::unique_ptr<Force> force);
  void addGravity(const Vec2& g);
  void addConstantForce(const Vec2& f);
  void addSpring(int edge, double k, double l0, double b);
  void addGravitational(int i, int j, double G);
  void addVortex(int i, int j, double kbs, double kvc);
  /// The collision settings and, for penalty and hybrid, its penalty force (k and thickness
  /// not given: the type's defaults; given, >= 0 as the loader's).
  /// maxIterations: any integer Python gives (2**31 is "at most 10000", not a TypeError); below
  /// -1 it is -1, as the loader's.
  void setCollision(const std::string& type, double cor, long long maxIterations, const std::string& failsafe,
                    std::optional<double> k, std::optional<double> thickness);
  void setIntegrator(const std::string& type, double dt);
  void setDuration(double duration);
  /// The description or tag: text a scene file can hold (no control characters, UTF-8).
  static void setText(std::string& into, const std::string& text, const char* what);

  void checkParticle(int i, const char* what) const;
};

}  // namespace fosssim::py
