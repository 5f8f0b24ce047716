// Internal header of fosssim_math: the interval solver staged for CCD queries, and the one
// implementation of firstPositiveTime (interval_solver.h), which adds its polynomials here
// all at once.
#pragma once

#include "fosssim/math/contract.h"
#include "fosssim/math/interval_solver.h"

namespace fosssim::math {

/// The solve, staged so that polynomials can be added as they are built and the query
/// abandoned at the first one that is never positive. The rules (interval_solver.h): all
/// positive just after 0 gives 0, under IntervalRule::Exact only (no root is then computed at
/// all); an empty positive set gives kNever; otherwise the first common time of the sets.
class StagedSolve {
 public:
  explicit StagedSolve(IntervalRule rule = IntervalRule::Exact, double tMax = 1.0) : rule_(rule), tMax_(tMax) {}
  /// False when p is never positive in [0, tMax]: the pair cannot collide this step. `p` must
  /// outlive finish(). At most kMaxSolverPolynomials polynomials.
  bool add(const Polynomial& p) {
    FOSSSIM_ASSERT(count_ < kMaxSolverPolynomials);
    polys_[count_] = &p;
    known_[count_] = rule_ == IntervalRule::Reference || !positiveJustAfterZero(p);
    if (known_[count_]) {
      allPositiveAtZero_ = false;
      sets_[count_] = positiveSet(p, tMax_, rule_);
      if (sets_[count_].empty()) return false;
    }
    ++count_;
    return true;
  }
  /// The first time in [0, tMax] at which every added polynomial is positive, or kNever.
  double finish() {
    if (allPositiveAtZero_) return 0.0;
    for (int i = 0; i < count_; ++i)
      if (!known_[i]) sets_[i] = positiveSet(*polys_[i], tMax_, rule_);
    return firstCommonTime(sets_, count_, tMax_, rule_);
  }

 private:
  IntervalRule rule_;  ///< how roots become the answer (interval_solver.h)
  double tMax_;        ///< the interval searched is [0, tMax]
  // Filled in order up to count_; not zeroed on purpose (hot path).
  const Polynomial* polys_[kMaxSolverPolynomials];
  PositiveSet sets_[kMaxSolverPolynomials];  ///< per polynomial: where it is positive in [0, tMax], once computed
  /// Per polynomial: sets_ computed by add(); false: left to finish() (positive just after 0).
  bool known_[kMaxSolverPolynomials];
  int count_ = 0;  ///< polynomials added
  /// Every polynomial added so far is positive just after 0 under IntervalRule::Exact: finish() gives 0.
  bool allPositiveAtZero_ = true;
};

}  // namespace fosssim::math
