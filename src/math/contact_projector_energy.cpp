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
  const Push first = pushAgain([&](int k) { return restitution_[k]; }, false);
  if (first != Push::TakenBack) return first == Push::Kept;
  return pushAgain([&](int k) { return std::max(restitution_[k], loadedRestitution_[k]); }, true) == Push::Kept;
}

// One try of restitute's, with the coefficients e(k).
template <class Coefficient>
ContactProjector::Push ContactProjector::pushAgain(const Coefficient& e, bool shorten) {
  // The row's impulse since the guard's start: its multiplier's change, plus what setRow moved
  // from its multiplier into replaced_ meanwhile.
  const auto impulse = [&](int k) { return startReplaced_[k] + row_[k].lambda - startLambda_[k]; };
  restituted_.clear();
  double first = -1.0;  // the coefficient of the first row that acts
  bool uniform = true;  // every row with an impulse pushes with that one coefficient
  for (int k : touched_) {
    const double ek = e(k), pushed = impulse(k);
    if (pushed > 0.0) uniform = uniform && (first < 0.0 || ek == first), first = first < 0.0 ? ek : first;
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
  if (energyFraction() < 1.0 && !(shorten && uniform && shortenPushes())) {
    // taken back exactly: each slot's first saved velocity wins
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

// The pushes scaled by the largest s in [0, 1] that adds no energy, each pushed slot at u + s p
// (u its velocity before the pushes, p what they added). Over the bodies changed since the
// guard's start, KE(s) = KE_u + s B + s^2 A with A = sum m |p|^2 / 2 and B = sum m u . p (only
// pushed slots depend on s), and KE(s) <= KE_start for s up to the larger root of
// A s^2 + B s - D, D = KE_start - KE_u: s = 2 D / (B + sqrt(B^2 + 4 A D)), the form that does not
// cancel when B < 0. With an exact projection and one coefficient that root is at or above 1
// (no scaling); short of it (a solve that ended on its budget or within its tolerance) a bounce
// kept in part loses less than one taken back whole (two fast disks in a box at COR 1 lost a
// quarter of their energy at one instant so). Only for one coefficient on every row that acts
// (pushAgain): rows with different ones (a hit beside a resting contact) gain energy by the law's
// own terms, not by a solve's shortfall, and their pushes are taken back whole, as Moreau's law
// has no answer there. False when no s > 0 fits.
bool ContactProjector::shortenPushes() {
  // Each pushed slot once, with its velocity before the pushes (its first saved one: a stable
  // sort keeps the entries of one slot in the order they were saved).
  pushedFrom_ = restituted_;
  std::stable_sort(pushedFrom_.begin(), pushedFrom_.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  pushedFrom_.erase(std::unique(pushedFrom_.begin(), pushedFrom_.end(),
                                [](const auto& x, const auto& y) { return x.first == y.first; }),
                    pushedFrom_.end());
  double a = 0, b = 0, d = 0;
  for (int s : changed_) {
    if (inverseMass_[s] == 0.0) continue;
    d += 0.5 / inverseMass_[s] * (startVelocity_[s].squaredNorm() - velocity_[s].squaredNorm());
  }
  for (const auto& [s, u] : pushedFrom_) {  // velocity_ holds u + p: d above counted it, not u
    const double m = 1.0 / inverseMass_[s];
    const Vec2 p = velocity_[s] - u;
    d += 0.5 * m * (velocity_[s].squaredNorm() - u.squaredNorm());
    a += 0.5 * m * p.squaredNorm();
    b += m * u.dot(p);
  }
  const double root = b * b + 4.0 * a * d;
  if (!(a > 0.0) || !(d > 0.0) || !(root >= 0.0)) return false;
  const double scale = std::min(1.0, 2.0 * d / (b + std::sqrt(root)));
  if (!(scale > 0.0)) return false;
  for (const auto& [s, u] : pushedFrom_) velocity_[s] = u + scale * (velocity_[s] - u);
  return energyFraction() >= 1.0;  // otherwise (rounding at the root) the caller takes them back
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
