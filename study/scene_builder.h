// Scenes for the study, built in code element by element as a scene file would give them: the
// builder makes the same SceneFile the loader makes of the equivalent XML (forces in the loader's
// summation order, the collision type's defaults, finalizeScene's penalty force), so every study
// run takes the path a user's scene takes. xml() writes the scene with the io layer's writer
// (fosssim/io/scene_writer.h), to save a study scene and replay it with FOSSSim; the study's
// tests check that the text loads back into the same scene.
#pragma once

#include "fosssim/core/types.h"
#include "fosssim/io/scene_file.h"

#include <string>
#include <vector>

namespace fosssim::study {

/// A <collision> element. Fields < 0 are left to the loader's defaults (the collision table's).
struct CollisionChoice {
  std::string type = "none";
  double cor = 1.0;
  int maxIterations = -1;   ///< hybrid only; < 0 leaves the default (10)
  double k = -1;            ///< penalty / hybrid stiffness; < 0 leaves the default
  double thickness = -1;    ///< penalty / hybrid thickness; < 0 leaves the default
};

/// One way of simulating: an integrator keyword plus a collision choice, with a short label for
/// tables and legends (e.g. "symplectic-euler" or "penalty k=1e4").
struct Method {
  std::string label;
  std::string integrator;
  CollisionChoice collision;
};

/// Collects a scene's elements; build() makes the scene file. Copyable (problems return one per
/// method and dt), and nothing is built until asked for.
class SceneBuilder {
 public:
  SceneBuilder& duration(double seconds);
  SceneBuilder& integrator(const std::string& type, double dt);
  SceneBuilder& collision(const CollisionChoice& choice);
  /// Uses the method's integrator and collision choice with time step dt.
  SceneBuilder& method(const Method& m, double dt);
  /// Returns the new particle's index.
  int particle(const Vec2& x, const Vec2& v, double mass, bool fixed = false, double radius = 0.1);
  /// Returns the new edge's index.
  int edge(int i, int j, double radius = 0.015);
  SceneBuilder& halfplane(const Vec2& point, const Vec2& normal);
  SceneBuilder& spring(int edge, double k, double l0, double b = 0);
  SceneBuilder& gravity(const Vec2& g);
  SceneBuilder& gravitational(int i, int j, double G);

  /// The scene file (its path `name`, for messages). Fails on an unknown integrator or collision
  /// type, or an index out of range, naming it.
  Status build(const std::string& name, SceneFile& out) const;
  /// The scene file as XML text (sceneToXml).
  Status xml(std::string& out) const;

 private:
  struct Particle {
    Vec2 x, v;
    double mass, radius;
    bool fixed;
  };
  struct Spring {
    int edge;
    double k, l0, b;
  };
  struct Pair {
    int i, j;
    double G;
  };
  double duration_ = 0, dt_ = 0.01;
  std::string integrator_ = "explicit-euler";
  CollisionChoice collision_;
  std::vector<Particle> particles_;
  std::vector<Edge> edges_;
  std::vector<HalfPlane> halfplanes_;
  std::vector<Spring> springs_;
  std::vector<Vec2> gravity_;
  std::vector<Pair> gravitational_;
};

}  // namespace fosssim::study
