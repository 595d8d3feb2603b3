#pragma once
// The fragments as the caller gave them (an array of structs, or strided arrays of doubles or
// floats) and where their forces go, one interface for both entry points of the C API, read and
// written by index. Floats are converted at this boundary, both ways, so everything behind it
// computes in double on one code path. A float widens to double exactly, and a force is rounded to
// the nearest float once, on the way out.

#include <Eigen/Core>
#include <cstdint>
#include <cstring>

#include "fragsim/control.h"

namespace fragsim::control {

// One fragment's numbers, as doubles, in the caller's frame.
struct FragmentIn {
  double position_m[3];
  double velocity_mps[3];
  double radius_m;
  double mass_kg;
};

// The fragments as the caller gave them, an array of structs or strided arrays.
struct StructSource {
  const fragsim_fragment* f;
  void read(std::size_t i, FragmentIn& out) const {
    const fragsim_fragment& g = f[i];
    out.position_m[0] = g.position_m.x;
    out.position_m[1] = g.position_m.y;
    out.position_m[2] = g.position_m.z;
    out.velocity_mps[0] = g.velocity_mps.x;
    out.velocity_mps[1] = g.velocity_mps.y;
    out.velocity_mps[2] = g.velocity_mps.z;
    out.radius_m = g.radius_m;
    out.mass_kg = g.mass_kg;
  }
  std::uint64_t id(std::size_t i) const { return f[i].id; }
  bool touched(std::size_t i) const { return f[i].touched != 0; }
};

// Element i of a strided array, read or written through memcpy, as a stride need not keep the
// type's alignment (an engine's packed struct).
inline const unsigned char* element(const void* base, std::size_t stride, std::size_t i) {
  return static_cast<const unsigned char*>(base) + i * stride;
}
inline unsigned char* element(void* base, std::size_t stride, std::size_t i) {
  return static_cast<unsigned char*>(base) + i * stride;
}

template <class Scalar>
void read_scalars(const void* base, std::size_t stride, std::size_t i, double* out, int n) {
  Scalar v[3];
  std::memcpy(v, element(base, stride, i), static_cast<std::size_t>(n) * sizeof(Scalar));
  for (int k = 0; k < n; ++k) out[k] = static_cast<double>(v[k]);
}

struct ArraySource {
  const fragsim_fragment_arrays* a;
  bool floats;  // scalar_type FLOAT (checked before)
  template <class Scalar>
  void read_as(std::size_t i, FragmentIn& out) const {
    read_scalars<Scalar>(a->position_m, a->position_stride_bytes, i, out.position_m, 3);
    read_scalars<Scalar>(a->velocity_mps, a->velocity_stride_bytes, i, out.velocity_mps, 3);
    read_scalars<Scalar>(a->radius_m, a->radius_stride_bytes, i, &out.radius_m, 1);
    read_scalars<Scalar>(a->mass_kg, a->mass_stride_bytes, i, &out.mass_kg, 1);
  }
  void read(std::size_t i, FragmentIn& out) const {
    if (floats) {
      read_as<float>(i, out);
    } else {
      read_as<double>(i, out);
    }
  }
  std::uint64_t id(std::size_t i) const {
    std::uint64_t v;
    std::memcpy(&v, element(a->id, a->id_stride_bytes, i), sizeof v);
    return v;
  }
  bool touched(std::size_t i) const {
    return a->touched != nullptr && *element(a->touched, a->touched_stride_bytes, i) != 0;
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
  void* base;
  std::size_t stride;
  bool floats;
  template <class Scalar>
  void put(std::size_t i, const Scalar (&v)[3]) const {
    std::memcpy(element(base, stride, i), v, sizeof v);
  }
  void zero(std::size_t n) const {
    if (base == nullptr) return;
    for (std::size_t i = 0; i < n; ++i) {
      if (floats) {
        put(i, {0.0f, 0.0f, 0.0f});
      } else {
        put(i, {0.0, 0.0, 0.0});
      }
    }
  }
  void set(std::size_t i, const Eigen::Vector3d& v) const {
    if (floats) {
      put(i, {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())});
    } else {
      put(i, {v.x(), v.y(), v.z()});
    }
  }
};

}  // namespace fragsim::control
