#pragma once
// Two doubles computed together, for the batched passes of the cheap rejection
// (cheap_rejection.hpp) and the prediction (collision_prediction.cpp). Not plain loops, as GCC
// cannot vectorise a loop calling std::sqrt while math-errno is on (the default), and a branch per
// fragment keeps the processor from overlapping fragments. Two lanes are one SSE2 register, the
// x86-64 baseline; a wider vector changes the calling convention without AVX (-Wpsabi).
//
// Arithmetic is GCC's and Clang's vector extension (+, -, *, / lane by lane, the same IEEE results
// as on a double). Comparisons, masks and selection go through SSE2's own instructions, since in
// vector-extension form GCC 12 turns them into conditionals that it lowers, lacking SSE4.1, to a
// scalar cmov per lane.

#include <cmath>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace fragsim::lanes {

inline constexpr int kWidth = 2;
using Lanes = double __attribute__((vector_size(16)));

inline Lanes broadcast(double x) {
  return Lanes{x, x};
}
inline Lanes load(const double* p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store(double* p, Lanes v) {
  std::memcpy(p, &v, sizeof v);
}

#if defined(__SSE2__)

// All bits set in a lane where a comparison held.
struct Mask {
  __m128d bits;
};
inline Mask operator&(Mask a, Mask b) {
  return {_mm_and_pd(a.bits, b.bits)};
}
inline Mask operator|(Mask a, Mask b) {
  return {_mm_or_pd(a.bits, b.bits)};
}
inline Mask operator~(Mask a) {
  return {_mm_xor_pd(a.bits, _mm_castsi128_pd(_mm_set1_epi32(-1)))};
}
inline Mask& operator|=(Mask& a, Mask b) {
  return a = a | b;
}
// The comparisons, false where a lane is NaN (true for ne), as on doubles.
inline Mask lt(Lanes a, Lanes b) {
  return {_mm_cmplt_pd(a, b)};
}
inline Mask le(Lanes a, Lanes b) {
  return {_mm_cmple_pd(a, b)};
}
inline Mask gt(Lanes a, Lanes b) {
  return {_mm_cmpgt_pd(a, b)};
}
inline Mask ge(Lanes a, Lanes b) {
  return {_mm_cmpge_pd(a, b)};
}
inline Mask eq(Lanes a, Lanes b) {
  return {_mm_cmpeq_pd(a, b)};
}
inline Mask ne(Lanes a, Lanes b) {
  return {_mm_cmpneq_pd(a, b)};
}
inline int bits(Mask m) {  // lane i's flag in bit i
  return _mm_movemask_pd(m.bits);
}
inline bool get(Mask m, int lane) {
  return ((bits(m) >> lane) & 1) != 0;
}
// m ? a : b, lane by lane.
inline Lanes select(Mask m, Lanes a, Lanes b) {
  return _mm_or_pd(_mm_and_pd(m.bits, a), _mm_andnot_pd(m.bits, b));
}
// Correctly rounded, like std::sqrt; a negative lane gives NaN and sets no errno.
inline Lanes sqrt(Lanes x) {
  return _mm_sqrt_pd(x);
}
// |x| and std::copysign, by the sign bit (-0.0 included).
inline Lanes abs(Lanes x) {
  return _mm_andnot_pd(broadcast(-0.0), x);
}
inline Lanes copysign(Lanes mag, Lanes sign) {
  const Lanes bit = broadcast(-0.0);
  return _mm_or_pd(_mm_andnot_pd(bit, mag), _mm_and_pd(bit, sign));
}

#else  // any other target uses the vector extension throughout

struct Mask {
  decltype(Lanes{} < Lanes{}) bits;
};
inline Mask operator&(Mask a, Mask b) {
  return {a.bits & b.bits};
}
inline Mask operator|(Mask a, Mask b) {
  return {a.bits | b.bits};
}
inline Mask operator~(Mask a) {
  return {~a.bits};
}
inline Mask& operator|=(Mask& a, Mask b) {
  return a = a | b;
}
inline Mask lt(Lanes a, Lanes b) {
  return {a < b};
}
inline Mask le(Lanes a, Lanes b) {
  return {a <= b};
}
inline Mask gt(Lanes a, Lanes b) {
  return {a > b};
}
inline Mask ge(Lanes a, Lanes b) {
  return {a >= b};
}
inline Mask eq(Lanes a, Lanes b) {
  return {a == b};
}
inline Mask ne(Lanes a, Lanes b) {
  return {a != b};
}
inline int bits(Mask m) {
  return (m.bits[0] != 0 ? 1 : 0) | (m.bits[1] != 0 ? 2 : 0);
}
inline bool get(Mask m, int lane) {
  return m.bits[lane] != 0;
}
inline Lanes select(Mask m, Lanes a, Lanes b) {
  using Bits = decltype(m.bits);
  return reinterpret_cast<Lanes>((reinterpret_cast<Bits>(a) & m.bits) |
                                 (reinterpret_cast<Bits>(b) & ~m.bits));
}
inline Lanes sqrt(Lanes x) {
  return Lanes{std::sqrt(x[0]), std::sqrt(x[1])};
}
inline Lanes abs(Lanes x) {
  return Lanes{std::abs(x[0]), std::abs(x[1])};
}
inline Lanes copysign(Lanes mag, Lanes sign) {
  return Lanes{std::copysign(mag[0], sign[0]), std::copysign(mag[1], sign[1])};
}

#endif

// std::min and std::max, lane by lane, returning the same lane on ties and NaNs, as std::min(a, b)
// is b < a ? b : a, which minpd(b, a) computes, and likewise for max.
#if defined(__SSE2__)
inline Lanes min(Lanes a, Lanes b) {
  return _mm_min_pd(b, a);
}
inline Lanes max(Lanes a, Lanes b) {
  return _mm_max_pd(b, a);
}
#else
inline Lanes min(Lanes a, Lanes b) {
  return select(lt(b, a), b, a);
}
inline Lanes max(Lanes a, Lanes b) {
  return select(lt(a, b), b, a);
}
#endif

// The operation set of the geometry's formulas written once for any width
// (geometry/time_to_plane.hpp's ScalarOps on one double), on two lanes.
struct LaneOps {
  using V = Lanes;
  using M = Mask;
  static V splat(double x) { return broadcast(x); }
  static M lt(V a, V b) { return lanes::lt(a, b); }
  static M gt(V a, V b) { return lanes::gt(a, b); }
  static M ge(V a, V b) { return lanes::ge(a, b); }
  static M ne(V a, V b) { return lanes::ne(a, b); }
  static M both(M a, M b) { return a & b; }
  static V select(M m, V a, V b) { return lanes::select(m, a, b); }
  static V sqrt(V x) { return lanes::sqrt(x); }
  static V copysign(V mag, V sign) { return lanes::copysign(mag, sign); }
  static V max(V a, V b) { return lanes::max(a, b); }
};

}  // namespace fragsim::lanes
