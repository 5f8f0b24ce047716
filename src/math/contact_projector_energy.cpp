// ContactProjector's energy guard (energyFraction, capEnergy, moveBack, rollBack) and the
// restitution that it checks (restitute, pushAgain).
#include <algorithm>

#include "fosssim/math/contact_projector.h"

namespace fosssim::math {

// The changed bodies' kinetic energy along the line from the guard's start (f = 0) to now
// (f = 1) is KE(0) + f B + f^2 C (see the header); C > 0 whenever anything moved. A gain
// B + C > 0 is taken back to f = -B / C, where the energy is KE(0) again, or to f = 0 when the
// changes only add (B >= 0). Multipliers on the same line stay non-negative (both ends are).
double ContactProjector::energyFraction() const {
  double b = 0, c = 0, start = 0;
  for (int s : changed_) {
    if (inverseMass_[s] == 0.0) continue;
    const double m = 1.0 / inverseMass_[s];
    const Vec2 d = velocity_[s] - startVelocity_[s];
    b += m * startVelocity_[s].dot(d);
    c += 0.5 * m * d.squaredNorm();
    start += 0.5 * m * startVelocity_[s].squaredNorm();
  }
  if (!(b + c > kEnergyRoundingFraction * (start + c))) return 1.0;
  return b < 0.0 ? -b / c : 0.0;
}

double ContactProjector::capEnergy() {
  const double f = energyFraction();
  if (f < 1.0) moveBack(f);
  return f;
}

bool ContactProjector::restitute() {
  // The hits alone first; then, if they would add energy, with the rows they loaded too.
  const Push first = pushAgain([&](int k) { return restitution_[k]; });
  if (first != Push::TakenBack) return first == Push::Kept;
  return pushAgain([&](int k) { return std::max(restitution_[k], loadedRestitution_[k]); }) == Push::Kept;
}

// One try of restitute's, with the coefficients e(k).
template <class Coefficient>
ContactProjector::Push ContactProjector::pushAgain(const Coefficient& e) {
  // The row's impulse since the guard's start: its multiplier's change, plus what setRow moved
  // from its multiplier into replaced_ meanwhile.
  const auto impulse = [&](int k) { return startReplaced_[k] + row_[k].lambda - startLambda_[k]; };
  restituted_.clear();
  for (int k : touched_) {
    const double ek = e(k), pushed = impulse(k);
    if (!(ek > 0.0) || !(pushed > 0.0)) continue;
    const ConstraintRow& r = row_[k].r;
    for (int m = 0; m < r.count; ++m) {
      const int s = r.body[m];
      if (inverseMass_[s] == 0.0) continue;
      markChanged(s);
      restituted_.emplace_back(s, velocity_[s]);
      velocity_[s] += (inverseMass_[s] * ek * pushed) * r.coef[m];
    }
  }
  if (restituted_.empty()) return Push::Nothing;
  if (energyFraction() < 1.0) {  // taken back exactly: each slot's first saved velocity wins
    for (auto it = restituted_.rbegin(); it != restituted_.rend(); ++it) velocity_[it->first] = it->second;
    return Push::TakenBack;
  }
  // A restituted row's multiplier is set aside as setRow sets a replaced one's (still applied,
  // counted in totalImpulse): a later solve that found the row opening would otherwise take the
  // multiplier back, and with it the bounce. Rows the pushes close (a disk pushed back into its
  // neighbours) are not queued here: their contacts come back as events, at their own times.
  for (int k : touched_) {
    if (!(e(k) > 0.0) || !(impulse(k) > 0.0)) continue;
    startReplaced_[k] += row_[k].lambda - startLambda_[k];
    startLambda_[k] = 0.0;
    replaced_[k] += row_[k].lambda;
    row_[k].lambda = 0.0;
  }
  return Push::Kept;
}

void ContactProjector::rollBack() { moveBack(0.0); }

void ContactProjector::moveBack(double f) {
  for (int s : changed_)
    if (inverseMass_[s] != 0.0) velocity_[s] = startVelocity_[s] + f * (velocity_[s] - startVelocity_[s]);
  for (int k : touched_) {
    row_[k].lambda = startLambda_[k] + f * (row_[k].lambda - startLambda_[k]);
    replaced_[k] -= (1.0 - f) * startReplaced_[k];
    queue(k);  // settled or not, it may close again
  }
}

}  // namespace fosssim::math
