#pragma once
// How the object breaks, into a grid of equal cubes (the default), Voronoi cells of the object's
// box, or the pieces of a mesh file fractured elsewhere (Blender, Houdini, a game engine).
// make_pieces turns one of these into the pieces the explosion throws.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "debris/piece.hpp"
#include "geometry/axis_convention.hpp"

namespace fragsim {

enum class DebrisPattern { kGrid, kVoronoi };

// More pieces than this is a mistake, not a scene, because each becomes an ODE body, and a file
// with more is most likely one whose every triangle is its own object.
constexpr int kMaxPieces = 20000;

struct DebrisDef {
  DebrisPattern pattern = DebrisPattern::kGrid;
  double size_m = 1.2;  // edge of the object's cube, centred on the object's centre
  int splits = 12;      // for grid, pieces per axis
  double gap = 0.02;    // each piece is shrunk by this share about its centre so none touch
  int pieces = 1000;    // for voronoi, the number of cells
  // For voronoi, in [0, 1). The seed points' density falls off as distance^(-3 cluster) from the
  // blast point, so a cell's size grows like distance^cluster (0 is uniform over the box), outside
  // a core of radius size_m / (2 pieces^(1/3)) about the blast where it is uniform, so cells near
  // the blast stay of a simulable size.
  double cluster = 0.0;
  Eigen::Vector3d blast_offset_m = Eigen::Vector3d::Zero();  // from the object's centre
  // When not empty, the pieces are this file's meshes (.obj, .gltf, .glb) and pattern, size_m,
  // splits, gap, pieces and cluster do not apply; the file's origin is the object's centre.
  std::string mesh_file;
  AxisConvention mesh_frame;  // the file's units and axes
  double density_kgpm3 = 600.0;
  std::uint64_t seed = 1;  // for voronoi, the seed points'
};

// The pieces, deterministic for a given def. Grid pieces are ordered x fastest, then y, then z;
// Voronoi cells in the order their seed points were drawn; a file's in its order (OBJ objects or
// groups, glTF nodes depth first from the scene's roots). Throws InputError (a bad mesh file,
// naming it and the piece) or std::runtime_error (a Voronoi cell the library failed to compute).
std::vector<Piece> make_pieces(const DebrisDef& def);

// The piece's volume, its hull's or its box's.
double piece_volume_m3(const Piece& piece);

}  // namespace fragsim
