#pragma once
// The operations of the batched passes, written once for two widths, two lanes (SSE2, lanes.hpp,
// the x86-64 baseline) and, where the processor has AVX2, four, through GCC's vector extension in
// functions compiled for AVX2 (chosen at run time with has_wide_lanes()). Templates over NarrowOps
// and WideOps perform the same IEEE operations in the same order at either width (no FMA, given
// -ffp-contract=off, and "avx2" does not enable it), so they give the same answers, bit for bit.
// Used by edge-min's rejection (two_box_clearance.cpp) and its exact solve's slab times
// (slab_times.cpp).
//
// WideOps exists only where FRAGSIM_WIDE_LANES is defined, GCC on x86-64 (Clang refuses AVX vectors
// outside AVX code even where they are inlined into it; it builds only the fuzzers here). An
// includer keeps -Wpsabi off to its end, as the four-lane type only ever lives in AVX2 code and the
// templates are instantiated in the including file.

#include <cstdint>
#include <cstring>

#include "control/strategies/lanes.hpp"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define FRAGSIM_WIDE_LANES 1
#include <immintrin.h>
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace fragsim {

// Whether this processor runs the four-lane code (false where it is not built).
inline bool has_wide_lanes() {
#if defined(FRAGSIM_WIDE_LANES)
  static const bool wide = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return wide;
#else
  return false;
#endif
}

struct NarrowOps {
  using V = lanes::Lanes;
  using M = lanes::Mask;
  static constexpr int kWidth = 2;
  static V splat(double x) { return lanes::broadcast(x); }
  static V load(const double* p) { return lanes::load(p); }
  static M lt(V a, V b) { return lanes::lt(a, b); }
  static M le(V a, V b) { return lanes::le(a, b); }
  static M gt(V a, V b) { return lanes::gt(a, b); }
  static M ge(V a, V b) { return lanes::ge(a, b); }
  static V select(M m, V a, V b) { return lanes::select(m, a, b); }
  static V min(V a, V b) { return lanes::min(a, b); }
  static V max(V a, V b) { return lanes::max(a, b); }
  static V abs(V x) { return lanes::abs(x); }
  static M eq(V a, V b) { return lanes::eq(a, b); }
  static M ne(V a, V b) { return lanes::ne(a, b); }
  static M none_of(M m) { return ~m; }
  static V sqrt(V x) { return lanes::sqrt(x); }
  static V copysign(V mag, V sign) { return lanes::copysign(mag, sign); }
  static int bits(M m) { return lanes::bits(m); }
};

#if defined(FRAGSIM_WIDE_LANES)
using Wide = double __attribute__((vector_size(32)));
using WideMask = std::int64_t __attribute__((vector_size(32)));
struct WideOps {
  using V = Wide;
  struct M {
    WideMask bits;
    [[gnu::always_inline]] M operator&(const M& o) const { return {bits & o.bits}; }
    [[gnu::always_inline]] M operator|(const M& o) const { return {bits | o.bits}; }
  };
  static constexpr int kWidth = 4;
  [[gnu::always_inline]] static V splat(double x) { return V{x, x, x, x}; }
  [[gnu::always_inline]] static V load(const double* p) {
    V v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  // Comparisons as on doubles (false where NaN); selection and |x| by the bits.
  [[gnu::always_inline]] static M lt(const V& a, const V& b) {
    return {reinterpret_cast<WideMask>(a < b)};
  }
  [[gnu::always_inline]] static M le(const V& a, const V& b) {
    return {reinterpret_cast<WideMask>(a <= b)};
  }
  [[gnu::always_inline]] static M gt(const V& a, const V& b) {
    return {reinterpret_cast<WideMask>(a > b)};
  }
  [[gnu::always_inline]] static M ge(const V& a, const V& b) {
    return {reinterpret_cast<WideMask>(a >= b)};
  }
  // A mask lane is all ones or all zeros (comparisons and their &, |, ~), so the vector
  // conditional is the bitwise select; written so, GCC emits one blend instead of three logic ops.
  [[gnu::always_inline]] static V select(const M& m, const V& a, const V& b) {
    return m.bits ? a : b;
  }
  // std::min and std::max, as lanes::min and lanes::max. vminpd(b, a) computes b < a ? b : a, NaN
  // and signed zeros included, and GCC emits it for this form.
  [[gnu::always_inline]] static V min(const V& a, const V& b) { return b < a ? b : a; }
  [[gnu::always_inline]] static V max(const V& a, const V& b) { return a < b ? b : a; }
  [[gnu::always_inline]] static V abs(const V& x) {
    const WideMask magnitude = WideMask{} + INT64_MAX;
    return reinterpret_cast<V>(reinterpret_cast<WideMask>(x) & magnitude);
  }
  [[gnu::always_inline]] static M eq(const V& a, const V& b) {
    return {reinterpret_cast<WideMask>(a == b)};
  }
  [[gnu::always_inline]] static M ne(const V& a, const V& b) {
    return {reinterpret_cast<WideMask>(a != b)};
  }
  [[gnu::always_inline]] static M none_of(const M& m) { return {~m.bits}; }
  // Two SSE2 halves, as an AVX intrinsic here could not be inlined into the generic templates that
  // call it (each square root is correctly rounded either way).
  [[gnu::always_inline]] static V sqrt(const V& x) {
    const lanes::Lanes lo = lanes::sqrt(lanes::Lanes{x[0], x[1]});
    const lanes::Lanes hi = lanes::sqrt(lanes::Lanes{x[2], x[3]});
    return V{lo[0], lo[1], hi[0], hi[1]};
  }
  // As lanes::copysign, the magnitude's bits but the sign bit, and the sign's sign bit.
  [[gnu::always_inline]] static V copysign(const V& mag, const V& sign) {
    const WideMask magnitude = WideMask{} + INT64_MAX;
    return reinterpret_cast<V>((reinterpret_cast<WideMask>(mag) & magnitude) |
                               (reinterpret_cast<WideMask>(sign) & ~magnitude));
  }
  // SSE2's movmskpd on each half, as for sqrt, since lane by lane GCC extracts and masks each.
  [[gnu::always_inline]] static int bits(const M& m) {
    using Half = std::int64_t __attribute__((vector_size(16)));
    const Half lo{m.bits[0], m.bits[1]};
    const Half hi{m.bits[2], m.bits[3]};
    return _mm_movemask_pd(reinterpret_cast<__m128d>(lo)) |
           _mm_movemask_pd(reinterpret_cast<__m128d>(hi)) << 2;
  }
};
#endif

}  // namespace fragsim
