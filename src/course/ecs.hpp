// The small ECS the course builds on (the archive's ECS library): typed
// entities Entity<Components...>, systems System<Required...> with
// `register` and `unregister`, entity ids. It lives in the engine
// (engine/ecs.hpp), below the course's systems and entities, so that the
// course tree and the engine depend one way (tools/check_layers.py).
#pragma once

#include "engine/ecs.hpp"
