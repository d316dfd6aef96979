// The layering checker itself (tools/check_layers.py, `make layers`): on a
// scratch tree it must refuse a wrong-way include and an include cycle,
// naming the file and the include, and accept a tree that goes one way.
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "helpers.hpp"

namespace fs = std::filesystem;

namespace {

struct Checked {
  int code;
  std::string err;
};

// A scratch src/ holding `files` (path relative to src/, text), checked.
Checked check(const std::vector<std::pair<std::string, std::string>>& files) {
  static int counter = 0;
  const fs::path dir = fs::temp_directory_path() / ("physics-layers-" + std::to_string(::getpid()) + "-" +
                                                    std::to_string(counter++));
  for (const auto& [path, text] : files) {
    fs::create_directories((dir / "src" / path).parent_path());
    std::ofstream(dir / "src" / path) << text;
  }
  const fs::path script = fs::absolute(fs::path(__FILE__).parent_path().parent_path() / "tools" / "check_layers.py");
  const std::string cmd = "python3 '" + script.string() + "' '" + (dir / "src").string() + "' >/dev/null 2>'" +
                          (dir / "err").string() + "'";
  const int status = std::system(cmd.c_str());
  std::ifstream in(dir / "err");
  std::stringstream err;
  err << in.rdbuf();
  std::error_code ec;
  fs::remove_all(dir, ec);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, err.str()};
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

BOOST_AUTO_TEST_SUITE(layers_check)

BOOST_AUTO_TEST_CASE(a_tree_that_goes_one_way_passes) {
  const Checked c = check({{"course/utils/vect.hpp", ""},
                           {"course/utils/rect.hpp", "#include \"course/utils/vect.hpp\"\n"},
                           {"course/component_defs.hpp", "#include \"course/utils/rect.hpp\"\n#include <vector>\n"},
                           {"engine/world.hpp", "#include \"component_defs.hpp\"\n#include \"system_defs.hpp\"\n"},
                           {"course/system_defs.hpp", "#include \"course/systems/move.hpp\"\n"},
                           {"course/systems/move.hpp", "#include \"engine/pairs.hpp\"\n"},
                           {"engine/pairs.hpp", ""},
                           {"course/game.hpp", "#include \"engine/world.hpp\"\n"},
                           {"app/cli.cpp", "#include \"game.hpp\"\n#include \"cli.hpp\"\n"},
                           {"app/cli.hpp", ""}});
  BOOST_TEST(c.code == 0);
  BOOST_TEST(c.err.empty());
}

BOOST_AUTO_TEST_CASE(a_wrong_way_include_fails_naming_the_file_and_the_include) {
  const Checked c = check({{"course/utils/vect.hpp", ""},
                           {"engine/world.hpp", "#include \"course/utils/vect.hpp\"\n\n#include \"scene/scene.hpp\"\n"},
                           {"scene/scene.hpp", "#include \"engine/world.hpp\"\n"}});
  BOOST_TEST(c.code == 1);
  BOOST_TEST(has(c.err, "engine/world.hpp:3"));
  BOOST_TEST(has(c.err, "#include \"scene/scene.hpp\" goes the wrong way"));
}

BOOST_AUTO_TEST_CASE(an_include_cycle_fails_even_within_one_level) {
  const Checked c = check({{"engine/a.hpp", "#include \"engine/b.hpp\"\n"},
                           {"engine/b.hpp", "#include \"c.hpp\"\n"},
                           {"engine/c.hpp", "#include \"engine/a.hpp\"\n"}});
  BOOST_TEST(c.code == 1);
  BOOST_TEST(has(c.err, "include cycle: engine/a.hpp -> engine/b.hpp -> engine/c.hpp -> engine/a.hpp"));
}

BOOST_AUTO_TEST_CASE(a_file_outside_every_level_fails) {
  const Checked c = check({{"physics/new.hpp", ""}});
  BOOST_TEST(c.code == 1);
  BOOST_TEST(has(c.err, "physics/new.hpp: has no level"));
}

BOOST_AUTO_TEST_SUITE_END()
