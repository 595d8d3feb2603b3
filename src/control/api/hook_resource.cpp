#include "api/hook_resource.hpp"

#include <new>

namespace fragsim::control {

void* HookResource::do_allocate(std::size_t bytes, std::size_t alignment) {
  if (alloc_ == nullptr) {
    if (alignment <= __STDCPP_DEFAULT_NEW_ALIGNMENT__) return ::operator new(bytes);
    return ::operator new(bytes, std::align_val_t(alignment));
  }
  void* p = alloc_(bytes, alignment, user_);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

void HookResource::do_deallocate(void* p, std::size_t bytes, std::size_t alignment) {
  if (free_ == nullptr) {
    if (alignment <= __STDCPP_DEFAULT_NEW_ALIGNMENT__) {
      ::operator delete(p);
    } else {
      ::operator delete(p, std::align_val_t(alignment));
    }
    return;
  }
  free_(p, bytes, alignment, user_);
}

}  // namespace fragsim::control
