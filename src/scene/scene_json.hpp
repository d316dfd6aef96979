// Scene files: JSON in, SceneSpec out (and back, for --print-scene).
//
// The format is documented in docs/scenes.md. The reader is strict, since a
// typo must not pass silently: unknown and duplicate keys are errors, every
// value is type-checked here (and an integer must fit its field), its meaning
// (mass > 0, restitution in [0, 1], placement, ...) by the scene validator,
// validate()/expand() in scene.hpp; each error is one line naming the
// file and either the line:column (syntax) or the key path (meaning):
//   scenes/x.json:4:17: invalid JSON: syntax error while parsing object ...
//   scenes/x.json: blocks[3].mass: must be > 0 or "inf" (got -1)
// Part of the physics library (no SDL), so it can be fuzzed on its own: any
// input either gives a valid SceneSpec or throws SceneError, within bounded
// time and memory (see the limits in engine/limits.hpp).
#pragma once

#include <string>
#include <string_view>

#include "scene/scene.hpp"

namespace physics {

// Reads a scene file's text into a SceneSpec: JSON syntax, keys and the types
// of values (what converting JSON needs), not the scene's meaning: that is
// validate()/expand() in scene.hpp, run once by whoever builds the world (the
// command line validates after applying its overrides). `source` names the
// file in messages and gives the default scene name (its file name without
// directory and extension). Throws SceneError.
SceneSpec read_scene(std::string_view text, const std::string& source);
// read_scene, then validated (expand: every check, placement included):
// a SceneSpec it returns builds. Throws SceneError.
SceneSpec parse_scene(std::string_view text, const std::string& source);

// The same from a file (a .tmj or .ldtk map too: is_map_file). Throw
// SceneError (also when it cannot be read).
SceneSpec read_scene_file(const std::string& path);
SceneSpec load_scene_file(const std::string& path);

// The text of the file at `path`, whatever it is (a file, a device, a pipe),
// at most 64 MB: more is refused, read no further than the limit. Throws
// SceneError "path: cannot read the `what`: ..." (no such file, a directory,
// larger than 64 MB, read error). Every input file is read with it.
std::string read_input_file(const std::string& path, const std::string& what);

// A file read_scene_file reads as a map from a level editor, by its name:
// .tmj (Tiled) or .ldtk (LDtk) (map.hpp; docs/scenes.md, "Maps from Tiled and LDtk").
bool is_map_file(std::string_view path);

// The scene as a scene file that parse_scene reads back to the same scene.
std::string to_json(const SceneSpec& s);

// 1-based line and column of the byte at 1-based `position` in `text`, as
// nlohmann's parse errors give it (the count of characters read so far).
struct TextPos {
  std::size_t line = 1, column = 1;
};
TextPos line_column(std::string_view text, std::size_t position);

}  // namespace physics
