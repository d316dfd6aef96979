// The engines of build/bench: ours and Debian's Box2D 2.4.1 and Chipmunk.
#include "bench.hpp"

namespace bench {

const std::vector<std::string>& engine_names() {
  static const std::vector<std::string> names{"ours", "ours-2t", "ours-course", "box2d", "chipmunk"};
  return names;
}

std::unique_ptr<Engine> make_engine(const std::string& name, const Scene& s) {
  if (name == "ours") return make_ours(s);
  if (name == "ours-2t") return make_ours(s, false, 2);
  if (name == "ours-course") return make_ours(s, true);
  if (name == "box2d") return make_box2d(s);
  if (name == "chipmunk") return make_chipmunk(s);
  return nullptr;
}

}  // namespace bench
