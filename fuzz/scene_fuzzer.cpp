// libFuzzer target over the scene loader: any bytes either parse into a valid
// scene or throw SceneError. Anything else (a crash, a sanitizer report, an
// uncaught exception of another type, a hang, a non-finite state the health
// check let through) is a bug.
// Run with `make fuzz SECONDS=600`; see the Makefile.
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstdint>
#include <string_view>

#include "scene/scene.hpp"
#include "scene/scene_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace physics;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    // Read, then validate once (expand), as the command line loads a file.
    const SceneSpec spec = read_scene(text, "fuzz");
    const std::vector<Body> bodies = expand(spec, "fuzz");
    // A scene that passed must also build and step: small ones only, to keep
    // each input fast.
    if (bodies.size() <= 200) {
      World w = make_world(spec, bodies, false);
      for (int i = 0; i < 3 && !w.health.non_finite; ++i) Game::step(w);
      // A non-finite position or velocity that the health check did not
      // stop with its error would be reported as a result: a bug.
      if (!w.health.non_finite)
        for (std::size_t e = 0; e < w.components.size(); ++e) {
          const Vector p = w.components.position[e], v = w.components.velocity[e];
          if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(v.x) && std::isfinite(v.y))) std::abort();
        }
    }
  } catch (const SceneError&) {
    // the expected outcome for bad input
  }
  return 0;
}
