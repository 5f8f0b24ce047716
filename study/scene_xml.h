// Scenes for the study, written as XML text and loaded through the ordinary scene loader, so that
// every study run goes through exactly the path a user's scene file takes (parseScene, the
// collision table's defaults, the force order) and the text can be saved and replayed with FOSSSim.
#pragma once

#include "fosssim/core/types.h"
#include "fosssim/io/scene_file.h"

#include <sstream>
#include <string>

namespace fosssim::study {

/// A <collision> element. Empty fields are left out so that the loader applies its defaults.
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

/// Builds a scene file's text element by element. Numbers are written with 17 significant digits,
/// so the loaded scene holds exactly the doubles given here.
class SceneXml {
 public:
  SceneXml& duration(double seconds);
  SceneXml& integrator(const std::string& type, double dt);
  SceneXml& collision(const CollisionChoice& choice);
  /// Uses the method's integrator and collision choice with time step dt.
  SceneXml& method(const Method& m, double dt);
  /// Returns the new particle's index.
  int particle(const Vec2& x, const Vec2& v, double mass, bool fixed = false, double radius = 0.1);
  /// Returns the new edge's index.
  int edge(int i, int j, double radius = 0.015);
  SceneXml& halfplane(const Vec2& point, const Vec2& normal);
  SceneXml& spring(int edge, double k, double l0, double b = 0);
  SceneXml& gravity(const Vec2& g);
  SceneXml& gravitational(int i, int j, double G);

  std::string text() const;
  /// Parses text() with the scene loader; `name` stands for the file in messages.
  Status load(const std::string& name, SceneFile& out) const;

 private:
  void append(const std::ostringstream& element);
  std::string body_;  ///< the elements so far, one per line
  int particles_ = 0;
  int edges_ = 0;
};

/// A number as the study writes it into scene text: shortest round-trip form ("%.17g").
std::string number(double value);

}  // namespace fosssim::study
