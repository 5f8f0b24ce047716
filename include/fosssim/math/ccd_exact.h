// Continuous collision detection for the DEFAULT (non-compat) mode: the same question as
// detectPP/PE/PH in ccd.h ("the first t in [0, 1] at which the pair overlaps and
// approaches", open-interval rules of firstPositiveTime), answered independently of the
// scene's units and with edges treated as full capsules. The functions of ccd.h stay as
// they are: they reproduce the reference simulator for --compat and the trajectory log.
//
// What differs from ccd.h, and why:
//  * Units. Only differences of positions enter (the pair is translated so that particle
//    1's start is the origin), and all lengths are multiplied by 2^-k, chosen so that the
//    largest relative position, displacement or radius lies in [1/2, 1). A power of two
//    scales without rounding, so a scene scaled by 2^j gives bit-identical answers, and any
//    other scale only the rounding of its own inputs. Half-plane normals are normalised.
//  * Negligible leading coefficients are judged relative to the polynomial's own largest
//    coefficient (kRelativeNegligibleCoefficient), not against the absolute 1e-12 of the
//    reference: with t in [0, 1] dimensionless, all coefficients of one polynomial share
//    units, so the ratio is scale-free.
//  * Capsules. An edge of radius re is the set of points within re of its segment. Besides
//    the interior (closest point strictly between the endpoints: the reference's four
//    conditions with the exact quintic), each end is a disk of radius re around the endpoint
//    (a particle-particle problem with radius sum rv + re), valid while the endpoint is the
//    closest point of the segment. The earliest of the three contacts wins.
//  * Small radii. PP, PH and the caps are solved in forms where nothing cancels against the
//    radius (closed form for disks, linear factors for half-planes), so a disk of radius
//    1e-9 crossing a unit distance in one step is caught. The capsule interior's distance
//    condition is R^2 |e|^2 - (w x e)^2 (Lagrange's identity), not the reference's expanded
//    |e|^2 |w|^2 - (w.e)^2, whose terms cancel and lost R^2 once R fell below about 1e-8 of the
//    edge's length: a thin disk could cross the middle of a long edge undetected.
//    Ratios beyond ~1e150 within one pair underflow after normalisation (R^2 subnormal).
//  * Overflow is reported. A non-finite input, or a relative quantity that overflows
//    before normalisation, gives CcdOutcome::Overflow (never a silent miss): the caller
//    names the pair and the step.
#pragma once

#include <cfloat>

#include "fosssim/math/ccd.h"

namespace fosssim::math {

/// A leading coefficient c of a polynomial sum_k c_k t^k (after normalisation) is dropped when
/// |c| <= kRelativeNegligibleCoefficient * max_k |c_k|. Why this is harmless: for t in [0, 1]
/// and n the highest power, |c t^n| <= |c| t^m for every m <= n, so the dropped term is at most
/// kRelativeNegligibleCoefficient * |c_max| t^m <= kRelativeNegligibleCoefficient * sum|c_k| t^k:
/// below the bound on the rounding error of evaluating the polynomial at that t
/// (kHornerErrorFactor * DBL_EPSILON * sum|c_k| t^k, polynomial.h). What it buys: a leading
/// coefficient that is only cancellation noise (a pair moving rigidly, a static edge) does not
/// raise the degree, and with it the number of spurious sign changes the root finder sees.
constexpr double kRelativeNegligibleCoefficient = 4.0 * DBL_EPSILON;

enum class CcdOutcome { Miss, Hit, Overflow };

struct ExactContact {
  double tau = kNever;  // first contact time in [0, 1], as a fraction of the step's motion
  /// UNIT vector at tau from particle 1 toward the other object: PP toward particle 2; PE
  /// toward the closest point of the segment (the endpoint at a cap); PH -m/|m|, toward the
  /// boundary.
  Vec2 normal = Vec2::Zero();
  double alpha = 0.0;  // PE: the closest point's parameter on the segment at tau, in [0, 1]
                       // (exactly 0 or 1 at a cap); 0 for PP and PH
};

/// Detection. *hit (if not null) is written only on Hit. No heap allocation; early exits as
/// in ccd.h (approach line first, a swept-box test for PE).
CcdOutcome exactPP(const PPInput& in, ExactContact* hit);
/// Particle 1 (radius rv) against the CAPSULE of radius re around the segment x2-x3 (the
/// endpoint particles' own radii play no part: the caller tests them as PP pairs).
CcdOutcome exactPE(const PEInput& in, ExactContact* hit);
/// A zero normal cannot be normalised and gives Overflow like a non-finite one (the scene
/// loader rejects it, so only corrupted state gets here).
CcdOutcome exactPH(const PHInput& in, ExactContact* hit);

}  // namespace fosssim::math
