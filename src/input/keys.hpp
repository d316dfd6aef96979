// Key codes, for the testbed's keys and the games': SDL's keycodes (a
// printable key is its ASCII code), without SDL's header, so that the
// testbed and the games build without SDL; window.cpp checks at compile
// time that they are SDL's.
#pragma once

namespace physics::key {

inline constexpr int escape = 27, tab = '\t', space = ' ', enter = '\r';
inline constexpr int right = (1 << 30) | 79, left = (1 << 30) | 80, down = (1 << 30) | 81,
                     up = (1 << 30) | 82;  // SDLK_RIGHT, _LEFT, _DOWN, _UP
inline constexpr int lshift = (1 << 30) | 225, rshift = (1 << 30) | 229;  // SDLK_LSHIFT, _RSHIFT

}  // namespace physics::key
