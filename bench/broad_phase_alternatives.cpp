#include "broad_phase_alternatives.h"

#include "bench_scenes.h"

#include "../src/core/collision/box_grid.h"
#include "../src/core/collision/pair_bounds.h"
#include "fosssim/core/integrator.h"
#include "fosssim/core/simulator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace fosssim::bench {
namespace {

double msSince(std::chrono::steady_clock::time_point t) {
  return 1000.0 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// The spatial hash of the first implementation: each box in every cell it covers (up to 64),
/// cells hashed into compressed buckets; a pair is reported from the cell of the lower corner of
/// the boxes' intersection only.
class HashGrid {
 public:
  void build(const std::vector<Box>& boxes) {
    boxes_ = &boxes;
    large_.clear();
    std::vector<double> extents;
    for (const Box& b : boxes) extents.push_back(std::max(b.x1 - b.x0, b.y1 - b.y0));
    auto nth = extents.begin() + static_cast<long>(0.9 * static_cast<double>(extents.size() - 1));
    std::nth_element(extents.begin(), nth, extents.end());
    inverse_ = 1.0 / *nth;
    originX_ = originY_ = 1e300;
    for (const Box& b : boxes) originX_ = std::min(originX_, b.x0), originY_ = std::min(originY_, b.y0);
    long entries = 0;
    for (size_t k = 0; k < boxes.size(); ++k) {
      const long c = cells(boxes[k]);
      if (c > 64) large_.push_back(static_cast<int>(k));
      else entries += c;
    }
    uint32_t buckets = 16;
    while (buckets < 2 * entries) buckets <<= 1;
    mask_ = buckets - 1;
    start_.assign(buckets + 1, 0);
    entries_.resize(static_cast<size_t>(entries));
    auto each = [&](const Box& b, auto&& f) {
      for (int y = cy(b.y0); y <= cy(b.y1); ++y)
        for (int x = cx(b.x0); x <= cx(b.x1); ++x) f(bucket(x, y));
    };
    for (size_t k = 0; k < boxes.size(); ++k)
      if (cells(boxes[k]) <= 64) each(boxes[k], [&](uint32_t h) { ++start_[h + 1]; });
    for (uint32_t h = 0; h < buckets; ++h) start_[h + 1] += start_[h];
    std::vector<int> cursor(start_.begin(), start_.end() - 1);
    for (size_t k = 0; k < boxes.size(); ++k)
      if (cells(boxes[k]) <= 64) each(boxes[k], [&](uint32_t h) { entries_[cursor[h]++] = static_cast<int>(k); });
  }
  template <class Visit>
  void query(const Box& b, Visit&& visit) const {
    for (int k : large_)
      if (overlap(b, (*boxes_)[k])) visit(k);
    const int x0 = cx(b.x0), x1 = cx(b.x1), y0 = cy(b.y0), y1 = cy(b.y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const uint32_t h = bucket(x, y);
        int previous = -1;
        for (int e = start_[h]; e < start_[h + 1]; ++e) {
          const int k = entries_[e];
          if (k == previous) continue;
          previous = k;
          const Box& o = (*boxes_)[k];
          if (!overlap(b, o)) continue;
          if (cx(std::max(b.x0, o.x0)) != x || cy(std::max(b.y0, o.y0)) != y) continue;
          visit(k);
        }
      }
  }

 private:
  int cx(double x) const { return static_cast<int>(std::floor((x - originX_) * inverse_)); }
  int cy(double y) const { return static_cast<int>(std::floor((y - originY_) * inverse_)); }
  long cells(const Box& b) const { return (cx(b.x1) - cx(b.x0) + 1L) * (cy(b.y1) - cy(b.y0) + 1L); }
  uint32_t bucket(int x, int y) const {
    const uint32_t h = static_cast<uint32_t>(x) * 0x9E3779B1u ^ static_cast<uint32_t>(y) * 0x85EBCA77u;
    return (h ^ (h >> 15)) & mask_;
  }
  const std::vector<Box>* boxes_ = nullptr;
  double originX_ = 0, originY_ = 0, inverse_ = 1;
  uint32_t mask_ = 0;
  std::vector<int> start_, entries_, large_;
};

/// Swept boxes of a step of `scene` at about n particles, after `steps` steps.
std::vector<Box> stepBoxes(const std::string& scene, int n, long steps) {
  BenchScene s;
  makeScene(scene, n, "hybrid", 1, s);
  std::unique_ptr<Simulator> sim;
  std::vector<Box> boxes;
  if (!Simulator::create(s.scene, {}, sim)) return boxes;
  State state = s.state;
  for (long k = 0; k < steps; ++k)
    if (!sim->step(s.scene, state)) return boxes;
  const VecX qs = state.x;
  if (!findIntegrator(s.scene.integrator)->make()->step(s.scene, state, s.scene.dt)) return boxes;
  const double scale = coordinateScale(s.scene, qs, state.x);
  for (int p = 0; p < s.scene.numParticles(); ++p)  // as the default mode's broad phase files them
    boxes.push_back(particleBox(s.scene, qs, state.x, p, scale, 0.0, Margins::Relative));
  return boxes;
}

template <class Rows>
BroadPhaseTiming best(const std::string& scene, int n, const char* method, int repeats, Rows&& rows) {
  BroadPhaseTiming t{scene, n, method, 1e300, 1e300, 0};
  for (int r = 0; r < repeats; ++r) {
    double build = 0, query = 0;
    t.pairs = rows(build, query);
    if (build + query < t.buildMs + t.queryMs) t.buildMs = build, t.queryMs = query;
  }
  return t;
}

}  // namespace

std::vector<BroadPhaseTiming> compareBroadPhases(const std::vector<std::string>& scenes, const std::vector<int>& sizes,
                                                 int repeats) {
  std::vector<BroadPhaseTiming> out;
  for (const std::string& scene : scenes) {
    for (int n : sizes) {
      // rain: the pile half formed; the others: well under way.
      const std::vector<Box> boxes = stepBoxes(scene, n, scene == "rain" ? 300 : 100);
      const int count = static_cast<int>(boxes.size());
      std::vector<int> row;
      out.push_back(best(scene, n, "grid", repeats, [&](double& build, double& query) {
        auto t0 = std::chrono::steady_clock::now();
        BoxGrid grid;
        grid.build(boxes.data(), count);
        build = msSince(t0);
        t0 = std::chrono::steady_clock::now();
        long pairs = 0;
        for (int i = 0; i < count; ++i) {
          row.clear();
          grid.forEachOverlap(boxes[i], [&](int j) {
            if (j > i) row.push_back(j);
          });
          std::sort(row.begin(), row.end());
          pairs += static_cast<long>(row.size());
        }
        query = msSince(t0);
        return pairs;
      }));
      out.push_back(best(scene, n, "hash", repeats, [&](double& build, double& query) {
        auto t0 = std::chrono::steady_clock::now();
        HashGrid grid;
        grid.build(boxes);
        build = msSince(t0);
        t0 = std::chrono::steady_clock::now();
        long pairs = 0;
        for (int i = 0; i < count; ++i) {
          row.clear();
          grid.query(boxes[i], [&](int j) {
            if (j > i) row.push_back(j);
          });
          std::sort(row.begin(), row.end());
          pairs += static_cast<long>(row.size());
        }
        query = msSince(t0);
        return pairs;
      }));
      out.push_back(best(scene, n, "sap", repeats, [&](double& build, double& query) {
        auto t0 = std::chrono::steady_clock::now();
        std::vector<int> order(count);
        for (int k = 0; k < count; ++k) order[k] = k;
        std::sort(order.begin(), order.end(), [&](int a, int b) { return boxes[a].x0 < boxes[b].x0; });
        build = msSince(t0);
        t0 = std::chrono::steady_clock::now();
        std::vector<uint64_t> pairs;
        for (int a = 0; a < count; ++a) {
          const Box& A = boxes[order[a]];
          for (int b = a + 1; b < count && boxes[order[b]].x0 <= A.x1; ++b) {
            const Box& B = boxes[order[b]];
            if (A.y0 <= B.y1 && B.y0 <= A.y1) {
              const uint64_t i = static_cast<uint64_t>(std::min(order[a], order[b]));
              const uint64_t j = static_cast<uint64_t>(std::max(order[a], order[b]));
              pairs.push_back(i << 32 | j);
            }
          }
        }
        std::sort(pairs.begin(), pairs.end());  // into the rows' order
        query = msSince(t0);
        return static_cast<long>(pairs.size());
      }));
      const long expected = out[out.size() - 3].pairs;
      for (size_t k = out.size() - 2; k < out.size(); ++k)
        if (out[k].pairs != expected)
          std::fprintf(stderr, "broad phase %s on %s: %ld pairs, the grid found %ld\n", out[k].method.c_str(),
                       scene.c_str(), out[k].pairs, expected);
    }
  }
  return out;
}

}  // namespace fosssim::bench
