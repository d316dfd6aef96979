// What the stages that keep their results while their inputs stay the same
// share: a resting pile's bodies come back to the same bits substep after
// substep, and the broad phase's pairs (BroadPhase::find) and the stable
// solver's classification and contacts (ContactSolver::classify, prepare)
// are then the last ones.
#pragma once

#include <bit>
#include <cstdint>

namespace physics {

// Whether they keep them: the same bits either way. Not in the browser's
// build (WebAssembly under WASI), which stays within its size budget
// without that code (docs/web.md); there the other shortcuts to the same
// result that cost code take their plain path too (each marked "the
// browser's build" where it is tested).
#if defined(__wasi__)
inline constexpr bool keeps_unchanged = false;
#else
inline constexpr bool keeps_unchanged = true;
#endif

// Nonzero when a and b differ in any bit (a zero's sign, a NaN's payload):
// == would take -0 for +0, whose signs the contact law does not treat
// alike, and never a NaN for itself.
inline std::uint64_t bits_differ(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) ^ std::bit_cast<std::uint64_t>(b);
}

}  // namespace physics
