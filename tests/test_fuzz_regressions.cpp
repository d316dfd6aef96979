// Inputs the scene-loader fuzzer (fuzz/scene_fuzzer.cpp) found or that guard
// its limits: tests/fuzz_regressions/bad-*.json must be refused with a
// SceneError, ok-*.json must load and step. Nothing may crash.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "helpers.hpp"
#include "scene/scene_json.hpp"

using namespace physics;
namespace fs = std::filesystem;

BOOST_AUTO_TEST_SUITE(fuzz_regressions)

BOOST_AUTO_TEST_CASE(every_regression_input_is_refused_or_loads_as_named) {
  const fs::path dir = fs::path(__FILE__).parent_path() / "fuzz_regressions";
  int seen = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    ++seen;
    if (name.rfind("bad-", 0) == 0) {
      BOOST_CHECK_THROW(parse_scene(text.str(), name), SceneError);
    } else {
      BOOST_TEST_CONTEXT(name) {
        const SceneSpec spec = parse_scene(text.str(), name);
        World w = make_world(spec, false, name);
        for (int i = 0; i < 3; ++i) Game::step(w);
        for (const Vector& p : w.components.position) BOOST_TEST((std::isfinite(p.x) && std::isfinite(p.y)));
      }
    }
  }
  BOOST_TEST(seen >= 5);
}

BOOST_AUTO_TEST_SUITE_END()
