// FOSSSIM_ASSERT: a contract that holds in every build (Release included), as Box2D's
// B2_ASSERT. For conditions the code itself guarantees (fixed capacities, sizes the callers
// promise), never for bad input: scene files, options and states are checked where they enter
// and reported with a message. A broken contract is a bug of FOSSSim; it is reported with its
// file and line and the program stops (std::abort), rather than computing on with a truncated
// polynomial or a dropped interval. The test costs a predictable branch; the failure path is out
// of line.
#pragma once

#include <cstdio>
#include <cstdlib>

namespace fosssim::math {

[[noreturn]] inline void contractFailed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "FOSSSim internal error: %s:%d: contract '%s' does not hold (a bug: please report it)\n",
               file, line, condition);
  std::abort();
}

}  // namespace fosssim::math

#if defined(__GNUC__) || defined(__clang__)
#define FOSSSIM_ASSERT(condition)                    \
  (__builtin_expect(static_cast<bool>(condition), 1) \
       ? (void)0                                     \
       : ::fosssim::math::contractFailed(#condition, __FILE__, __LINE__))
#else
#define FOSSSIM_ASSERT(condition) \
  (static_cast<bool>(condition) ? (void)0 : ::fosssim::math::contractFailed(#condition, __FILE__, __LINE__))
#endif
