// The friction case of `make report` (docs/game-physics.md): a block
// launched along the floor stops after v0²/(2 mu g); how far off each
// solver's stop distance is, against dt. Also used by tests/test_numerics.cpp.
#pragma once

#include <string>
#include <vector>

#include "numerics/scenes.hpp"

namespace physics::numerics {

struct Slide {
  double v0 = 0.5, mu = 0.5, g = 0.001;  // px/ms, -, px/ms²
  double exact() const { return v0 * v0 / (2 * mu * g); }
};

struct SlideResult {
  double distance = 0;  // px the block slid before it stopped
  double error = 0;     // (distance - exact) / exact
  int frames = 0;       // frames until it stopped (the run gives up after 100 s)
  bool stopped = false;
};

SlideResult run_slide(const Mode& m, const Slide& s = {});

// The settings of the friction table: each solver at the sheet's dt and
// finer, as the report's other families.
struct FrictionSetting {
  std::string family, label;
  Mode mode;
};
std::vector<FrictionSetting> friction_settings();

}  // namespace physics::numerics
