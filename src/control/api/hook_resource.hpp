#pragma once
// The allocator hook of fragsim_controller_def (alloc_fn, free_fn, alloc_user) as a MemoryResource,
// so every container a controller owns (its id tables, its work arrays, its strategy's vectors)
// allocates through the game's hook, and the strategies, which the tool runs with the default
// resource, need no second code path.
//
// Without a hook it is the default resource (memory/memory_resource.hpp), the C++ runtime's
// operator new and delete, so a program that replaces operator new sees every allocation of a
// hookless controller.

#include <cstddef>

#include "control/memory/memory_resource.hpp"
#include "fragsim/control.h"

namespace fragsim::control {

class HookResource final : public MemoryResource {
 public:
  // alloc_fn and free_fn both set, or both NULL (the runtime's new and delete); a def with one of
  // them only is refused before this is built.
  explicit HookResource(const fragsim_controller_def& def)
      : alloc_(def.alloc_fn), free_(def.free_fn), user_(def.alloc_user) {}
  bool hooked() const { return alloc_ != nullptr; }

  // Throws std::bad_alloc when the hook returns NULL, the containers' own way of failing, which the
  // controller's two-phase step already turns into FRAGSIM_ERROR_OUT_OF_MEMORY.
  void* allocate(std::size_t bytes, std::size_t alignment) override;
  void deallocate(void* p, std::size_t bytes, std::size_t alignment) override;

 private:
  void* (*alloc_)(size_t, size_t, void*);
  void (*free_)(void*, size_t, size_t, void*);
  void* user_;
};

}  // namespace fragsim::control
