// The collision table: every keyword of <collision type="..."> and what it builds.
#include "collision_handlers.h"
#include "event_handler.h"

#include "fosssim/math/contract.h"

namespace fosssim {
namespace {

std::unique_ptr<CollisionHandler> makeSimple(const CollisionSettings& s, const HandlerOptions& o) {
  return std::make_unique<SimpleHandler>(s, o);
}

// Outside --compat, "continuous-time" and "hybrid" resolve contacts in time order (event_handler.h);
// they differ in how many impulses a particle may take in a step before the failsafe.
std::unique_ptr<CollisionHandler> makeContinuousTime(const CollisionSettings& s, const HandlerOptions& o) {
  if (!o.compat) return std::make_unique<EventHandler>(s, kContinuousEventsPerParticle, o);
  return std::make_unique<ContinuousTimeHandler>(s, o);
}

std::unique_ptr<CollisionHandler> makeHybrid(const CollisionSettings& s, const HandlerOptions& o) {
  if (!o.compat) return std::make_unique<EventHandler>(s, s.maxIterations, o);
  return std::make_unique<HybridHandler>(s, o);
}

}  // namespace

const std::vector<CollisionEntry>& collisionTable() {
  //                                  impulses polynomials midStep
  static const RecordLayout kNothing{false, false, false};
  static const RecordLayout kImpulses{true, false, false};
  static const RecordLayout kEverything{true, true, true};
  static const std::vector<CollisionEntry> table = {
      {CollisionType::None, "none", nullptr, false, 0.0, 0.0, kNothing, "no collision handling"},
      {CollisionType::Simple, "simple", makeSimple, false, 0.0, 0.0, kImpulses,
       "discrete: overlapping, approaching pairs at the end of the step get an impulse"},
      {CollisionType::ContinuousTime, "continuous-time", makeContinuousTime, false, 0.0, 0.0, kEverything,
       "every pair tested along its motion during the step; impulses applied at once, one pass"},
      {CollisionType::Hybrid, "hybrid", makeHybrid, true, 10.0, 0.1, kEverything,
       "iterative impulses (maxiters passes), then rigid impact zones; adds a weak penalty force"},
      {CollisionType::Penalty, "penalty", nullptr, true, 100.0, 0.01, kNothing,
       "a penalty force pushes apart pairs closer than their radii plus a thickness"},
  };
  return table;
}

const CollisionEntry& collisionEntry(CollisionType type) {
  const auto& table = collisionTable();
  const auto index = static_cast<size_t>(type);
  FOSSSIM_ASSERT(index < table.size() && table[index].type == type);
  return table[index];
}

const CollisionEntry* findCollisionType(const std::string& keyword) {
  for (const auto& entry : collisionTable())
    if (keyword == entry.keyword) return &entry;
  return nullptr;
}

}  // namespace fosssim
