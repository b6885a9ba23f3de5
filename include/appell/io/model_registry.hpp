// appell/io/model_registry.hpp -- models added to the registry while a program starts: a model of
// a user's own (or the tests'), its home compiled beside the program by CMake's appell_add_models
// (cmake/instantiate.cmake), which registers it before main.  read_scene then finds it by its name
// as it finds a built-in model, and the motion's calls move it (motion/registry.hpp).
#pragma once

#include "appell/io/scene.hpp"

namespace appell {

/// Adds `entry` after the built-in models (registered_models(), find_model).  Call it before any
/// scene is read, from one thread (the generated registration does, while the program starts);
/// std::logic_error if a model of that name is registered already.  `entry` must outlive the
/// program's use of the registry (the generated registration gives the model's static entry).
void register_model(const model_entry& entry);

}  // namespace appell
