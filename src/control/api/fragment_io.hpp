#pragma once
// The fragments as the caller gave them (an array of structs, or strided arrays) and where their
// forces go: one interface for both entry points of the C API, read and written by index.

#include <Eigen/Core>
#include <cstdint>
#include <cstring>

#include "fragsim/control.h"

namespace fragsim::control {

// The fragments as the caller gave them: an array of structs, or strided arrays.
struct StructSource {
  const fragsim_fragment* f;
  const double* position(std::size_t i) const { return &f[i].position_m.x; }
  const double* velocity(std::size_t i) const { return &f[i].velocity_mps.x; }
  double radius(std::size_t i) const { return f[i].radius_m; }
  double mass(std::size_t i) const { return f[i].mass_kg; }
  std::uint64_t id(std::size_t i) const { return f[i].id; }
  bool touched(std::size_t i) const { return f[i].touched != 0; }
};

struct ArraySource {
  const fragsim_fragment_arrays* a;
  template <class T>
  static const T* at(const T* base, std::size_t stride, std::size_t i) {
    return reinterpret_cast<const T*>(reinterpret_cast<const unsigned char*>(base) + i * stride);
  }
  const double* position(std::size_t i) const {
    return at(a->position_m, a->position_stride_bytes, i);
  }
  const double* velocity(std::size_t i) const {
    return at(a->velocity_mps, a->velocity_stride_bytes, i);
  }
  double radius(std::size_t i) const { return *at(a->radius_m, a->radius_stride_bytes, i); }
  double mass(std::size_t i) const { return *at(a->mass_kg, a->mass_stride_bytes, i); }
  std::uint64_t id(std::size_t i) const { return *at(a->id, a->id_stride_bytes, i); }
  bool touched(std::size_t i) const {
    return a->touched != nullptr && *at(a->touched, a->touched_stride_bytes, i) != 0;
  }
};

// Where the forces go.
struct StructSink {
  fragsim_vec3* f;
  void zero(std::size_t n) const {
    if (f != nullptr && n > 0) std::memset(static_cast<void*>(f), 0, n * sizeof(fragsim_vec3));
  }
  void set(std::size_t i, const Eigen::Vector3d& v) const { f[i] = {v.x(), v.y(), v.z()}; }
};

struct ArraySink {
  double* base;
  std::size_t stride;
  double* at(std::size_t i) const {
    return reinterpret_cast<double*>(reinterpret_cast<unsigned char*>(base) + i * stride);
  }
  void zero(std::size_t n) const {
    if (base == nullptr) return;
    for (std::size_t i = 0; i < n; ++i) {
      double* p = at(i);
      p[0] = p[1] = p[2] = 0.0;
    }
  }
  void set(std::size_t i, const Eigen::Vector3d& v) const {
    double* p = at(i);
    p[0] = v.x();
    p[1] = v.y();
    p[2] = v.z();
  }
};

}  // namespace fragsim::control
