// Implicit Euler (Newton's method on the velocity change) and linearized implicit Euler (one
// Newton step), both on the system of implicit_system.h.
//
// Implicit Euler solves M dv = h F(x + h (v + dv), v + dv). Newton on dv, starting from dv = 0,
// linearises F around the current guess (x + dx, v + dv) with dx = h (v + dv):
//   (M - h dF/dv - h^2 dF/dx) delta = h F(x + dx, v + dv) - M dv,   dv += delta
// until |delta| < kNewtonTolerance (at least one iteration, as the reference does); in the
// default mode until |delta| <= kNewtonRelativeTolerance max(|v + dv|, kNewtonRestingFraction
// |x| / h), the scene's own scales.
// Linearized implicit Euler takes exactly one such step from the guess dv = 0, i.e. with forces
// and Jacobians at (x + h v, v); then v += dv and x += h v (with the new v).
#include "implicit_system.h"

#include "core/short_number.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace fosssim {
Status ImplicitSystem::assemble(const Scene& scene, const VecX& x, const VecX& v, double h,
                                const VecX& dvCurrent, ForceContext& forces) {
  const int n = scene.numParticles();
  const std::vector<char>* resting = forces.resting();
  const char* held = resting && static_cast<int>(resting->size()) == n ? resting->data() : nullptr;
  // The reference's dense solve where it reproduces the reference (nothing held, a small system);
  // otherwise the solved particles' system.
  dense_ = !held && x.size() <= kMaxDenseDofs;
  if (!dense_) {
    slot_.assign(n, -1);
    solved_.clear();
    for (int i = 0; i < n; ++i)
      if (!scene.isFixed(i) && !(held && held[i])) slot_[i] = static_cast<int>(solved_.size()), solved_.push_back(i);
    if (solved_.empty()) return Status::ok();  // nothing moves: no forces, no system
  }
  // Right-hand side h F - M dv.
  rhs_.setZero(x.size());
  accumulateGradient(scene, x, v, rhs_, forces);
  rhs_ = -h * rhs_ - scene.mass.cwiseProduct(dvCurrent);

  jacobianX_.clear();
  jacobianV_.clear();
  for (const auto& force : scene.forces) {
    force->addJacobianX(scene, x, v, jacobianX_);
    force->addJacobianV(scene, x, v, jacobianV_);
  }
  return dense_ ? assembleDense(scene, h) : assembleSparse(scene, h);
}

// Fixed particles' velocity changes are zero: rows and columns zero but for the diagonal, zero
// right-hand side. The reference puts 1 on that diagonal; the default mode puts the particle's
// mass there, which is the same system in exact arithmetic but keeps the matrix in the scene's
// units: full pivoting orders its pivots by size, and 1 among masses of 10^9 (or 10^-9) changed
// that order with the units, and with it the solve's rounding (Units tests, tests/core/units_test.cpp).
Status ImplicitSystem::assembleDense(const Scene& scene, double h) {
  const Eigen::Index n = rhs_.size();
  for (int i = 0; i < scene.numParticles(); ++i)
    if (scene.isFixed(i)) at(rhs_, i).setZero();
  denseMatrix_.setZero(n, n);
  denseDamping_.setZero(n, n);
  for (const auto& t : jacobianX_) denseMatrix_(t.row(), t.col()) += t.value();
  for (const auto& t : jacobianV_) denseDamping_(t.row(), t.col()) += t.value();
  denseMatrix_ *= h * h;
  denseMatrix_ += h * denseDamping_;
  denseMatrix_.diagonal() += scene.mass;
  for (int i = 0; i < scene.numParticles(); ++i) {
    if (!scene.isFixed(i)) continue;
    denseMatrix_.middleRows(2 * i, 2).setZero();
    denseMatrix_.middleCols(2 * i, 2).setZero();
    denseMatrix_.block<2, 2>(2 * i, 2 * i) = fixedDiagonal(scene, i) * Mat2::Identity();
  }
  denseLu_.compute(denseMatrix_);
  denseScale_.resize(0);
  if (denseLu_.isInvertible()) return Status::ok();
  // Full-pivoting LU calls a matrix singular when a pivot falls below n eps times its largest,
  // a test that depends on how the rows are scaled: with masses 10^12 apart (a pile of masses
  // e^-14 .. e^14 under springs) it called a system singular whose scaled form below has
  // singular values 0.007 .. 2. Scaled by M^-1/2 on both sides the system is unit-free (the
  // identity plus h^2 K / m and h D / m terms), and its test means what it says. Only where the
  // unscaled test fails (which stopped the run before), so every system that passes it is still
  // solved as the reference solves it, bit for bit.
  denseScale_.resize(n);
  for (int i = 0; i < scene.numParticles(); ++i)
    at(denseScale_, i).setConstant(1.0 / std::sqrt(scene.isFixed(i) ? fixedDiagonal(scene, i) : scene.massOf(i)));
  denseScaledLu_.compute(denseScale_.asDiagonal() * denseMatrix_ * denseScale_.asDiagonal());
  if (!denseScaledLu_.isInvertible())
    return Status::error("the implicit system (M - h dF/dv - h^2 dF/dx) is singular");
  return Status::ok();
}

