// Components (course: component_defs.ml): position, box and color, and the
// ones the sheet adds (Q2): mass (default 0.0; infinity for walls),
// velocity and sum_forces (default the zero vector); beyond the sheet,
// restitution, friction and the contact rules.
//
// Each is a tag naming the property and its default value
// (component::position::def, ...), and the values live in the engine's dense
// storage, one array per component indexed by entity id: both are in
// engine/components.hpp, so that the engine, the course's systems and its
// entities read the same arrays while depending one way (tools/check_layers.py).
#pragma once

#include "engine/components.hpp"
