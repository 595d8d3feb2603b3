#pragma once
// The table behind fragsim_controller_id, as Box2D v3's ids, with a slot per live controller and a
// generation per slot, bumped when the controller is destroyed, so an id kept after destroy (or one
// never created) is refused with a status instead of being followed to freed memory.
//
// The library's one global. Creating and destroying take a lock; finding a controller by id takes
// none, as the slots live in chunks that are never moved or freed, and each slot's generation and
// pointer are atomics, so a thread stepping its controller never races another thread creating or
// destroying a different one.

#include <cstdint>

#include "fragsim/control.h"

namespace fragsim::control {

class Controller;

// Stores the controller and returns its id; the null id when every slot is taken
// (FRAGSIM_MAX_CONTROLLERS). Throws std::bad_alloc when a new chunk of slots cannot be made.
fragsim_controller_id add_controller(Controller* controller);

// The live controller of id, or nullptr (null, stale, or never created).
Controller* find_controller(fragsim_controller_id id);

// Takes the controller out of its slot (the caller deletes it); nullptr when id is not live.
Controller* remove_controller(fragsim_controller_id id);

}  // namespace fragsim::control
