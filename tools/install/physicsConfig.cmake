# CMake package of the physics engine (installed by `make install PREFIX=DIR`):
#   find_package(physics REQUIRED)     # CMAKE_PREFIX_PATH=DIR, or physics_DIR=DIR/lib/cmake/physics
#   target_link_libraries(app PRIVATE physics::physics)
# The target carries the include folder and C++20. Relocatable: paths are
# found from this file's place, DIR/lib/cmake/physics.
get_filename_component(_physics_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET physics::physics)
  add_library(physics::physics STATIC IMPORTED)
  set_target_properties(physics::physics PROPERTIES
    IMPORTED_LOCATION "${_physics_prefix}/lib/libphysics.a"
    INTERFACE_INCLUDE_DIRECTORIES "${_physics_prefix}/include"
    INTERFACE_COMPILE_FEATURES cxx_std_20)
endif()
unset(_physics_prefix)
