#pragma once
// Pieces in mesh files, read from a file fractured elsewhere (one mesh per piece, an OBJ object or
// group or a glTF node with a mesh) and written, so `fragsim fracture` output opens in any viewer
// and reads back as the same pieces.

#include <string>
#include <vector>

#include "debris/piece.hpp"
#include "geometry/axis_convention.hpp"

namespace fragsim {

// The farthest a piece's vertex may lie from the file's origin, per coordinate.
inline constexpr double kMaxMeshCoordinate_m = 1e6;

// An object wider than this is more likely a file in centimetres read as metres (a 2 m crate
// becomes 200 m) than a real one, so read_pieces warns.
inline constexpr double kLargeObject_m = 100.0;

// The pieces of an .obj, .gltf or .glb file (by its extension), in the file's frame converted by
// `frame` to fragsim's (metres, Y up, right-handed), each the convex hull of its mesh's vertices
// (for glTF with the node's transform and its parents' applied; at most kMaxHullVertices vertices,
// convex_hull.hpp), of uniform density. Throws InputError, one line naming the file and, where it
// is one piece's fault, the piece or file:line, for any of: not found or unreadable, not parsable
// (an OBJ coordinate that is not a finite number, a face index naming no vertex; a glTF uri outside
// the file's folder or not a regular file, an unsupported required extension), no mesh, more than
// kMaxPieces pieces, a non-finite vertex or one beyond kMaxMeshCoordinate_m, a flat or zero-volume
// piece (below kMinHullVolume_m3). `warnings`, when given, gets one line per thing worth saying
// that is no error, each starting with the path: hulls simplified (how many, the largest volume
// change), an object over kLargeObject_m across at unit_m = 1.
std::vector<Piece> read_pieces(const std::string& path, double density_kgpm3,
                               const AxisConvention& frame = {},
                               std::vector<std::string>* warnings = nullptr);

// The same from a file's bytes already in memory. `path` gives the format (its extension), the name
// in messages and the folder a .gltf's external buffers are looked up in.
std::vector<Piece> parse_pieces(const std::string& bytes, const std::string& path,
                                double density_kgpm3, const AxisConvention& frame = {},
                                std::vector<std::string>* warnings = nullptr);

// A piece's vertices about its centre of mass in its body axes, and its faces, each a loop
// counter-clockwise seen from outside, from the hull `shape` or, without one, the box of these half
// extents (a grid piece). The meshes of pieces_obj, pieces_glb and the bake (report/gltf_bake.hpp).
void body_polyhedron(const ConvexShape* shape, const Eigen::Vector3d& half_extents_m,
                     std::vector<Eigen::Vector3d>& vertices_m,
                     std::vector<std::vector<int>>& faces);

// Each piece's hull (a grid piece's box) in the object's frame, one OBJ object `piece_<n>` per
// piece with 17 significant digits, so the file reads back to the last bit of every vertex.
std::string pieces_obj(const std::vector<Piece>& pieces);
// The same as binary glTF, one node per piece, translated to its centre of mass, whose mesh holds
// the vertices relative to that centre as 32-bit floats (glTF has no other type for positions).
std::string pieces_glb(const std::vector<Piece>& pieces);

// One of the two, chosen by the extension (.obj, .glb), written atomically (io/atomic_file.hpp).
// Throws InputError naming the path for another extension, std::runtime_error if it cannot be
// written.
void write_pieces(const std::vector<Piece>& pieces, const std::string& path);

}  // namespace fragsim
