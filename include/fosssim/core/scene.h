// What a scene *is*: everything about a simulation that does not change while it runs.
// What changes (positions, velocities, time) lives in State (state.h). A step reads a Scene and
// advances a State, so one Scene can drive many States (the grader, the study, the benchmarks).
#pragma once

#include "fosssim/core/force.h"
#include "fosssim/core/state.h"
#include "fosssim/core/status.h"
#include "fosssim/core/types.h"

#include <memory>
#include <string>
#include <vector>

namespace fosssim {

/// A capsule between two particles: the set of points within `radius` of the segment i-j.
struct Edge {
  int i = 0;              ///< first endpoint (particle index)
  int j = 0;              ///< second endpoint (particle index), j != i
  double radius = 0.015;  ///< capsule radius (the reference's default)
};

/// A half-plane obstacle. The free side is where (x - point) . normal > 0.
struct HalfPlane {
  Vec2 point = Vec2::Zero();   ///< a point on the boundary line
  Vec2 normal = Vec2::UnitY(); ///< points to the free side; kept unnormalised, as the reference does
                               ///< (it enters the logged polynomials), never zero
};

/// What the default mode does with contacts that impulses cannot settle within a step.
enum class Failsafe {
  Projection,  ///< inelastic projection per impact zone (Harmon et al. 2008); a zone still
               ///< jammed then stops its contacts' particles, a free one moves rigidly
  Rigid,       ///< rigid impact zones at once (the course's failsafe)
};

/// The collision handling methods, in the order of collisionTable() (collision_handler.h), which
/// maps each to its keyword of <collision type="..."> and to what it builds. A scene holds the
/// method, not its keyword: the keyword is looked up once, where it is read (loader, Python).
enum class CollisionType { None, Simple, ContinuousTime, Hybrid, Penalty };

/// How collisions are handled.
struct CollisionSettings {
  CollisionType type = CollisionType::None;
  double cor = 1.0;           ///< coefficient of restitution, 1 elastic .. 0 inelastic
  int maxIterations = 10;     ///< hybrid: impulse passes before the failsafe; <= 0 means none
                              ///< (default mode: impulse events per particle and step)
  Failsafe failsafe = Failsafe::Projection;  ///< default mode only; --compat is always rigid
  double penaltyK = 0.0;          ///< penalty / hybrid: the penalty force's stiffness and
  double penaltyThickness = 0.0;  ///< thickness, as the file gives them (finalizeScene builds
                                  ///< the force in Scene::forces from them; the writer writes them)
};

/// The static description of a particle system.
struct Scene {
  // --- particles: N of them -------------------------------------------------------------------
  VecX mass;                  ///< 2N: particle i's mass at rows 2i and 2i+1 (the diagonal of M)
  /// N: 1 if forces and collisions leave the particle (infinite mass). It keeps its velocity,
  /// which the default mode's time-ordered handling requires to be 0.
  std::vector<char> fixed;
  std::vector<double> radius; ///< N: disk radius, > 0

  // --- other geometry -------------------------------------------------------------------------
  std::vector<Edge> edges;           ///< capsules, in file order (springs refer to them by index)
  std::vector<HalfPlane> halfplanes; ///< in file order

  // --- dynamics -------------------------------------------------------------------------------
  /// Forces in the reference's summation order (springs, simple gravity, gravitational, constant,
  /// drag, vortex, then the collision penalty), which fixes the floating-point result.
  std::vector<std::unique_ptr<Force>> forces;
  std::string integrator = "explicit-euler";  ///< keyword of integratorTable()
  double dt = 0.01;                           ///< time step, > 0
  double duration = 0.0;                      ///< simulated time; the run has numSteps() steps
  CollisionSettings collision;

  int numParticles() const { return static_cast<int>(radius.size()); }
  bool isFixed(int i) const { return fixed[i] != 0; }
  double massOf(int i) const { return mass[2 * i]; }
  /// Steps in a full run: ceil(duration / dt), computed exactly as the reference does.
  long numSteps() const;

  Scene() = default;
  Scene(Scene&&) noexcept = default;
  Scene& operator=(Scene&&) noexcept = default;
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;
};

/// A particle's constant properties, for building scenes.
struct ParticleSpec {
  double mass = 1.0;
  bool fixed = false;
  double radius = 0.1;
};

/// Appends particles to a scene under construction (one resize for the whole batch).
void addParticles(Scene& scene, const std::vector<ParticleSpec>& particles);
/// Appends one particle (convenient for small hand-made scenes).
void addParticle(Scene& scene, double mass, bool fixed, double radius);

/// Completes a scene built from its settings, once, before it runs: adds the penalty force that
/// the collision type implies (penalty, hybrid: CollisionEntry::addsPenaltyForce) with the
/// settings' k and thickness, last in the summation order, unless the scene has one already.
/// The loader calls it; so should any code that builds a scene with such a collision type.
void finalizeScene(Scene& scene);

/// Whether a scene built in code holds together: per-particle arrays of one length N (mass 2N,
/// fixed and radius N), every edge's and pair force's particles in [0, N), and `state` (if
/// given) of 2N positions and velocities. The loader's scenes always do; a library caller's may
/// not, and a step over them would read out of bounds. Simulator::create and step check it.
Status checkSceneShape(const Scene& scene, const State* state = nullptr);

/// Sum of the gradients of all the scene's forces at (x, v): minus the total force (size 2N).
/// `context`: the caller's options and storage for forces that search pairs (force.h); the
/// overload without one uses a fresh default context.
void accumulateGradient(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE, ForceContext& context);
void accumulateGradient(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE);

/// Total potential energy of the scene's forces that have one (context as above).
double potentialEnergy(const Scene& scene, const VecX& x, const VecX& v, ForceContext& context);
double potentialEnergy(const Scene& scene, const VecX& x, const VecX& v);

/// Kinetic energy 1/2 v^T M v.
double kineticEnergy(const Scene& scene, const VecX& v);

}  // namespace fosssim
