// The WebAssembly module (make web): the testbed, the scenes and the games
// behind a few exported functions, for the page (web/front.js) and for the
// checks under Node's WASI (web/test/node_check.mjs). A WASI reactor: no
// main; the host calls _initialize, then these. Strings cross as
// NUL-terminated UTF-8 in the module's memory (web_alloc).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#include "app/dump.hpp"
#include "app/headless.hpp"
#include "app/input_log.hpp"
#include "app/testbed.hpp"
#include "determinism_world.hpp"
#include "draw_commands.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/scene_json.hpp"

#define WEB_EXPORT(name) __attribute__((export_name(#name)))

using namespace physics;

namespace {

// The testbed's scenes as the window has them (app/cli.cpp, testbed_scenes):
// the built-ins, and a scene file as the ninth; `current` is `name`'s.
std::vector<SceneSpec> scenes_for(const std::string& name, std::size_t& current) {
  std::vector<SceneSpec> scenes(builtin_scenes().begin(), builtin_scenes().end());
  current = scenes.size();
  for (std::size_t i = 0; i < scenes.size(); ++i)
    if (scenes[i].name == name) current = i;
  if (current == scenes.size()) scenes.push_back(load_scene_file(name));
  return scenes;
}

// Text to stdout: no iostreams in the module (their locale machinery was a
// quarter of it, docs/web.md).
void print(const std::string& text) { std::fwrite(text.data(), 1, text.size(), stdout); }

std::string hex(std::uint64_t h) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%016llx", static_cast<unsigned long long>(h));
  return buf;
}

// A log played on `scene`'s testbed, headless (app/cli.cpp, replay_run),
// and what it printed: ticks, the game's outcome, the state hash, the dump.
int play_log(const InputLog& log, const std::string& scene) {
  std::size_t current = 0;
  Testbed tb(scenes_for(scene, current), current);
  tb.replay(log);
  tb.play();
  print("replay: " + std::to_string(tb.replayed()) + " events over " + std::to_string(tb.ticks()) +
        " ticks, ended at frame " + std::to_string(tb.world().frame) + "\n");
  if (tb.level()) print(std::string("game: ") + (tb.outcome() == Level::Outcome::won ? "won" : "not won") + "\n");
  print("state " + hex(determinism::state_hash(tb.world().components)) + "\n");
  print(Dump::state(tb.world()));
  std::fflush(stdout);
  return 0;
}

// An export's work, its error (a scene or log that does not read) as the
// command line gives it: one line on stderr, and 2.
template <class F>
int guarded(F&& f) {
  try {
    return f();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "game: %s\n", e.what());
    std::fflush(stderr);
    return 2;
  }
}

struct Page {
  std::unique_ptr<Testbed> tb;
  web::Commands commands;
  std::string state;
};
Page page;

}  // namespace

