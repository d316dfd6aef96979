// libFuzzer target over the scene loader: any bytes either parse into a valid
// scene or throw SceneError. Anything else (a crash, a sanitizer report, an
// uncaught exception of another type, a hang) is a bug.
// Run with `make fuzz SECONDS=600`; see the Makefile.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "app/scene.hpp"
#include "app/scene_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace physics;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const SceneSpec spec = parse_scene(text, "fuzz");
    // A scene that parsed must also build and step: small ones only, to keep
    // each input fast.
    if (body_count(spec) <= 200) {
      World w = make_world(spec, false, "fuzz");
      for (int i = 0; i < 3; ++i) Game::step(w);
    }
  } catch (const SceneError&) {
    // the expected outcome for bad input
  }
  return 0;
}
