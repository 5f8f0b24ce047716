// What collision handling reports about a step: the impulses it applied and, when asked for, the
// polynomials of every continuous-time query in call order. Both go into trajectory records.
#pragma once

#include "fosssim/core/types.h"

#include <vector>

namespace fosssim {

enum class PairKind : int { ParticleParticle = 0, ParticleEdge = 1, ParticleHalfPlane = 2 };

/// "particle-particle", "particle-edge" or "particle-half-plane", for messages.
inline const char* pairKindName(PairKind kind) {
  switch (kind) {
    case PairKind::ParticleParticle: return "particle-particle";
    case PairKind::ParticleEdge: return "particle-edge";
    case PairKind::ParticleHalfPlane: return "particle-half-plane";
  }
  return "unknown pair kind";
}

/// A pair found colliding during a step: what detection finds and what --verify reports
/// (Violation). For particle-edge and particle-half-plane, j is the edge or half-plane index.
struct Collision {
  PairKind kind = PairKind::ParticleParticle;  ///< what j indexes: a particle, an edge or a half-plane
  int i = 0;              ///< the particle (the lower index for particle-particle)
  int j = 0;              ///< the other particle, the edge or the half-plane
  double tau = 0;         ///< first contact as a fraction of the step, in [0, 1]
  Vec2 n = Vec2::Zero();  ///< contact vector at tau, from particle i to the other object
  double alpha = 0;       ///< particle-edge: the closest point's parameter at tau, clamped to [0, 1]
};

/// One collision response, as trajectory records hold it (the reference's record: kind, i, j,
/// n, then the contact time: the tau of the Collision it answers, 0 for discrete detection).
struct Impulse {
  PairKind kind = PairKind::ParticleParticle;  ///< what j indexes: a particle, an edge or a half-plane
  int i = 0;                ///< the particle (the lower index for particle-particle)
  int j = 0;                ///< the other particle, edge or half-plane
  Vec2 n = Vec2::Zero();    ///< contact vector (unnormalised), from particle i to the other object
  double tau = 0.0;         ///< contact time as a fraction of the step (0 for discrete detection)
};

/// Polynomial coefficient lists (highest power first) stored back to back: no allocation per
/// polynomial once the buffers have grown, and nothing at all while disabled.
class PolynomialLog {
 public:
  bool enabled() const { return enabled_; }
  void setEnabled(bool on) { enabled_ = on; }
  void clear() {
    coefficients_.clear();
    ends_.clear();
  }
  void add(const double* coefficients, int count) {
    coefficients_.insert(coefficients_.end(), coefficients, coefficients + count);
    ends_.push_back(static_cast<int>(coefficients_.size()));
  }
  int size() const { return static_cast<int>(ends_.size()); }
  const double* coefficients(int k) const { return coefficients_.data() + begin(k); }
  int length(int k) const { return ends_[k] - begin(k); }

 private:
  int begin(int k) const { return k == 0 ? 0 : ends_[k - 1]; }
  bool enabled_ = false;  ///< whether detection logs its queries' polynomials here (setEnabled)
  /// Every polynomial's coefficients, highest power first, back to back in call order.
  std::vector<double> coefficients_;
  std::vector<int> ends_;  ///< one past the last coefficient of each polynomial
};

struct CollisionLog {
  /// The step's impulses in the order they were applied (the hybrid handler's stays empty).
  std::vector<Impulse> impulses;
  PolynomialLog polynomials;  ///< every continuous-time query's polynomials, in call order (only while enabled)
  void clear() {
    impulses.clear();
    polynomials.clear();
  }
};

/// What a trajectory record holds beyond positions and velocities, and how many records a step
/// writes. It depends only on the collision handler (the reference's file layout).
struct RecordLayout {
  bool impulses = false;     ///< simple, continuous-time, hybrid
  bool polynomials = false;  ///< continuous-time, hybrid
  bool midStep = false;      ///< continuous-time, hybrid: a record from inside collision handling
};

}  // namespace fosssim