extern "C" {

WEB_EXPORT(web_alloc) char* web_alloc(int n) { return static_cast<char*>(std::malloc(static_cast<std::size_t>(n))); }
WEB_EXPORT(web_free) void web_free(char* p) { std::free(p); }

// The determinism check: each mode's gas and pyramid hash, then the course
// solver's gas after 1 000 frames (tests/test_determinism.cpp has the
// committed values), one line each: "NAME gas 0x... pyramid 0x...".
WEB_EXPORT(web_determinism) int web_determinism() {
  using namespace physics::determinism;
  for (const Mode& m : modes) {
    World gas = thousand_bodies(m.params());
    for (int f = 0; f < gas_frames; ++f) Game::step(gas);
    World pile = pyramid(m.params(), pyramid_base);
    for (int f = 0; f < pyramid_frames; ++f) Game::step(pile);
    std::printf("%s gas %s pyramid %s\n", m.name, hex(state_hash(gas.components)).c_str(),
                hex(state_hash(pile.components)).c_str());
  }
  World w = thousand_bodies();
  for (int f = 0; f < long_frames; ++f) Game::step(w);
  std::printf("long %s\n", hex(state_hash(w.components)).c_str());
  std::fflush(stdout);  // a reactor's stdio is flushed by no exit
  return 0;
}

// `build/game --replay LOG --headless`'s run (app/cli.cpp, replay_run): the
// log's scene, its events at their ticks; prints the ticks, the game's line,
// the final state's hash and its dump (Dump::write_state, as --dump writes).
WEB_EXPORT(web_replay) int web_replay(const char* log_path) {
  return guarded([&] {
    const InputLog log = read_input_log(log_path);
    return play_log(log, log.scene);
  });
}

// `build/game --scene NAME --headless --frames N`'s run and summary
// (Headless::run, print_summary: the bench's measure, physics ms/step), then
// the final state's dump (as --dump writes it).
WEB_EXPORT(web_headless) int web_headless(const char* name, int frames) {
  return guarded([&] {
    const SceneSpec* builtin = find_builtin(name);
    const SceneSpec spec = builtin ? *builtin : load_scene_file(name);
    if (!spec.game.kind.empty()) {  // a game's level runs in its testbed, with no input (as natively)
      InputLog idle;
      idle.end = frames;
      return play_log(idle, name);
    }
    World w = make_world(spec, false);
    const Headless::Summary s = Headless::run(w, frames);
    print(Headless::summary(w, s, "the web build's headless run", spec.name));
    print(Dump::state(w));
    std::fflush(stdout);
    return 0;
  });
}

// The built-in scenes' names, one a line, in the order of the keys 1-8.
WEB_EXPORT(web_builtins) const char* web_builtins() {
  static const std::string names = [] {
    std::string out;
    for (const SceneSpec& s : builtin_scenes()) out += s.name + "\n";
    return out;
  }();
  return names.c_str();
}

// The page's testbed on scene `name` (a built-in's name or a scene file);
// one that does not read leaves the testbed as it was (2, the error on stderr).
WEB_EXPORT(web_open) int web_open(const char* name) {
  return guarded([&] {
    std::size_t current = 0;
    std::vector<SceneSpec> scenes = scenes_for(name, current);
    page.tb = std::make_unique<Testbed>(std::move(scenes), current);
    return 0;
  });
}

// An input event (InputEvent::Kind's order); 1 when it asks to quit.
WEB_EXPORT(web_event) int web_event(int kind, int key, int x, int y, int button) {
  const InputEvent e{static_cast<InputEvent::Kind>(kind), key, x, y, button};
  return page.tb->live(e) == Testbed::Action::quit ? 1 : 0;
}

// Real time passed, ms: the fixed steps it covers (Testbed::advance).
WEB_EXPORT(web_advance) int web_advance(double elapsed_ms) { return page.tb->advance(elapsed_ms); }

// The frame's drawing commands (web/draw_commands.hpp): their floats' count.
WEB_EXPORT(web_draw) int web_draw(double fps, double draw_ms) {
  web::render(page.tb->world(), page.tb->view(fps, draw_ms), page.commands);
  return static_cast<int>(page.commands.ops().size());
}
WEB_EXPORT(web_ops) const float* web_ops() { return page.commands.ops().data(); }
WEB_EXPORT(web_texts) const char* web_texts() { return page.commands.texts().c_str(); }

// What the page reads back, as JSON: scene, size, frame, ticks, paused,
// bodies, the state hash, a game's outcome and HUD message.
WEB_EXPORT(web_state) const char* web_state() {
  const Testbed& tb = *page.tb;
  const World& w = tb.world();
  const char* outcome = tb.outcome() == Level::Outcome::won    ? "won"
                        : tb.outcome() == Level::Outcome::lost ? "lost"
                                                               : "playing";
  std::size_t alive = 0;
  for (std::size_t e = 0; e < w.components.size(); ++e) alive += w.alive(static_cast<EntityId>(e));
  using std::to_string;
  page.state = "{\"scene\":\"" + tb.scene().name + "\",\"index\":" + to_string(tb.current()) +
               ",\"width\":" + to_string(tb.scene().width) + ",\"height\":" + to_string(tb.scene().height) +
               ",\"frame\":" + to_string(w.frame) + ",\"ticks\":" + to_string(tb.ticks()) +
               ",\"paused\":" + (tb.paused() ? "true" : "false") + ",\"bodies\":" + to_string(alive) +
               ",\"hash\":\"" + hex(determinism::state_hash(w.components)) + "\",\"game\":" +
               (tb.level() ? "true" : "false") + ",\"outcome\":\"" + outcome + "\"}";
  return page.state.c_str();
}

}
