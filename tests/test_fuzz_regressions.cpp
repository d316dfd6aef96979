// Inputs the fuzzers (fuzz/scene_fuzzer.cpp, fuzz/map_fuzzer.cpp) found or
// that guard their limits: tests/fuzz_regressions/bad-*.json must be refused
// with a SceneError, ok-*.json must load and step; the same for the maps of
// tests/fuzz_regressions/maps/ (.tmj, .ldtk), whose errors are one line
// naming the file. And the sample maps, truncated and with hostile values,
// as the map fuzzer mutates them. Nothing may crash.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "helpers.hpp"
#include "scene/map.hpp"
#include "scene/scene_json.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_fuzz_regressions {

using namespace physics;
namespace fs = std::filesystem;

namespace {

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The map `text` read as the file `path`: true if it loads (and then builds
// and steps); false if refused, by a SceneError of one line naming the file.
bool map_loads(const std::string& text, const std::string& path) {
  try {
    const SceneSpec spec = read_map(text, path);
    World w = make_world(spec, false, path);
    for (int i = 0; i < 3; ++i) Game::step(w);
    for (const Vector& p : w.components.position) BOOST_TEST((std::isfinite(p.x) && std::isfinite(p.y)));
    return true;
  } catch (const SceneError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.starts_with(path + ":"), m);
    BOOST_TEST(m.find('\n') == std::string::npos, m);
    return false;
  }
}

// The project's sample maps, read where they are (their tileset beside them).
const fs::path samples = fs::path(__FILE__).parent_path().parent_path() / "scenes" / "maps";

}  // namespace

BOOST_AUTO_TEST_SUITE(fuzz_regressions)

BOOST_AUTO_TEST_CASE(every_regression_input_is_refused_or_loads_as_named) {
  const fs::path dir = fs::path(__FILE__).parent_path() / "fuzz_regressions";
  int seen = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;  // maps/: the next case
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

BOOST_AUTO_TEST_CASE(every_map_regression_input_is_refused_or_loads_as_named) {
  int seen = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(__FILE__).parent_path() / "fuzz_regressions" / "maps")) {
    const std::string name = entry.path().filename().string();
    ++seen;
    // Read as if it lay beside the samples (an external tileset they name is found).
    const std::string path = (samples / name).string();
    BOOST_TEST(map_loads(contents(entry.path()), path) == name.starts_with("ok-"), name);
  }
  BOOST_TEST(seen >= 1);
}

// Each sample cut short at every byte: refused in one line naming the file
// (but for the whole file, and a cut that leaves it whole JSON).
BOOST_AUTO_TEST_CASE(truncated_sample_maps_are_refused_in_one_line) {
  for (const char* name : {"platform.tmj", "level.ldtk"}) {
    const std::string text = contents(samples / name), path = (samples / name).string();
    int loaded = 0;
    for (std::size_t n = 0; n < text.size(); ++n) loaded += map_loads(text.substr(0, n), path);
    BOOST_TEST(loaded <= 1, name);  // at most the cut of the last newline
    BOOST_TEST(map_loads(text, path), name);
  }
}

// Where each JSON number of text is outside strings: (offset, length).
// (Not <regex>: under the sanitizer build g++ 12 warns inside it.)
static std::vector<std::pair<std::size_t, std::size_t>> json_numbers(const std::string& text) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') { in_string = true; continue; }
    if (!(c == '-' || (c >= '0' && c <= '9'))) continue;
    std::size_t j = i + 1;
    while (j < text.size() && std::string_view("0123456789.eE+-").find(text[j]) != std::string_view::npos) ++j;
    out.emplace_back(i, j - i);
    i = j - 1;
  }
  return out;
}

// Each number of each sample replaced, one at a time, by a hostile value
// (negative, zero, huge, past 32 bits, not finite as text, another type):
// it loads or is refused in one line naming the file, never anything else.
BOOST_AUTO_TEST_CASE(sample_maps_with_hostile_values_load_or_are_refused_in_one_line) {
  for (const char* name : {"platform.tmj", "level.ldtk"}) {
    const std::string text = contents(samples / name), path = (samples / name).string();
    int refused = 0, tried = 0;
    for (const auto& [at, length] : json_numbers(text))
      for (const char* value : {"-1", "0", "1e308", "4294967297", "\"nan\"", "null", "[]", "{}"}) {
        const std::string mutated = text.substr(0, at) + value + text.substr(at + length);
        ++tried;
        refused += !map_loads(mutated, path);
      }
    BOOST_TEST(tried > 500, name);
    BOOST_TEST(refused > tried / 4, name << ": " << refused << " of " << tried);  // the values are mostly wrong
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_fuzz_regressions
