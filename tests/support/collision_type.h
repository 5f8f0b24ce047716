// Tests name collision methods by their scene-file keywords (as traces and parameter lists read
// best); a scene holds the method itself. A misspelt keyword fails the test that uses it.
#pragma once

#include "fosssim/core/collision_handler.h"

#include <stdexcept>
#include <string>

namespace fosssim::test {

inline CollisionType collisionType(const std::string& keyword) {
  const CollisionEntry* entry = findCollisionType(keyword);
  if (!entry) throw std::invalid_argument("no collision type \"" + keyword + "\"");
  return entry->type;
}

}  // namespace fosssim::test
