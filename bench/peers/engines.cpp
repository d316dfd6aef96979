// The engines of build/bench-peers: the peers built from source by
// `make bench PEERS=DIR` (see the Makefile for why they have a binary of their own).
#include "../bench.hpp"

namespace bench {

const std::vector<std::string>& engine_names() {
  static const std::vector<std::string> names{"box2d3", "box2d3-2t", "chipmunk-release"};
  return names;
}

std::unique_ptr<Engine> make_engine(const std::string& name, const Scene& s) {
  if (name == "box2d3") return make_box2d3(s);
  if (name == "box2d3-2t") return make_box2d3(s, 2);  // its own scheduler on two threads
  if (name == "chipmunk-release") return make_chipmunk(s);  // bench/engine_chipmunk.cpp against the release build
  return nullptr;
}

}  // namespace bench
