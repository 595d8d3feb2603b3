// Every replaceable form of the global operator new and delete, for a test program that must see
// (count, or fail) each allocation a library makes: all of them are defined here, in terms of
// one function the including program defines,
//
//   void* test_allocate(std::size_t size, std::size_t alignment);  // alignment 0: the default
//
// which returns the block or throws std::bad_alloc. Replacing only some forms is a trap: a block
// from a form left to the runtime (or to a sanitizer's) freed by a replaced delete is a mismatch
// (libFuzzer allocates with new (std::nothrow) and frees with delete[]). Blocks come from malloc
// or aligned_alloc, so every delete is free. Include it in one translation unit of the program.
#ifndef FRAGSIM_TESTS_REPLACED_OPERATOR_NEW_HPP
#define FRAGSIM_TESTS_REPLACED_OPERATOR_NEW_HPP

#include <cstddef>
#include <cstdlib>
#include <new>

void* test_allocate(std::size_t size, std::size_t alignment);

// The block test_allocate hands out: malloc's for the default alignment, aligned_alloc's above it
// (whose size must be a multiple of the alignment). Throws std::bad_alloc when the system has none.
inline void* test_system_block(std::size_t size, std::size_t alignment) {
  if (size == 0) size = 1;
  void* p = alignment <= alignof(std::max_align_t)
                ? std::malloc(size)
                : std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

void* operator new(std::size_t n) {
  return test_allocate(n, 0);
}
void* operator new[](std::size_t n) {
  return test_allocate(n, 0);
}
void* operator new(std::size_t n, std::align_val_t a) {
  return test_allocate(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
  return test_allocate(n, static_cast<std::size_t>(a));
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return test_allocate(n, 0);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return test_allocate(n, 0);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  try {
    return test_allocate(n, static_cast<std::size_t>(a));
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  try {
    return test_allocate(n, static_cast<std::size_t>(a));
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  std::free(p);
}

#endif
