// Small scenes built in code for the core tests.
#pragma once

#include "fosssim/core/forces.h"
#include "fosssim/core/scene.h"
#include "fosssim/core/state.h"

namespace fosssim::testing {

/// A scene together with a state to run it from.
struct TestScene {
  Scene scene;
  State state;
};

/// Appends a particle to both the scene and the state.
inline int addBody(TestScene& s, double m, Vec2 x, Vec2 v, double radius = 0.1, bool fixed = false) {
  addParticle(s.scene, m, fixed, radius);
  return s.state.addParticle(x, v);
}

/// The ground most contact tests stand on: the floor y = 0 (a half-plane facing up) and gravity
/// of g pointing down.
inline void addFloorAndGravity(TestScene& s, double g = 9.81) {
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0, 0), Vec2(0, 1)});
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -g)));
}

inline TestScene projectile(const std::string& integrator, double dt, Vec2 v0, Vec2 g) {
  TestScene s;
  addBody(s, 2.0, Vec2(0, 0), v0);
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(g));
  s.scene.integrator = integrator;
  s.scene.dt = dt;
  return s;
}

/// Two particles joined by an undamped spring, stretched from rest length 1 to `length`.
inline TestScene spring(const std::string& integrator, double dt, double k, double length = 1.5) {
  TestScene s;
  addBody(s, 1.0, Vec2(0, 0), Vec2(0, 0));
  addBody(s, 1.0, Vec2(length, 0), Vec2(0, 0));
  s.scene.edges.push_back(Edge{0, 1, 0.01});
  s.scene.forces.push_back(std::make_unique<SpringForce>(0, 1, k, 1.0, 0.0));
  s.scene.integrator = integrator;
  s.scene.dt = dt;
  return s;
}

}  // namespace fosssim::testing
