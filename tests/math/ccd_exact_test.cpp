// exactPP/PE/PH on random scenes: agreement with the reference detectors where the two must
// agree, invariance under scaling and translation, a brute-force capsule check, and the cost per
// query. Contacts worked out by hand, at unit and at extreme scales: ccd_exact_closed_form_test.cpp.
#include "fosssim/math/ccd_exact.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace fosssim::math {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// ------------------------------------------------------------ random scenes
// Coordinates on a 2^-20 grid, so that offsets up to 2^30 translate them without rounding.

class Scenes {
 public:
  explicit Scenes(unsigned seed) : rng_(seed) {}
  double real(double lo, double hi) {
    const double v = std::uniform_real_distribution<double>(lo, hi)(rng_);
    return std::round(v * 1048576.0) / 1048576.0;
  }
  // x drawn before y, in separate statements: a call's arguments are evaluated in an order the
  // compiler picks (gcc right to left, clang left to right), and both must build the same scenes.
  Vec2 vec(double reach) {
    const double x = real(-reach, reach);
    const double y = real(-reach, reach);
    return Vec2(x, y);
  }

  PPInput pp() {
    PPInput in;
    in.x1 = vec(1.0);
    in.r1 = real(0.02, 0.3);
    in.r2 = real(0.02, 0.3);
    in.x2 = in.x1 + vec(1.5);
    in.d1 = vec(1.0);
    in.d2 = vec(1.0);
    return in;
  }
  // Short edges and thick capsules, so that caps are involved in many contacts.
  PEInput pe() {
    PEInput in;
    in.x2 = vec(1.0);
    in.x3 = in.x2 + vec(0.6);
    in.x1 = in.x2 + vec(0.8);
    in.rv = real(0.02, 0.2);
    in.re = real(0.0, 0.15);
    in.d1 = vec(1.5);
    in.d2 = vec(0.5);
    in.d3 = in.d2 + vec(0.3);
    return in;
  }
  PHInput ph() {
    PHInput in;
    in.x1 = vec(1.0);
    in.r = real(0.02, 0.3);
    in.p = in.x1 + vec(0.8);
    in.m = vec(2.0);
    in.d1 = vec(1.0);
    return in;
  }

 private:
  std::mt19937 rng_;
};

// One detection's answer in a comparable form.
struct Answer {
  bool hit = false;
  double tau = kNever;
  Vec2 normal = Vec2::Zero();
  double alpha = 0.0;
};

Answer exact(const PPInput& in) {
  ExactContact c;
  const CcdOutcome o = exactPP(in, &c);
  EXPECT_NE(o, CcdOutcome::Overflow);
  return {o == CcdOutcome::Hit, c.tau, c.normal, c.alpha};
}
Answer exact(const PEInput& in) {
  ExactContact c;
  const CcdOutcome o = exactPE(in, &c);
  EXPECT_NE(o, CcdOutcome::Overflow);
  return {o == CcdOutcome::Hit, c.tau, c.normal, c.alpha};
}
Answer exact(const PHInput& in) {
  ExactContact c;
  const CcdOutcome o = exactPH(in, &c);
  EXPECT_NE(o, CcdOutcome::Overflow);
  return {o == CcdOutcome::Hit, c.tau, c.normal, c.alpha};
}
// The reference's answers, its contact vector normalised.
Answer fromContact(bool hit, const Contact& c) {
  return {hit, c.tau, hit ? Vec2(c.n.normalized()) : Vec2::Zero(), 0.0};
}
Answer reference(const PPInput& in) {
  Contact c;
  return fromContact(detectPP(in, &c), c);
}
Answer reference(const PEInput& in) {
  Contact c;
  return fromContact(detectPE(in, &c, nullptr, DetectionRules{}), c);
}
Answer reference(const PHInput& in) {
  Contact c;
  return fromContact(detectPH(in, &c), c);
}

