#pragma once
// MemoryResource, where the library's containers get their memory, and ResourceVector, a
// std::vector that allocates from one. The controller hands every container it owns its allocator
// hook (api/hook_resource.hpp); the tool and the tests use the default resource, the C++ runtime's
// operator new.
//
// The library's own instead of std::pmr because the WebAssembly toolchain it is built with
// (emscripten 3.1.6, libc++ 14) has no <memory_resource>; the contract is std::pmr's, narrowed
// to what the library uses, so moving between the two changes no allocation.

#include <cstddef>
#include <new>
#include <type_traits>
#include <vector>

namespace fragsim {

class MemoryResource {
 public:
  virtual ~MemoryResource() = default;
  // Throws std::bad_alloc when it has no memory to give, the containers' own way of failing.
  virtual void* allocate(std::size_t bytes, std::size_t alignment) = 0;
  virtual void deallocate(void* p, std::size_t bytes, std::size_t alignment) = 0;
};

// The C++ runtime's operator new and delete, called as a `new T[n]` would (the plain operator for
// alignments it guarantees, the aligned one beyond). A program that replaces operator new sees
// every allocation made through it.
class NewDeleteResource final : public MemoryResource {
 public:
  void* allocate(std::size_t bytes, std::size_t alignment) override {
    if (alignment <= __STDCPP_DEFAULT_NEW_ALIGNMENT__) return ::operator new(bytes);
    return ::operator new(bytes, std::align_val_t(alignment));
  }
  void deallocate(void* p, std::size_t bytes, std::size_t alignment) override {
    (void)bytes;
    if (alignment <= __STDCPP_DEFAULT_NEW_ALIGNMENT__) {
      ::operator delete(p);
    } else {
      ::operator delete(p, std::align_val_t(alignment));
    }
  }
};

inline MemoryResource* default_memory_resource() {
  static NewDeleteResource resource;
  return &resource;
}

// A standard allocator over a MemoryResource. Like std::pmr::polymorphic_allocator, it is not
// propagated by a container's assignment or swap (an assigned vector keeps its own resource), so
// a controller's containers never hold memory of another resource; unlike it, a copy-constructed
// container keeps the resource of the one it copies rather than falling back to the default.
template <class T>
class ResourceAllocator {
 public:
  using value_type = T;
  using propagate_on_container_copy_assignment = std::false_type;
  using propagate_on_container_move_assignment = std::false_type;
  using propagate_on_container_swap = std::false_type;
  using is_always_equal = std::false_type;

  // Implicit, as polymorphic_allocator's, so a container is built from a resource pointer.
  ResourceAllocator(MemoryResource* resource = default_memory_resource()) noexcept  // NOLINT
      : resource_(resource) {}
  template <class U>
  ResourceAllocator(const ResourceAllocator<U>& other) noexcept  // NOLINT
      : resource_(other.resource()) {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(resource_->allocate(n * sizeof(T), alignof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    resource_->deallocate(p, n * sizeof(T), alignof(T));
  }
  MemoryResource* resource() const noexcept { return resource_; }

  template <class U>
  bool operator==(const ResourceAllocator<U>& other) const noexcept {
    return resource_ == other.resource();
  }

 private:
  MemoryResource* resource_;
};

template <class T>
using ResourceVector = std::vector<T, ResourceAllocator<T>>;

}  // namespace fragsim
