// Block entity (course: entities/block.ml): a coloured rectangle with a mass.
#pragma once

#include "engine/components.hpp"
#include "engine/world.hpp"

namespace physics::Block {

// The components a block has: the C++ spelling of the OCaml object type
//   object inherit position inherit box inherit color inherit mass
//          inherit velocity inherit sum_forces end
using t = Entity<component::position, component::box, component::color, component::mass,
                 component::velocity, component::sum_forces, component::restitution>;

// Block.make x y w h color mass: creates the block and registers it with every
// system the world declared (Draw, Move, Forces, Collision).
// Expects a valid block (asserted): 0 < size <= max_block_size, a mass > 0 or
// infinity, a finite position, a restitution in [0, 1]. Scenes are checked
// before, by the scene validator (scene/scene.hpp).
t make(World& w, double x, double y, int width, int height, Color color, double mass,
       double restitution = component::restitution::def);

}  // namespace physics::Block
