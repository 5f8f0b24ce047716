// Internal header of fosssim_math: the interval solver staged for CCD queries.
#pragma once

#include "fosssim/math/interval_solver.h"

namespace fosssim::math {

// firstPositiveTime, staged so that polynomials can be added as they are built and the
// query abandoned at the first one that is never positive. The rules are the solver's own
// (all positive just after 0 gives 0, under IntervalRule::Exact only; an empty positive set
// gives kNever; otherwise the intersection of the same PositiveSets), so both paths give
// identical answers.
class StagedSolve {
 public:
  explicit StagedSolve(IntervalRule rule = IntervalRule::Exact) : rule_(rule) {}
  // False when p is never positive in [0, 1]: the pair cannot collide this step.
  bool add(const Polynomial& p) {
    polys_[count_] = &p;
    known_[count_] = rule_ == IntervalRule::Reference || !positiveJustAfterZero(p);
    if (known_[count_]) {
      allPositiveAtZero_ = false;
      sets_[count_] = positiveSet(p, 1.0, rule_);
      if (sets_[count_].empty()) return false;
    }
    ++count_;
    return true;
  }
  double finish() {
    if (allPositiveAtZero_) return 0.0;
    for (int i = 0; i < count_; ++i)
      if (!known_[i]) sets_[i] = positiveSet(*polys_[i], 1.0, rule_);
    return firstCommonTime(sets_, count_, 1.0, rule_);
  }

 private:
  IntervalRule rule_;
  // Filled in order up to count_; not zeroed on purpose (hot path).
  const Polynomial* polys_[4];
  PositiveSet sets_[4];
  bool known_[4];
  int count_ = 0;
  bool allPositiveAtZero_ = true;
};

}  // namespace fosssim::math
