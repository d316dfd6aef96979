// The layering checker itself (tools/check_layers.py, `make layers`): on a
// scratch tree it must refuse a wrong-way include, a folder cycle and a file
// cycle, naming the files and the include, accept a tree that goes one way,
// and keep its table of known violations true: each listed one is printed
// and passes, a listed one that is gone fails, a new one fails.
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "helpers.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_layers {

namespace fs = std::filesystem;

namespace {

struct Checked {
  int code;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A scratch tree holding `files` (paths relative to the tree's root: src/...,
// include/...), checked with `known` as the table of known violations.
Checked check(const std::vector<std::pair<std::string, std::string>>& files, const std::string& known = "") {
  static int counter = 0;
  const fs::path dir = fs::temp_directory_path() / ("physics-layers-" + std::to_string(::getpid()) + "-" +
                                                    std::to_string(counter++));
  fs::create_directories(dir / "src");
  for (const auto& [path, text] : files) {
    fs::create_directories((dir / path).parent_path());
    std::ofstream(dir / path) << text;
  }
  std::ofstream(dir / "known") << known;
  const fs::path script = fs::absolute(fs::path(__FILE__).parent_path().parent_path() / "tools" / "check_layers.py");
  const std::string cmd = "python3 '" + script.string() + "' '" + (dir / "src").string() + "' --known '" +
                          (dir / "known").string() + "' >'" + (dir / "out").string() + "' 2>'" +
                          (dir / "err").string() + "'";
  const int status = std::system(cmd.c_str());
  Checked c{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "out"), slurp(dir / "err")};
  std::error_code ec;
  fs::remove_all(dir, ec);
  return c;
}

using physics::test::has;

}  // namespace

BOOST_AUTO_TEST_SUITE(layers_check)

// The course's value types < the engine < the course's systems < its entities
// < its root files < the scene < the games < the app, and the public header
// at the bottom (standard headers only).
const std::vector<std::pair<std::string, std::string>> one_way = {
    {"include/physics/math.hpp", "#include <vector>\n"},
    {"src/course/utils/vect.hpp", ""},
    {"src/course/utils/rect.hpp", "#include \"course/utils/vect.hpp\"\n"},
    {"src/engine/components.hpp", "#include \"course/utils/rect.hpp\"\n#include <vector>\n"},
    {"src/engine/pairs.hpp", "#include \"components.hpp\"\n"},
    {"src/engine/world.hpp", "#include \"engine/pairs.hpp\"\n"},
    {"src/course/systems/collision.hpp", "#include \"engine/pairs.hpp\"\n"},
    {"src/course/entities/block.hpp", "#include \"engine/world.hpp\"\n"},
    {"src/course/system_defs.hpp", "#include \"course/systems/collision.hpp\"\n"},
    {"src/course/game.hpp", "#include \"system_defs.hpp\"\n#include \"course/entities/block.hpp\"\n"},
    {"src/scene/scene.hpp", "#include \"course/game.hpp\"\n"},
    {"src/games/level.hpp", "#include \"scene/scene.hpp\"\n#include \"physics/math.hpp\"\n"},
    {"src/app/cli.cpp", "#include \"games/level.hpp\"\n#include \"cli.hpp\"\n"},
    {"src/app/cli.hpp", ""}};

std::vector<std::pair<std::string, std::string>> with(std::vector<std::pair<std::string, std::string>> files,
                                                      const std::string& path, const std::string& text) {
  files.emplace_back(path, text);
  return files;
}

BOOST_AUTO_TEST_CASE(a_tree_that_goes_one_way_passes) {
  const Checked c = check(one_way);
  BOOST_TEST(c.code == 0);
  BOOST_TEST(c.err.empty());
  BOOST_TEST(!has(c.out, "known"));
}

BOOST_AUTO_TEST_CASE(a_wrong_way_include_fails_naming_the_file_and_the_include) {
  const Checked c = check({{"src/course/utils/vect.hpp", ""},
                           {"src/engine/world.hpp", "#include \"course/utils/vect.hpp\"\n\n#include \"scene/scene.hpp\"\n"},
                           {"src/scene/scene.hpp", ""}});
  BOOST_TEST(c.code == 1);
  BOOST_TEST(has(c.err, "src/engine/world.hpp:3: #include \"scene/scene.hpp\" goes the wrong way"));
  BOOST_TEST(has(c.err, "engine is level"));
}

BOOST_AUTO_TEST_CASE(the_public_header_may_include_only_standard_headers_and_itself) {
  const Checked c = check(with(one_way, "include/physics/physics.hpp",
                               "#include <vector>\n#include \"math.hpp\"\n#include \"engine/world.hpp\"\n"));
  BOOST_TEST(c.code == 1);
  BOOST_TEST(has(c.err, "include/physics/physics.hpp:3: #include \"engine/world.hpp\" goes the wrong way"));
  BOOST_TEST(!has(c.err, "physics.hpp:2"));
}

BOOST_AUTO_TEST_CASE(a_game_may_not_include_the_course_even_below_it) {
  const Checked c = check(with(one_way, "src/games/targets.cpp", "#include \"course/entities/block.hpp\"\n"));
  BOOST_TEST(c.code == 1);
  BOOST_TEST(has(c.err, "src/games/targets.cpp:1: #include \"course/entities/block.hpp\" goes the wrong way: "
                        "games may include only"));
}

BOOST_AUTO_TEST_CASE(a_folder_cycle_fails_even_through_a_third_folder) {
  // No file cycle: scene -> course/entities and course/entities -> engine are
  // fine, engine -> scene closes the cycle between folders only.
  const Checked c = check({{"src/engine/a.hpp", "#include \"scene/b.hpp\"\n"},
                           {"src/scene/b.hpp", ""},
                           {"src/scene/c.hpp", "#include \"course/entities/d.hpp\"\n"},
                           {"src/course/entities/d.hpp", "#include \"engine/e.hpp\"\n"},
                           {"src/engine/e.hpp", ""}});
  BOOST_TEST(c.code == 1);
  BOOST_TEST(has(c.err, "folder cycle: course/entities -> engine -> scene -> course/entities"));
  BOOST_TEST(has(c.err, "src/engine/a.hpp:1 includes src/scene/b.hpp"));
  BOOST_TEST(!has(c.err, "include cycle"));
}

BOOST_AUTO_TEST_CASE(an_include_cycle_fails_even_within_one_folder) {
  const Checked c = check({{"src/engine/a.hpp", "#include \"engine/b.hpp\"\n"},
                           {"src/engine/b.hpp", "#include \"c.hpp\"\n"},
                           {"src/engine/c.hpp", "#include \"engine/a.hpp\"\n"}});
  BOOST_TEST(c.code == 1);
  BOOST_TEST(has(c.err, "include cycle: src/engine/a.hpp -> src/engine/b.hpp -> src/engine/c.hpp -> src/engine/a.hpp"));
  BOOST_TEST(!has(c.err, "folder cycle"));
}

BOOST_AUTO_TEST_CASE(a_file_outside_every_level_fails) {
  const Checked c = check({{"src/physics/new.hpp", ""}});
  BOOST_TEST(c.code == 1);
  BOOST_TEST(has(c.err, "src/physics/new.hpp: has no level"));
}

// A tree with the engine's World on the course's systems, as today.
const std::vector<std::pair<std::string, std::string>> engine_on_course =
    with(one_way, "src/engine/stages.hpp", "#include \"course/system_defs.hpp\"\n");
const std::string listed = "# the table\nsrc/engine/stages.hpp -> src/course/system_defs.hpp: World holds the Systems\n";

BOOST_AUTO_TEST_CASE(a_known_violation_is_printed_and_passes_with_its_cycle) {
  BOOST_TEST(check(engine_on_course).code == 1);  // not listed: fails
  const Checked c = check(engine_on_course, listed);
  BOOST_TEST(c.code == 0);
  BOOST_TEST(c.err.empty());
  BOOST_TEST(has(c.out, "known: src/engine/stages.hpp -> src/course/system_defs.hpp (engine is level"));
  BOOST_TEST(has(c.out, "World holds the Systems"));
  BOOST_TEST(has(c.out, "known folder cycle: course -> course/entities -> engine -> course"));
}

BOOST_AUTO_TEST_CASE(a_known_violation_that_is_gone_fails) {
  const Checked c = check(one_way, listed);
  BOOST_TEST(c.code == 1);
  BOOST_TEST(has(c.err, "known violation src/engine/stages.hpp -> src/course/system_defs.hpp is no longer found"));
}

BOOST_AUTO_TEST_CASE(a_new_violation_beside_a_known_one_fails) {
  const Checked c = check(with(engine_on_course, "src/engine/draw.hpp", "#include \"course/systems/collision.hpp\"\n"),
                          listed);
  BOOST_TEST(c.code == 1);
  BOOST_TEST(has(c.err, "src/engine/draw.hpp:1: #include \"course/systems/collision.hpp\" goes the wrong way"));
  BOOST_TEST(has(c.out, "known: src/engine/stages.hpp"));
}

// The project's own tree, as `make layers` checks it, with the table of the script.
BOOST_AUTO_TEST_CASE(the_real_tree_passes) {
  const fs::path script = fs::absolute(fs::path(__FILE__).parent_path().parent_path() / "tools" / "check_layers.py");
  const fs::path out = fs::temp_directory_path() / ("physics-layers-real-" + std::to_string(::getpid()));
  const int status = std::system(("python3 '" + script.string() + "' >'" + out.string() + "' 2>&1").c_str());
  const std::string text = slurp(out);
  std::error_code ec;
  fs::remove(out, ec);
  BOOST_TEST((WIFEXITED(status) && WEXITSTATUS(status) == 0), text);
  BOOST_TEST(has(text, "levels: none goes the wrong way"));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_layers
