// Shared by the test files that drive the command line: Cli::run in this
// process, or the real program (build/game) in a scratch directory.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "helpers.hpp"

namespace physics::test {

struct Ran {
  int code;
  std::string out, err;
};

// Cli::run, as main() calls it, with no window front end.
inline Ran cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = Cli::run(args, out, err, nullptr);
  return {code, out.str(), err.str()};
}

// Bad input: exit code 2 and exactly one line on stderr, "game: ...", containing `part`.
inline void expect_bad(const std::vector<std::string>& args, const std::string& part) {
  const Ran r = cli(args);
  BOOST_TEST(r.code == 2);
  BOOST_TEST(has(r.err, part), "'" << part << "' in: " << r.err);
  BOOST_TEST(r.err.rfind("game: ", 0) == 0u);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  BOOST_TEST(r.out.empty());
}

// A scratch directory, removed at the end of the test.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    static int counter = 0;
    path = std::filesystem::temp_directory_path() /
           ("physics-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name, const std::string& text = "") const {
    const auto p = path / name;
    if (!text.empty()) std::ofstream(p) << text;
    return p.string();
  }
};

// The repository's folders, absolute: tests may run elsewhere.
inline std::filesystem::path repo_root() { return std::filesystem::absolute(__FILE__).parent_path().parent_path(); }
// A scene file of scenes/, or else a Tiled map of scenes/maps/ (the platformer's levels).
inline std::string scene_path(const std::string& name) {
  const auto file = repo_root() / "scenes" / (name + ".json"), map = repo_root() / "scenes" / "maps" / (name + ".tmj");
  return (std::filesystem::exists(file) || !std::filesystem::exists(map) ? file : map).string();
}
inline std::string replay_path(const std::string& name) { return (repo_root() / "replays" / (name + ".log")).string(); }

inline std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The real program, next to this test binary.
inline std::string game_binary() {
  return (std::filesystem::read_symlink("/proc/self/exe").parent_path() / "game").string();
}

inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// env's options that take the display away (SDL then has no window to open).
inline const std::string no_display = "-u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER";

// Runs build/game with `env` (e.g. no_display + " SDL_VIDEODRIVER=dummy") in dir.
inline Ran program(const TempDir& dir, const std::string& env, const std::vector<std::string>& args) {
  std::string cmd = "cd " + quote(dir.path.string()) + " && env " + env + " " + quote(game_binary());
  for (const std::string& a : args) cmd += " " + quote(a);
  cmd += " >" + quote(dir.file("stdout")) + " 2>" + quote(dir.file("stderr")) + " </dev/null";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read(dir.file("stdout")), read(dir.file("stderr"))};
}

}  // namespace physics::test
