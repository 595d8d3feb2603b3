#include "control/api/hook_resource.hpp"

#include <new>

namespace fragsim::control {

void* HookResource::allocate(std::size_t bytes, std::size_t alignment) {
  if (alloc_ == nullptr) return default_memory_resource()->allocate(bytes, alignment);
  void* p = alloc_(bytes, alignment, user_);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

void HookResource::deallocate(void* p, std::size_t bytes, std::size_t alignment) {
  if (free_ == nullptr) {
    default_memory_resource()->deallocate(p, bytes, alignment);
    return;
  }
  free_(p, bytes, alignment, user_);
}

}  // namespace fragsim::control