// Radii scaled by (1 + rel), and whole scenes scaled by s and shifted by o.
PPInput withRadii(PPInput in, double f) { return in.r1 *= f, in.r2 *= f, in; }
PEInput withRadii(PEInput in, double f) { return in.rv *= f, in.re *= f, in; }
PHInput withRadii(PHInput in, double f) { return in.r *= f, in; }
PPInput transformed(PPInput in, double s, Vec2 o) {
  return {s * in.x1 + o, s * in.d1, s * in.r1, s * in.x2 + o, s * in.d2, s * in.r2};
}
PEInput transformed(PEInput in, double s, Vec2 o) {
  return {s * in.x1 + o, s * in.d1, s * in.rv, s * in.x2 + o, s * in.d2, s * in.x3 + o, s * in.d3, s * in.re};
}
PHInput transformed(PHInput in, double s, Vec2 o) { return {s * in.x1 + o, s * in.d1, s * in.r, s * in.p + o, in.m}; }

// A scene is well conditioned for `detect` when changing the radii by a relative 1e-7 keeps the
// outcome and moves tau by less than 1e-5: then rounding-level differences (1e-16 relative)
// between two correct computations move tau by far less than 1e-9. Grazing pairs and contacts
// that begin where a condition barely changes sign are excluded this way; they are rare.
template <class In>
bool wellConditioned(const In& in, const std::function<Answer(const In&)>& detect) {
  const Answer lo = detect(withRadii(in, 1.0 - 1e-7)), mid = detect(in), hi = detect(withRadii(in, 1.0 + 1e-7));
  if (lo.hit != mid.hit || hi.hit != mid.hit) return false;
  return !mid.hit || std::fabs(hi.tau - lo.tau) < 1e-5;
}

constexpr int kScenes = 3000;

// ------------------------------------------------------------ agreement with the reference

TEST(ExactCcdAgreement, PPAndPHMatchReferenceAtUnitScale) {
  Scenes g(11);
  int compared = 0, hits = 0;
  for (int i = 0; i < kScenes; ++i) {
    const PPInput pp = g.pp();
    if (wellConditioned<PPInput>(pp, [](const PPInput& x) { return reference(x); })) {
      const Answer r = reference(pp), e = exact(pp);
      ASSERT_EQ(r.hit, e.hit) << "PP scene " << i;
      if (r.hit) {
        EXPECT_NEAR(r.tau, e.tau, 1e-9);
        EXPECT_NEAR((r.normal - e.normal).norm(), 0.0, 1e-9);
      }
      ++compared, hits += r.hit;
    }
    const PHInput ph = g.ph();
    if (wellConditioned<PHInput>(ph, [](const PHInput& x) { return reference(x); })) {
      const Answer r = reference(ph), e = exact(ph);
      ASSERT_EQ(r.hit, e.hit) << "PH scene " << i;
      if (r.hit) {
        EXPECT_NEAR(r.tau, e.tau, 1e-9);
        EXPECT_NEAR((e.normal + ph.m.normalized()).norm(), 0.0, 1e-12);  // -m/|m|
      }
      ++compared, hits += r.hit;
    }
  }
  EXPECT_GT(compared, 2 * kScenes * 95 / 100);
  EXPECT_GT(hits, compared / 5);
  EXPECT_LT(hits, compared * 4 / 5);
}


// The capsule contains the reference's interior region: every reference hit is an exact hit no
// later; where the exact hit lies strictly inside the segment, or the exact answer is a miss,
// the two agree (the caps are then not involved).
TEST(ExactCcdAgreement, PEMatchesReferenceAwayFromTheCaps) {
  Scenes g(12);
  int interior = 0, misses = 0, caps = 0;
  for (int i = 0; i < kScenes; ++i) {
    const PEInput pe = g.pe();
    if (!wellConditioned<PEInput>(pe, [](const PEInput& x) { return reference(x); }) ||
        !wellConditioned<PEInput>(pe, [](const PEInput& x) { return exact(x); }))
      continue;
    const Answer r = reference(pe), e = exact(pe);
    if (r.hit) {
      ASSERT_TRUE(e.hit) << "PE scene " << i;
      EXPECT_LE(e.tau, r.tau + 1e-9);
    }
    if (!e.hit) {
      ++misses;
      EXPECT_FALSE(r.hit);
    } else if (e.alpha > 0.0 && e.alpha < 1.0) {
      ++interior;
      ASSERT_TRUE(r.hit) << "PE scene " << i;
      EXPECT_NEAR(r.tau, e.tau, 1e-9);
      EXPECT_NEAR((r.normal - e.normal).norm(), 0.0, 1e-9);
    } else {
      ++caps;
    }
  }
  EXPECT_GT(interior, kScenes / 10);
  EXPECT_GT(misses, kScenes / 10);
  EXPECT_GT(caps, kScenes / 20);
}

