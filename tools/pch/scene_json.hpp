// Precompiled for the scene files that read or write JSON (Makefile,
// JSON_PCH): nlohmann/json, as json_reader.hpp configures it, and
// course/game.hpp through scene/scene.hpp.
#include "scene/json_reader.hpp"
