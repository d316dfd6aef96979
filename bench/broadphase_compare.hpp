// The broadphase choice, measured: our uniform grid (src/engine/broadphase)
// against a sort-and-sweep with a persistent, incrementally sorted x axis,
// both fed the same boxes taken from bench scenes in motion.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace bench {

// Runs the comparison and returns it as a Markdown section (also what the
// harness prints). Throws if the two ever disagree on the pairs found.
std::string compare_broadphases(const std::vector<std::size_t>& sizes);

}  // namespace bench