// The solved particles' rows and columns, renumbered in their order; the entries that tie one
// to a fixed or held particle multiply that particle's zero velocity change and are left out.
// With every particle solved this is the full matrix, entry for entry.
Status ImplicitSystem::assembleSparse(const Scene& scene, double h) {
  const Eigen::Index n = 2 * static_cast<Eigen::Index>(solved_.size());
  auto solvedDof = [&](Eigen::Index r) -> Eigen::Index {
    const int s = slot_[static_cast<size_t>(r / 2)];
    return s < 0 ? -1 : 2 * s + r % 2;
  };
  entries_.clear();
  entries_.reserve(jacobianX_.size() + jacobianV_.size() + n);
  auto add = [&](const Triplets& jacobian, double scale) {
    for (const auto& t : jacobian) {
      const Eigen::Index r = solvedDof(t.row()), c = solvedDof(t.col());
      if (r >= 0 && c >= 0) entries_.emplace_back(r, c, scale * t.value());
    }
  };
  add(jacobianX_, h * h);
  add(jacobianV_, h);
  solvedRhs_.resize(n);
  for (size_t s = 0; s < solved_.size(); ++s) {
    const int i = solved_[s];
    for (int d = 0; d < 2; ++d) {
      const Eigen::Index r = 2 * static_cast<Eigen::Index>(s) + d;
      entries_.emplace_back(r, r, scene.mass[2 * i + d]);
      solvedRhs_[r] = rhs_[2 * i + d];
    }
  }
  matrix_.resize(n, n);
  matrix_.setFromTriplets(entries_.begin(), entries_.end());
  lu_.compute(matrix_);
  if (lu_.info() != Eigen::Success)
    return Status::error("the implicit system (M - h dF/dv - h^2 dF/dx) is singular");
  return Status::ok();
}

double ImplicitSystem::fixedDiagonal(const Scene& scene, int i) const { return course_ ? 1.0 : scene.massOf(i); }

const VecX& ImplicitSystem::solve() {
  if (dense_) {
    // Scaled: A = S^-1 (S A S) S^-1, so A^-1 r = S (S A S)^-1 S r.
    if (denseScale_.size() > 0)
      delta_ = denseScale_.cwiseProduct(denseScaledLu_.solve(denseScale_.cwiseProduct(rhs_)).eval());
    else
      delta_ = denseLu_.solve(rhs_);
    return delta_;
  }
  delta_.setZero(2 * static_cast<Eigen::Index>(slot_.size()));
  if (solved_.empty()) return delta_;
  const VecX solved = lu_.solve(solvedRhs_);
  for (size_t s = 0; s < solved_.size(); ++s) at(delta_, solved_[s]) = at(solved, static_cast<int>(s));
  return delta_;
}

double ImplicitSystem::residualEnergy(const Scene& scene) const {
  double energy = 0;
  for (int i = 0; i < scene.numParticles(); ++i) {
    if (dense_ ? scene.isFixed(i) : slot_[i] < 0) continue;
    energy += at(rhs_, i).squaredNorm() / scene.massOf(i);
  }
  return 0.5 * energy;
}

