// Wall-clock time per stage of the step, for the HUD and the headless
// summary: the course's systems and each stage of the engine's numerics.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <string_view>

namespace physics {

enum class Stage : std::uint8_t {
  forces,       // the Forces system
  move,         // the Move system
  collision,    // the Collision system's pass (its broad phase included)
  pairs,        // the broad phase of the numerics stages
  ccd,          // swept collision: impacts in time order
  prepare,      // stable solver: contacts from the pairs
  warm_start,   // stable solver: last substep's impulses applied again
  relax,        // stable solver: sequential impulses, then the bottom-up pass
  restitution,  // stable solver: bounces, second relaxation, energy guard
  impact_time,  // stable solver: impacts moved to their time in the substep
  store,        // stable solver: impulses kept for the next warm start
  positions,    // stable solver: overlaps projected apart after Move
  health,       // the checks after the step (engine/health.hpp)
};
inline constexpr std::size_t stage_count = 13;
std::string_view name(Stage s);

struct StageTimes {
  std::array<std::int64_t, stage_count> ns{};
  std::int64_t steps = 0;

  double ms_per_step(Stage s) const;
  double total_ms_per_step() const;

  // Runs f and adds its wall-clock time to stage s.
  template <class F>
  void time(Stage s, F&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    ns[static_cast<std::size_t>(s)] +=
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
  }
};

}  // namespace physics