// ------------------------------------------------------------ brute force (capsule semantics)

// Distance from x to the segment ab, with the clamped parameter of the closest point.
double segmentDistance(const Vec2& x, const Vec2& a, const Vec2& b, double* alpha) {
  *alpha = segmentParameterClamped(x, a, b);
  return (pointOnSegment(a, b, *alpha) - x).norm();
}

// Rate of change of the squared capsule distance at t. By Danskin's theorem the derivative of
// min over alpha in [0, 1] of |x1 - x2 - alpha e|^2 is the partial derivative at the minimiser.
double approachRate(const PEInput& in, double t) {
  const Vec2 x1 = in.x1 + t * in.d1, x2 = in.x2 + t * in.d2, x3 = in.x3 + t * in.d3;
  double alpha;
  segmentDistance(x1, x2, x3, &alpha);
  const Vec2 rel = x1 - pointOnSegment(x2, x3, alpha);
  return 2.0 * rel.dot(in.d1 - in.d2 - alpha * (in.d3 - in.d2));
}

// Sampled on a fine grid, independently of any polynomial: no instant before tau where the pair
// clearly overlaps and clearly approaches; at tau > 0 the pair touches (or starts to approach);
// alpha and the normal describe the closest point at tau.
TEST(ExactCcdBruteForce, PECapsuleAgainstSampling) {
  Scenes g(13);
  constexpr int kSamples = 2000;
  int hits = 0;
  for (int i = 0; i < 1000; ++i) {
    const PEInput in = g.pe();
    const double R = in.rv + in.re;
    ExactContact c;
    const bool hit = exactPE(in, &c) == CcdOutcome::Hit;
    for (int k = 0; k <= kSamples; ++k) {
      const double t = static_cast<double>(k) / kSamples;
      if (hit && t >= c.tau) break;
      double alpha;
      const double dist = segmentDistance(in.x1 + t * in.d1, in.x2 + t * in.d2, in.x3 + t * in.d3, &alpha);
      ASSERT_FALSE(dist < R * (1.0 - 1e-6) && approachRate(in, t) < -1e-6)
          << "scene " << i << " collides at " << t << (hit ? " before tau " : ", reported a miss") << c.tau;
    }
    if (!hit) continue;
    ++hits;
    const Vec2 x1 = in.x1 + c.tau * in.d1, x2 = in.x2 + c.tau * in.d2, x3 = in.x3 + c.tau * in.d3;
    double alpha;
    const double dist = segmentDistance(x1, x2, x3, &alpha);
    if (c.tau > 0.0) {
      EXPECT_TRUE(std::fabs(dist - R) < 1e-9 || std::fabs(approachRate(in, c.tau)) < 1e-6) << i;
    }
    EXPECT_LT(dist, R + 1e-9);
    EXPECT_NEAR(c.alpha, alpha, 1e-6) << i;
    if (dist > 1e-6) {
      EXPECT_NEAR((c.normal - (pointOnSegment(x2, x3, alpha) - x1) / dist).norm(), 0.0, 1e-6) << i;
    }
    EXPECT_LE(approachRate(in, std::fmin(1.0, c.tau + 1e-9)), 1e-9) << i;
  }
  EXPECT_GT(hits, 200);
}

// ------------------------------------------------------------ scale and translation