Status ImplicitEuler::step(const Scene& scene, State& state, double dt, ForceContext& forces) {
  iterations_ = 0;
  if (state.x.size() == 0) return Status::ok();  // nothing to solve (and no empty factorisation)
  dv_.setZero(state.v.size());
  dx_ = dt * state.v;
  const double restingScale = kNewtonRestingFraction * state.x.norm() / dt;
  bool assembled = false;  // at dv_ already, by the last iteration's line search
  for (int iteration = 1;; ++iteration) {
    iterations_ = iteration;
    if (!assembled)
      if (Status s = assembleAtGuess(scene, state, dt, forces); !s) return s;
    assembled = false;
    delta_ = system_.solve();
    const double size = delta_.norm();
    if (!std::isfinite(size))
      return Status::error("implicit Euler: the Newton update became non-finite");
    next_ = dv_ + delta_;  // the full Newton step
    const double tolerance =
        course_ ? kNewtonTolerance : kNewtonRelativeTolerance * std::max((state.v + next_).norm(), restingScale);
    const bool converged = course_ ? size < tolerance : size <= tolerance;
    if (course_ || converged) {  // the reference's full steps, and the last one
      dv_ = next_;
      dx_ = dt * (state.v + dv_);
    } else {
      if (Status s = lineSearch(scene, state, dt, forces); !s) return s;
      assembled = true;
    }
    if (converged) break;
    if (iteration == kMaxNewtonIterations)
      return Status::error("implicit Euler: Newton's method did not converge in " +
                           std::to_string(kMaxNewtonIterations) + " iterations (last update " + shortNumber(size) +
                           ", tolerance " + shortNumber(tolerance) + "); a smaller dt helps");
  }
  state.x += dx_;
  state.v += dv_;
  return Status::ok();
}

// Newton's full step can overshoot where the forces bend sharply (springs compressed far below
// their length, masses 10^12 apart: the updates cycled at a size of 5 for 100 iterations, "did
// not converge"), so the default mode backtracks on the residual's energy (residualEnergy), on
// which the Newton direction descends at the rate -2 E: the step alpha delta is taken when E falls
// by at least kArmijo 2 alpha E, else alpha is halved. The full step is tried first and, taken,
// costs nothing more (its assembly is the next iteration's); where every full step is taken the
// iterates are those of plain Newton, bit for bit. After kMaxHalvings the shortest step is taken
// anyway: the iteration limit then reports the failure as before.
Status ImplicitEuler::lineSearch(const Scene& scene, const State& state, double dt, ForceContext& forces) {
  constexpr double kArmijo = 1e-4;
  constexpr int kMaxHalvings = 30;
  const double energy = system_.residualEnergy(scene);
  from_ = dv_;
  double alpha = 1.0;
  for (int halving = 0;; ++halving) {
    dv_ = from_ + alpha * delta_;  // alpha = 1: bit for bit the full step, next_
    dx_ = dt * (state.v + dv_);
    if (Status s = assembleAtGuess(scene, state, dt, forces); !s) return s;
    const double trial = system_.residualEnergy(scene);
    if (trial <= (1.0 - 2.0 * kArmijo * alpha) * energy || halving == kMaxHalvings) return Status::ok();
    alpha *= 0.5;
  }
}

Status ImplicitEuler::assembleAtGuess(const Scene& scene, const State& state, double dt, ForceContext& forces) {
  xTrial_ = state.x + dx_;
  vTrial_ = state.v + dv_;
  return system_.assemble(scene, xTrial_, vTrial_, dt, dv_, forces);
}

Status LinearizedImplicitEuler::step(const Scene& scene, State& state, double dt, ForceContext& forces) {
  solved_ = state.x.size() > 0;
  if (!solved_) return Status::ok();
  xTrial_ = state.x + dt * state.v;
  zero_.setZero(state.v.size());
  if (Status s = system_.assemble(scene, xTrial_, state.v, dt, zero_, forces); !s) return s;
  state.v += system_.solve();
  state.x += dt * state.v;
  return Status::ok();
}

}  // namespace fosssim
