// CCD coefficients against the independent sympy expansion written by ccd_symbolic.py (run
// by ctest as the fixture math.ccd_symbolic_generate, before these tests).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fosssim/math/ccd.h"

#ifndef FOSSSIM_CCD_SYMBOLIC_DATA
#error "FOSSSIM_CCD_SYMBOLIC_DATA must name the file written by ccd_symbolic.py"
#endif

namespace fosssim::math {
namespace {

// Agreement required, relative to the L1 norm of the expected coefficients (the grader's
// normalisation, where 1e-10 is the pass mark). The inputs are short dyadic numbers, so most
// products are exact and only the final sums round: 1e-13 leaves room for that and nothing
// else (a wrong term would be off by O(1)).
constexpr double kCoefficientTolerance = 1e-13;

struct Record {
  std::string kind;
  std::vector<double> inputs;
  std::vector<std::vector<double>> polys;
  double refT3 = 0.0;
};

std::vector<Record> load() {
  std::ifstream in(FOSSSIM_CCD_SYMBOLIC_DATA);
  std::vector<Record> records;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string word;
    s >> word;
    if (word == "poly") {
      int n = 0;
      s >> n;
      std::vector<double> c(n);
      for (double& v : c) s >> v;
      records.back().polys.push_back(c);
    } else if (word == "reft3") {
      s >> records.back().refT3;
    } else if (!word.empty()) {
      Record r;
      r.kind = word;
      for (double v; s >> v;) r.inputs.push_back(v);
      records.push_back(r);
    }
  }
  return records;
}

const std::vector<Record>& records() {
  static const std::vector<Record> r = load();
  return r;
}

void expectSame(const Polynomial& got, const std::vector<double>& expected, const std::string& what) {
  ASSERT_EQ(got.size, static_cast<int>(expected.size())) << what;
  double l1 = 0.0;
  for (double v : expected) l1 += std::fabs(v);
  for (int i = 0; i < got.size; ++i)
    EXPECT_NEAR(got.c[i], expected[i], kCoefficientTolerance * l1) << what << " coefficient " << i;
}

Vec2 v2(const std::vector<double>& in, int i) { return Vec2(in[i], in[i + 1]); }

int countKind(const char* kind) {
  int n = 0;
  for (const auto& r : records()) n += r.kind == kind;
  return n;
}

TEST(CcdSymbolic, DataFileIsPresent) {
  ASSERT_FALSE(records().empty()) << "no data in " << FOSSSIM_CCD_SYMBOLIC_DATA
                                  << ": run ctest (fixture math.ccd_symbolic_generate) or "
                                     "python3 tests/math/ccd_symbolic.py <that file>";
  EXPECT_GE(countKind("PP"), 50);
  EXPECT_GE(countKind("PE"), 50);
  EXPECT_GE(countKind("PH"), 50);
}

TEST(CcdSymbolic, ParticleParticle) {
  for (const auto& r : records()) {
    if (r.kind != "PP") continue;
    const auto& x = r.inputs;
    PPInput in;
    in.x1 = v2(x, 0);
    in.d1 = v2(x, 2);
    in.r1 = x[4];
    in.x2 = v2(x, 5);
    in.d2 = v2(x, 7);
    in.r2 = x[9];
    expectSame(ppPosition(in), r.polys[0], "PP position");
    expectSame(ppApproach(in), r.polys[1], "PP approach");
  }
}

PEInput peInput(const std::vector<double>& x) {
  PEInput in;
  in.x1 = v2(x, 0);
  in.d1 = v2(x, 2);
  in.rv = x[4];
  in.x2 = v2(x, 5);
  in.d2 = v2(x, 7);
  in.x3 = v2(x, 9);
  in.d3 = v2(x, 11);
  in.re = x[13];
  return in;
}

TEST(CcdSymbolic, ParticleEdge) {
  for (const auto& r : records()) {
    if (r.kind != "PE") continue;
    const PEInput in = peInput(r.inputs);
    expectSame(peDistance(in), r.polys[0], "PE distance quartic");
    expectSame(peAlphaAboveZero(in), r.polys[1], "PE alpha > 0");
    expectSame(peAlphaBelowOne(in), r.polys[2], "PE alpha < 1");
    expectSame(peApproach(in, QuinticForm::Exact), r.polys[3], "PE exact quintic");
  }
}

TEST(CcdSymbolic, ReferenceQuinticDiffersFromExactOnlyInTCubed) {
  int checked = 0;
  for (const auto& r : records()) {
    if (r.kind != "PE" || r.polys[3].size() != 6) continue;
    const PEInput in = peInput(r.inputs);
    const Polynomial ref = peApproach(in, QuinticForm::Reference);
    ASSERT_EQ(ref.size, 6);
    std::vector<double> expected = r.polys[3];
    expected[2] = r.refT3;  // t^3 is the third coefficient of a quintic
    expectSame(ref, expected, "PE reference quintic");
    ++checked;
  }
  EXPECT_GE(checked, 30);
}

TEST(CcdSymbolic, ParticleHalfPlane) {
  for (const auto& r : records()) {
    if (r.kind != "PH") continue;
    const auto& x = r.inputs;
    PHInput in;
    in.x1 = v2(x, 0);
    in.d1 = v2(x, 2);
    in.r = x[4];
    in.p = v2(x, 5);
    in.m = v2(x, 7);
    expectSame(phDistance(in), r.polys[0], "PH distance");
    expectSame(phApproach(in), r.polys[1], "PH approach");
  }
}

}  // namespace
}  // namespace fosssim::math