template <class In>
void expectInvariant(const char* kind, unsigned seed, In (Scenes::*make)()) {
  Scenes g(seed);
  const double scales[] = {1e-9, 1e-6, 1e-3, 1e3, 1e6, 1e9};
  int checked = 0;
  for (int i = 0; i < 1000; ++i) {
    const In in = (g.*make)();
    if (!wellConditioned<In>(in, [](const In& x) { return exact(x); })) continue;
    ++checked;
    const Answer base = exact(in);
    // Offsets of 2^k size move grid coordinates without rounding: bit-identical answers.
    const Answer far = exact(transformed(in, 1.0, Vec2(1e6, -3e9)));
    ASSERT_EQ(base.hit, far.hit) << kind << " " << i;
    if (base.hit) {
      EXPECT_EQ(base.tau, far.tau) << kind << " " << i;
    }
    for (double s : scales) {
      for (const Vec2& o : {Vec2(0.0, 0.0), Vec2(1e3 * s, -2e3 * s)}) {
        const Answer a = exact(transformed(in, s, o));
        ASSERT_EQ(base.hit, a.hit) << kind << " " << i << " scale " << s;
        if (!base.hit) continue;
        EXPECT_NEAR(base.tau, a.tau, 1e-9) << kind << " " << i << " scale " << s;
        EXPECT_NEAR((base.normal - a.normal).norm(), 0.0, 1e-9) << kind << " " << i << " scale " << s;
        EXPECT_NEAR(base.alpha, a.alpha, 1e-9) << kind << " " << i << " scale " << s;
      }
    }
  }
  EXPECT_GT(checked, 900) << kind;
}

TEST(ExactCcdScale, PPInvariantUnderScaleAndTranslation) { expectInvariant("PP", 21, &Scenes::pp); }
TEST(ExactCcdScale, PEInvariantUnderScaleAndTranslation) { expectInvariant("PE", 22, &Scenes::pe); }
TEST(ExactCcdScale, PHInvariantUnderScaleAndTranslation) { expectInvariant("PH", 23, &Scenes::ph); }

// ------------------------------------------------------------ cost

// Time per query on near pairs against the reference detectors (recorded as test properties
// in the XML output, --gtest_output=xml; nothing printed). The counts check that the loops
// really ran the detectors.
template <class In, class F>
double nanosecondsPerQuery(const std::vector<In>& inputs, F detect, int* hits) {
  using Clock = std::chrono::steady_clock;
  double best = kInf;
  for (int repeat = 0; repeat < 3; ++repeat) {
    int count = 0;
    const auto start = Clock::now();
    for (int sweep = 0; sweep < 20; ++sweep)
      for (const In& in : inputs) count += detect(in);
    const std::chrono::duration<double, std::nano> spent = Clock::now() - start;
    best = std::fmin(best, spent.count() / (20.0 * static_cast<double>(inputs.size())));
    *hits = count / 20;
  }
  return best;
}

TEST(ExactCcdCost, QueryTimesAgainstReference) {
  Scenes g(31);
  std::vector<PPInput> pps;
  std::vector<PEInput> pes;
  std::vector<PHInput> phs;
  for (int i = 0; i < 2000; ++i) pps.push_back(g.pp()), pes.push_back(g.pe()), phs.push_back(g.ph());
  int refHits = 0, exactHits = 0;
  const auto record = [](const char* key, double ns) { ::testing::Test::RecordProperty(key, std::to_string(ns)); };
  record("pp_reference_ns", nanosecondsPerQuery(pps, [](const PPInput& x) { return detectPP(x, nullptr); }, &refHits));
  record("pp_exact_ns", nanosecondsPerQuery(
                            pps, [](const PPInput& x) { return exactPP(x, nullptr) == CcdOutcome::Hit; }, &exactHits));
  EXPECT_NEAR(refHits, exactHits, 20);
  record("pe_reference_ns", nanosecondsPerQuery(pes, [](const PEInput& x) { return detectPE(x, nullptr); }, &refHits));
  record("pe_exact_ns", nanosecondsPerQuery(
                            pes, [](const PEInput& x) { return exactPE(x, nullptr) == CcdOutcome::Hit; }, &exactHits));
  EXPECT_GE(exactHits, refHits);  // the capsule holds the reference's region
  record("ph_reference_ns", nanosecondsPerQuery(phs, [](const PHInput& x) { return detectPH(x, nullptr); }, &refHits));
  record("ph_exact_ns", nanosecondsPerQuery(
                            phs, [](const PHInput& x) { return exactPH(x, nullptr) == CcdOutcome::Hit; }, &exactHits));
  EXPECT_NEAR(refHits, exactHits, 20);
}

}  // namespace
}  // namespace fosssim::math
