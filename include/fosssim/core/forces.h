// The concrete forces of the scene format. Each documents its formula; the derivations of the
// Jacobians are in the .cpp files, and tests/core/forces_test.cpp checks every one of them
// against finite differences.
#pragma once

#include "fosssim/core/force.h"
#include "fosssim/core/scene.h"

namespace fosssim {

/// A force between two particles, i and j: their motions are tied, so they sleep only together
/// (Force::couples).
class PairForce : public Force {
 public:
  bool couples(std::vector<std::pair<int, int>>& pairs) const override {
    pairs.emplace_back(i_, j_);
    return true;
  }
  int i() const { return i_; }
  int j() const { return j_; }

 protected:
  PairForce(int i, int j) : i_(i), j_(j) {}
  int i_, j_;  ///< the two particles' indices
};

/// <springforce edge k l0 b>: E = k/2 (l - l0)^2 with l = |x_j - x_i|, plus the damping force
/// -b ((v_j - v_i) . n) n on j (and its opposite on i), n = (x_j - x_i)/l.
class SpringForce final : public PairForce {
 public:
  SpringForce(int i, int j, double k, double l0, double b) : PairForce(i, j), k_(k), l0_(l0), b_(b) {}
  const char* keyword() const override { return "springforce"; }
  double energy(const Scene&, const VecX& x, const VecX& v) const override;
  void addGradient(const Scene&, const VecX& x, const VecX& v, VecX& gradE) const override;
  void addJacobianX(const Scene&, const VecX& x, const VecX& v, Triplets& out) const override;
  void addJacobianV(const Scene&, const VecX& x, const VecX& v, Triplets& out) const override;
  bool hasPotential() const override { return b_ == 0.0; }
  bool mayAddEnergy() const override { return b_ < 0.0; }  ///< damping with b >= 0 only removes energy
  double stiffness() const override { return k_; }
  // The parameters, for writers and bindings.
  double restLength() const { return l0_; }
  double damping() const { return b_; }

 private:
  double k_, l0_, b_;  ///< stiffness k, rest length l0 and damping coefficient b of the formula above
};

/// <simplegravity fx fy>: the force m g on every particle; E = -sum m_i g . x_i.
class SimpleGravityForce final : public Force {
 public:
  explicit SimpleGravityForce(const Vec2& g) : g_(g) {}
  const char* keyword() const override { return "simplegravity"; }
  double energy(const Scene&, const VecX& x, const VecX& v) const override;
  void addGradient(const Scene&, const VecX& x, const VecX& v, VecX& gradE) const override;
  bool hasPotential() const override { return true; }
  bool actsAlone() const override { return true; }
  const Vec2& acceleration() const { return g_; }

 private:
  Vec2 g_;  ///< the acceleration g of every particle
};

/// <constantforce fx fy>: the same force f on every particle; E = -sum f . x_i.
class ConstantForce final : public Force {
 public:
  explicit ConstantForce(const Vec2& f) : f_(f) {}
  const char* keyword() const override { return "constantforce"; }
  double energy(const Scene&, const VecX& x, const VecX& v) const override;
  void addGradient(const Scene&, const VecX& x, const VecX& v, VecX& gradE) const override;
  bool hasPotential() const override { return true; }
  bool actsAlone() const override { return true; }
  const Vec2& force() const { return f_; }

 private:
  Vec2 f_;  ///< the force f on every particle
};

/// <gravitationalforce i j G>: E = -G m_i m_j / |x_j - x_i|.
class GravitationalForce final : public PairForce {
 public:
  GravitationalForce(int i, int j, double G) : PairForce(i, j), G_(G) {}
  const char* keyword() const override { return "gravitationalforce"; }
  double energy(const Scene&, const VecX& x, const VecX& v) const override;
  void addGradient(const Scene&, const VecX& x, const VecX& v, VecX& gradE) const override;
  void addJacobianX(const Scene&, const VecX& x, const VecX& v, Triplets& out) const override;
  bool hasPotential() const override { return true; }
  double G() const { return G_; }

 private:
  double G_;  ///< the gravitational constant G of the formula above
};

/// <dragdamping b>: the force -b v on every particle.
class DragDampingForce final : public Force {
 public:
  explicit DragDampingForce(double b) : b_(b) {}
  const char* keyword() const override { return "dragdamping"; }
  void addGradient(const Scene&, const VecX& x, const VecX& v, VecX& gradE) const override;
  void addJacobianV(const Scene&, const VecX& x, const VecX& v, Triplets& out) const override;
  bool mayAddEnergy() const override { return b_ < 0.0; }  ///< -b v with b >= 0 only removes energy
  bool actsAlone() const override { return true; }
  double damping() const { return b_; }

 private:
  double b_;  ///< the drag coefficient b (the force is -b v)
};

/// <vortexforce i j kbs kvc>: with r = x_j - x_i, rhat = r/|r|, perp(a, b) = (-b, a):
/// F_j = kvc/|r|^2 (kbs perp(rhat) - (v_j - v_i)), F_i = -F_j. No energy, no Jacobian (as in the
/// reference), so implicit integrators treat it explicitly.
class VortexForce final : public PairForce {
 public:
  VortexForce(int i, int j, double kbs, double kvc) : PairForce(i, j), kbs_(kbs), kvc_(kvc) {}
  const char* keyword() const override { return "vortexforce"; }
  void addGradient(const Scene&, const VecX& x, const VecX& v, VecX& gradE) const override;
  bool hasJacobians() const override { return false; }
  double kbs() const { return kbs_; }
  double kvc() const { return kvc_; }

 private:
  double kbs_, kvc_;  ///< the coefficients kbs and kvc of the formula above
};

/// The penalty force of <collision type="penalty"> and "hybrid": for every pair closer than
/// r_sum + thickness, E = k/2 (|n| - r_sum - thickness)^2 where n is the vector from the particle
/// to the other object's closest point (particle-particle, particle-edge with the edge endpoints
/// weighted 1-alpha and alpha, particle-half-plane). Gradient only, as in the reference.
/// The near pairs are searched with the context's options and storage (energyWith,
/// addGradientWith); energy() and addGradient() use a fresh default context (tests, tools).
class PenaltyForce final : public Force {
 public:
  PenaltyForce(double k, double thickness) : k_(k), thickness_(thickness) {}
  const char* keyword() const override { return "collision penalty"; }
  double energy(const Scene&, const VecX& x, const VecX& v) const override;
  void addGradient(const Scene&, const VecX& x, const VecX& v, VecX& gradE) const override;
  double energyWith(const Scene&, const VecX& x, const VecX& v, ForceContext& context) const override;
  void addGradientWith(const Scene&, const VecX& x, const VecX& v, VecX& gradE, ForceContext& context) const override;
  bool hasJacobians() const override { return false; }
  bool hasPotential() const override { return true; }
  bool actsAlone() const override { return true; }  ///< contact range only (see Force)
  double stiffness() const override { return k_; }
  double thickness() const { return thickness_; }

 private:
  double k_, thickness_;  ///< stiffness k, and the thickness added to the pair's r_sum (see above)
};

}  // namespace fosssim
