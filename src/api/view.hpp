// Internals, opt-in (as Chipmunk's chipmunk_private.h): the public API on a
// World its caller owns, for this repository's upper layers (the games run
// on the testbed's world through it). Not installed: a game maker's program
// owns its worlds through create_world.
#pragma once

#include "engine/world.hpp"
#include "physics/physics.hpp"

namespace physics::api {

// A WorldId naming `w` while the View lives: every call of the public API
// works on it as on a world of create_world (bodies made outside the API get
// ids too, of generation 1). `w` must outlive the View and not move.
class View {
 public:
  explicit View(World& w);
  ~View();
  View(const View&) = delete;
  View& operator=(const View&) = delete;
  WorldId id() const { return id_; }
  // The same id for `w` from now on: the viewed world moved into its place
  // (the testbed builds a level's world aside, then moves it in); throws
  // Error if `w` does not hold as many bodies.
  void rebind(World& w);

 private:
  WorldId id_;
};

// The engine's World behind an id (throws Error for a bad id).
World& internal(WorldId id);
// The body id of entity e of the world behind `world`.
BodyId body_id(WorldId world, EntityId e);
// The entity behind a body id (throws Error for a bad id).
EntityId entity(BodyId body);

}  // namespace physics::api
