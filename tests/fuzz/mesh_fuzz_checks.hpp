#pragma once
// What the mesh-file fuzz targets (obj_mesh_fuzz.cpp, gltf_mesh_fuzz.cpp) check on any input:
//  - bad input throws InputError and nothing else;
//  - accepted pieces are what read_pieces promises: 1 .. kMaxPieces pieces, each a convex shape
//    with finite vertices and centre, volume >= kMinHullVolume_m3 and mass density * volume > 0;
//  - written by pieces_obj (17 digits) they read back as as many pieces.
// Each broken invariant is a __builtin_trap().

#include <cmath>
#include <string>
#include <vector>

#include "debris/convex_hull.hpp"
#include "debris/debris_def.hpp"
#include "debris/mesh_file.hpp"
#include "io/input_error.hpp"

namespace fragsim::fuzz {

inline constexpr double kDensityKgpm3 = 1000.0;

inline std::vector<Piece> parse_or_trap(const std::string& bytes, const std::string& path,
                                        bool* ok) {
  *ok = false;
  try {
    std::vector<Piece> p = parse_pieces(bytes, path, kDensityKgpm3);
    *ok = true;
    return p;
  } catch (const InputError&) {
    return {};
  } catch (...) {
    __builtin_trap();  // only InputError may leave the reader on bad input
  }
}

inline bool finite(const Eigen::Vector3d& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

inline void check_pieces(const std::string& bytes, const std::string& path) {
  bool ok = false;
  const std::vector<Piece> pieces = parse_or_trap(bytes, path, &ok);
  if (!ok) return;
  if (pieces.empty() || pieces.size() > static_cast<std::size_t>(kMaxPieces)) __builtin_trap();
  for (const Piece& p : pieces) {
    if (!p.shape || !finite(p.centre_m) || !finite(p.half_extents_m)) __builtin_trap();
    if (!(p.shape->volume_m3 >= kMinHullVolume_m3) || !std::isfinite(p.shape->volume_m3)) {
      __builtin_trap();
    }
    if (!(p.mass_kg > 0.0) || !std::isfinite(p.mass_kg)) __builtin_trap();
    if (p.shape->vertices_m.size() < 4) __builtin_trap();
    for (const Eigen::Vector3d& v : p.shape->vertices_m) {
      if (!finite(v)) __builtin_trap();
    }
  }
  const std::vector<Piece> back = parse_or_trap(pieces_obj(pieces), "roundtrip.obj", &ok);
  if (!ok || back.size() != pieces.size()) __builtin_trap();
}

}  // namespace fragsim::fuzz
