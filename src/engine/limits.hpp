// The one set of limits on what a world may hold. The scene validator
// (scene/scene.cpp, validate/expand) rejects any scene outside them with a
// message naming the key; the engine's own guards (validate(Params) in the
// World's constructor, the asserts of Block::make) check the same numbers, so
// every scene the validator accepts passes them.
#pragma once

#include <cstdint>

namespace physics {

// Limits that keep any input from exhausting memory, hanging the loader or
// overflowing: sizes are summed in Rect::mdiff and minkowski_difference (int), far below INT_MAX here.
// Frames a run may ask for (--frames, a saved state's frame, an input log's
// ticks): exactly representable as doubles, far beyond any run that ends.
inline constexpr std::int64_t max_frames = std::int64_t{1} << 53;
inline constexpr int max_world_size = 1 << 20;  // px, per side
inline constexpr int max_block_size = 1 << 20;  // px, per side
inline constexpr std::int64_t max_bodies = 1'000'000;
inline constexpr int max_substeps = 1000;
inline constexpr int max_iterations = 1000;
inline constexpr double max_motion = 1e6;  // |velocity|, |force|, |impulse|, |gravity| per axis
inline constexpr double max_dt = 1e6;      // ms
// Masses: within them no figure a run prints overflows (docs/reliability.md,
// "No non-finite figure"). A speed stays below about 1e28 px/ms (gravity and
// dt at their limits for max_frames frames), so m v^2 summed over max_bodies
// stays below 1e213; an impulse, a momentum, below 1e185; 1 / min_mass is
// finite (a mass of 1e-320 made the inverse mass inf and the impulses NaN).
inline constexpr double max_mass = 1e150;
inline constexpr double min_mass = 1e-300;
// The smallest dt: below it, impulse/dt (the first frame's force) and the
// Forces' divisions overflow or lose all precision (--dt 1e-320 gave NaN).
inline constexpr double min_dt = 1e-6;     // ms
// The largest friction coefficient (rubber on rubber is about 1; beyond a
// few, every contact sticks anyway).
inline constexpr double max_friction = 1e3;

}  // namespace physics
