// libFuzzer target over the map loaders (src/scene/tiled.cpp, ldtk.cpp,
// map.cpp): any bytes, read as a Tiled map and as an LDtk project, either
// give a valid scene or throw a SceneError whose one line names the file.
// Anything else (a crash, a sanitizer report, another exception, a hang, an
// error of several lines or naming no file) is a bug; a scene that loads
// must also build and step.
// The maps' path is scenes/maps/fuzz.*: run from the project's folder (make
// fuzz does), an external tileset of the seeds (props.tsj) is found there.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "scene/map.hpp"
#include "scene/scene.hpp"
#include "scene/scene_json.hpp"

namespace {

void load_map(std::string_view text, const std::string& path) {
  using namespace physics;
  try {
    const SceneSpec spec = read_map(text, path);
    const std::vector<Body> bodies = expand(spec, path);
    if (bodies.size() <= 200) {
      World w = make_world(spec, bodies, false);
      for (int i = 0; i < 3 && !w.health.non_finite; ++i) Game::step(w);
    }
  } catch (const SceneError& e) {
    const std::string_view m = e.what();
    if (!m.starts_with(path + ":") || m.find('\n') != std::string_view::npos) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  load_map(text, "scenes/maps/fuzz.tmj");
  load_map(text, "scenes/maps/fuzz.ldtk");
  return 0;
}
