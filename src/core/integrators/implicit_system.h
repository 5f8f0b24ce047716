// Internal header: the linear system shared by both implicit integrators,
//   (M + h dE/dv + h^2 d2E/dx2) delta = h F - M dv_current
// (that is M - h dF/dv - h^2 dF/dx on the left), assembled at a given (x, v) with fixed
// particles' rows and columns replaced by the identity (the default mode: their mass times the
// identity, setCourseForm) and a zero right-hand side.
//
// Small systems are solved densely, assembled and factored exactly as the course's reference does
// (sum the Hessians, scale by h^2, add h times the damping Jacobians, add M; full-pivoting LU, fixed
// particles' rows and columns the identity), so implicit scenes reproduce its trajectories bit for
// bit. Larger ones, where a dense O(n^3) solve would be unusable, use a sparse LU of the same
// system with the fixed particles' rows and columns left out (their velocity change is 0).
//
// Particles held at rest (ForceContext::resting: the default mode's sleepers, which the step puts
// back where they rest) are left out the same way, and then the system is always sparse: a pile
// asleep costs neither forces nor a factorisation, and a pile partly asleep the system of its
// awake particles only (the dense solve is there for the reference's rounding, which such a
// system does not have anyway, and a few hundred awake particles would pay its O(n^3)).
// Leaving a particle out is the same, in exact arithmetic, as its identity row (an entry tying a
// solved particle to it multiplies its zero velocity change). With sleepers held it is also what
// the awake particles get with the sleepers left free: no Jacobian ties a sleeper to an awake
// particle, since particles tied at a distance sleep and wake together (sleepers.h).

#pragma once

#include "fosssim/core/integrator.h"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

namespace fosssim {

using SparseMat = Eigen::SparseMatrix<double>;

class ImplicitSystem {
 public:
  /// Assembles and factors the system at (x, v) for step h, with right-hand side
  /// h F(x, v) - M dvCurrent, over the particles that are neither fixed nor held at rest
  /// (forces.resting(), see above). Returns an error if the matrix is singular.
  Status assemble(const Scene& scene, const VecX& x, const VecX& v, double h, const VecX& dvCurrent,
                  ForceContext& forces);
  /// Solves for delta (size 2N; 0 for fixed and held particles) with the last assembled system.
  const VecX& solve();
  /// The last assembly's residual r = M dvCurrent - h F as an energy, r^T M^-1 r / 2 over the
  /// solved particles: implicit Euler's merit function (0 at the step's answer; the Newton update
  /// descends on it). Unit-free in the sense that matters: in J whatever the masses' spread.
  double residualEnergy(const Scene& scene) const;

  /// The reference's dense system, fixed particles' rows the identity (--compat, the default), or
  /// the same system in the scene's units, their diagonal their mass (assembleDense).
  void setCourseForm(bool course) { course_ = course; }

  /// Systems with at most this many degrees of freedom (2 per particle) are solved densely.
  static constexpr Eigen::Index kMaxDenseDofs = 256;

 private:
  Status assembleDense(const Scene& scene, double h);
  /// What a fixed particle's rows of the dense system hold on their diagonal (setCourseForm).
  double fixedDiagonal(const Scene& scene, int i) const;
  /// The sparse system of the solved particles (slot_, solved_).
  Status assembleSparse(const Scene& scene, double h);

  /// The forces' -dF/dx and -dF/dv at (x, v), 2N x 2N, and the sparse system's entries.
  Triplets jacobianX_, jacobianV_, entries_;
  bool dense_ = true;  ///< the last system was dense (nothing held, at most kMaxDenseDofs)
  bool course_ = true;  ///< setCourseForm
  /// For the sparse system: per particle its index among the solved particles (-1: fixed or
  /// held), the solved particles in order, and their right-hand side.
  std::vector<int> slot_, solved_;
  VecX solvedRhs_;
  Eigen::MatrixXd denseMatrix_, denseDamping_;  ///< dense: the system matrix and the summed -dF/dv (2N x 2N)
  Eigen::FullPivLU<Eigen::MatrixXd> denseLu_;   ///< dense: the factorisation of denseMatrix_
  /// Dense, when denseLu_ calls the matrix singular only because its masses are far apart
  /// (assembleDense): the system scaled by M^-1/2 on both sides, its factorisation, and the
  /// scale (2N: 1/sqrt(m), 1 for fixed particles). Empty scale: denseLu_ solves.
  Eigen::FullPivLU<Eigen::MatrixXd> denseScaledLu_;
  VecX denseScale_;
  SparseMat matrix_;                            ///< sparse: the solved particles' system (2S x 2S, S solved particles)
  Eigen::SparseLU<SparseMat> lu_;               ///< sparse: the factorisation of matrix_
  VecX rhs_, delta_;                            ///< 2N: the right-hand side h F - M dvCurrent, and solve()'s delta
};

class ImplicitEuler final : public Integrator {
 public:
  using Integrator::step;
  Status step(const Scene& scene, State& state, double dt, ForceContext& forces) override;
  int newtonIterations() const override { return iterations_; }
  void setCourseForm(bool course) override {
    course_ = course;
    system_.setCourseForm(course);
  }

 private:
  /// Assembles the system at the current guess: x + dx_, v + dv_.
  Status assembleAtGuess(const Scene& scene, const State& state, double dt, ForceContext& forces);
  /// The default mode's step along delta_ from dv_ (see the .cpp); leaves the system assembled at
  /// the new dv_.
  Status lineSearch(const Scene& scene, const State& state, double dt, ForceContext& forces);

  ImplicitSystem system_;  ///< each Newton iteration's linear system
  /// 2N: the step's position and velocity changes so far, and the trial point x + dx, v + dv.
  VecX dx_, dv_, xTrial_, vTrial_;
  /// 2N: the Newton update, dv_ plus all of it, and dv_ where the line search started.
  VecX delta_, next_, from_;
  int iterations_ = 0;  ///< Newton iterations of the last step (newtonIterations())
  bool course_ = true;  ///< kNewtonTolerance (absolute) or kNewtonRelativeTolerance
};

class LinearizedImplicitEuler final : public Integrator {
 public:
  using Integrator::step;
  Status step(const Scene& scene, State& state, double dt, ForceContext& forces) override;
  int newtonIterations() const override { return solved_ ? 1 : 0; }
  void setCourseForm(bool course) override { system_.setCourseForm(course); }

 private:
  ImplicitSystem system_;  ///< the step's one linear system
  VecX xTrial_, zero_;   ///< 2N: x + h v, where the system is assembled, and a zero dvCurrent
  bool solved_ = false;  ///< the last step solved its system (not so for a scene without particles)
};

}  // namespace fosssim
