// The components' storage is the engine's (engine/components.cpp): see
// course/component_defs.hpp. This file stays so that the course tree reads
// like the archive's (component_defs.ml).
#include "course/component_defs.hpp"
