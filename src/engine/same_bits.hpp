// Bit-for-bit comparison of doubles, for the stages that keep what they
// computed while its inputs stay the same (a resting pile's bodies come back
// to the same bits substep after substep): == would take -0 for +0, whose
// signs the contact law does not treat alike, and never a NaN for itself.
#pragma once

#include <bit>
#include <cstdint>

namespace physics {

// Nonzero when a and b differ in any bit (a zero's sign, a NaN's payload).
inline std::uint64_t bits_differ(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) ^ std::bit_cast<std::uint64_t>(b);
}

}  // namespace physics
