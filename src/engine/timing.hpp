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
    add(s, std::chrono::steady_clock::now() - t0);
  }
  void add(Stage s, std::chrono::steady_clock::duration d) {
    ns[static_cast<std::size_t>(s)] += std::chrono::duration_cast<std::chrono::nanoseconds>(d).count();
  }

  // Stages run one after the other: each lap ends where the next one starts,
  // so n stages take n + 1 clock reads instead of 2n. A read costs about
  // 30 ns on these VMs: with two per stage, the stable solver's stages made
  // a quarter of a 9-block scene's step (perf, the question-9 scene under
  // gravity with --solver auto). What runs between two laps counts to the
  // next one; a lap must not contain another StageTimes::time of its own.
  class Laps {
   public:
    explicit Laps(StageTimes& times) : times_(times), last_(std::chrono::steady_clock::now()) {}
    template <class F>
    void time(Stage s, F&& f) {
      f();
      const auto now = std::chrono::steady_clock::now();
      times_.add(s, now - last_);
      last_ = now;
    }

   private:
    StageTimes& times_;
    std::chrono::steady_clock::time_point last_;
  };
};

}  // namespace physics
