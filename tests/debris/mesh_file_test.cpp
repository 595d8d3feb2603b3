// Pieces from and to mesh files: closed forms for a cube and a tetrahedron read from OBJ, round
// trips through OBJ and binary glTF, and one line naming the file and piece for each bad input.

#include "debris/mesh_file.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "debris/convex_hull.hpp"
#include "debris/debris_def.hpp"
#include "io/input_error.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;

class MeshFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fragsim_mesh_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  // The message of the InputError reading `path` throws; empty if none.
  static std::string error_of(const std::string& path) {
    try {
      read_pieces(path, 600.0);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

// A unit cube centred on (1, 2, 3), its faces as triangles, as Blender exports it.
const char* kCubeObj =
    "o Cube\n"
    "v 0.5 1.5 2.5\nv 1.5 1.5 2.5\nv 0.5 2.5 2.5\nv 1.5 2.5 2.5\n"
    "v 0.5 1.5 3.5\nv 1.5 1.5 3.5\nv 0.5 2.5 3.5\nv 1.5 2.5 3.5\n"
    "f 1 3 4\nf 1 4 2\nf 5 6 8\nf 5 8 7\nf 1 2 6\nf 1 6 5\n"
    "f 3 7 8\nf 3 8 4\nf 1 5 7\nf 1 7 3\nf 2 4 8\nf 2 8 6\n";

TEST_F(MeshFile, UnitCubeHasTheClosedFormMassAndInertia) {
  const std::vector<Piece> p = read_pieces(write("cube.obj", kCubeObj), 750.0);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR(p[0].mass_kg, 750.0, 750.0 * 1e-12);
  EXPECT_NEAR((p[0].centre_m - Eigen::Vector3d(1, 2, 3)).norm(), 0.0, 1e-12);
  const Eigen::Matrix3d inertia_kgm2 = p[0].mass_kg * p[0].shape->inertia_per_kg_m2;
  EXPECT_NEAR((inertia_kgm2 - Eigen::Matrix3d::Identity() * 750.0 / 6.0).norm(), 0.0,
              750.0 * 1e-12);
  EXPECT_EQ(p[0].shape->faces.size(), 6u);  // coplanar triangles merged
  EXPECT_NEAR((p[0].half_extents_m - Eigen::Vector3d::Constant(0.5)).norm(), 0.0, 1e-12);
}

TEST_F(MeshFile, TetrahedronHasTheClosedFormVolumeAndCentroid) {
  // Two objects: the cube, then the corner tetrahedron of edges 1, 2, 3 at (-4, 0, 0).
  const std::string tet =
      "o Tet\nv -4 0 0\nv -3 0 0\nv -4 2 0\nv -4 0 3\nf 9 11 10\nf 9 10 12\nf 9 12 11\nf 10 11 "
      "12\n";
  const std::vector<Piece> p = read_pieces(write("two.obj", std::string(kCubeObj) + tet), 1.0);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NEAR(p[1].shape->volume_m3, 1.0 * 2.0 * 3.0 / 6.0, 1e-14);
  EXPECT_NEAR((p[1].centre_m - Eigen::Vector3d(-4 + 0.25, 0.5, 0.75)).norm(), 0.0, 1e-14);
}

// Every vertex of `a` (in the object's frame) has one of `b` within tol, and the counts agree.
void expect_same_piece(const Piece& a, const Piece& b, double tol) {
  ASSERT_NE(b.shape, nullptr);
  ASSERT_EQ(a.shape->vertices_m.size(), b.shape->vertices_m.size());
  EXPECT_NEAR((a.centre_m - b.centre_m).norm(), 0.0, tol);
  for (const auto& va : a.shape->vertices_m) {
    double best_m = INFINITY;
    for (const auto& vb : b.shape->vertices_m) {
      best_m = std::min(best_m, (a.centre_m + va - b.centre_m - vb).norm());
    }
    EXPECT_LE(best_m, tol);
  }
}

DebrisDef some_cells() {
  DebrisDef d;
  d.pattern = DebrisPattern::kVoronoi;
  d.pieces = 60;
  d.cluster = 0.4;
  d.blast_offset_m = Eigen::Vector3d(0.2, -0.1, 0.3);
  return d;
}

TEST_F(MeshFile, ObjRoundTripIsExactTo1e12) {
  const DebrisDef d = some_cells();
  const std::vector<Piece> a = make_pieces(d);
  const std::string path = (dir_ / "cells.obj").string();
  write_pieces(a, path);
  const std::vector<Piece> b = read_pieces(path, d.density_kgpm3);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    expect_same_piece(a[i], b[i], 1e-12);
    EXPECT_NEAR(b[i].mass_kg / a[i].mass_kg, 1.0, 1e-12);
  }
}

TEST_F(MeshFile, GlbRoundTripIsExactToFloatPrecision) {
  const DebrisDef d = some_cells();
  const std::vector<Piece> a = make_pieces(d);
  const std::string path = (dir_ / "cells.glb").string();
  write_pieces(a, path);
  const std::vector<Piece> b = read_pieces(path, d.density_kgpm3);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    // 32-bit positions about the centre, which the node holds in double: 1e-6 of the piece's size.
    expect_same_piece(a[i], b[i], 1e-6 * a[i].shape->radius_m);
    EXPECT_NEAR(b[i].mass_kg / a[i].mass_kg, 1.0, 1e-6);
  }
}

TEST_F(MeshFile, GridPiecesWriteAsBoxes) {
  DebrisDef d;
  d.splits = 2;
  const std::vector<Piece> a = make_pieces(d);
  const std::string path = (dir_ / "grid.obj").string();
  write_pieces(a, path);
  const std::vector<Piece> b = read_pieces(path, d.density_kgpm3);
  ASSERT_EQ(b.size(), 8u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR((a[i].centre_m - b[i].centre_m).norm(), 0.0, 1e-12);
    EXPECT_NEAR(b[i].mass_kg / a[i].mass_kg, 1.0, 1e-12);
    EXPECT_NEAR((b[i].half_extents_m - a[i].half_extents_m).norm(), 0.0, 1e-12);
  }
}

// A piece of 19,800 triangles (a UV sphere, as a modelling tool exports one; a 1e6-triangle sphere
// hung ODE's convex set-up) comes out with at most kMaxHullVertices vertices, and the file gets
// one warning saying so with the volume change. The small cube beside it is untouched.
TEST_F(MeshFile, AManyTriangleSphereIsReducedWithOneWarning) {
  std::string obj = kCubeObj;
  obj += "o Sphere\nv 0 0 1\nv 0 0 -1\n";
  const int rings = 100;
  const int segments = 100;
  char line[96];
  for (int r = 1; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const double theta = M_PI * r / rings;
      const double phi = 2 * M_PI * s / segments;
      std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", std::sin(theta) * std::cos(phi),
                    std::sin(theta) * std::sin(phi), std::cos(theta));
      obj += line;
    }
  }
  // Vertex k of ring r (1-based rings) is 8 (the cube's) + 2 (poles) + (r - 1) segments + k + 1.
  const auto at = [&](int r, int k) { return 11 + (r - 1) * segments + (k % segments); };
  for (int k = 0; k < segments; ++k) {
    obj += "f 9 " + std::to_string(at(1, k)) + " " + std::to_string(at(1, k + 1)) + "\n";
    obj += "f 10 " + std::to_string(at(rings - 1, k + 1)) + " " + std::to_string(at(rings - 1, k)) +
           "\n";
    for (int r = 1; r + 1 < rings; ++r) {
      obj += "f " + std::to_string(at(r, k)) + " " + std::to_string(at(r + 1, k)) + " " +
             std::to_string(at(r + 1, k + 1)) + " " + std::to_string(at(r, k + 1)) + "\n";
    }
  }
  const std::string path = write("sphere.obj", obj);
  std::vector<std::string> warnings;
  const std::vector<Piece> p = read_pieces(path, 1.0, {}, &warnings);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].shape->vertices_m.size(), 8u);
  EXPECT_NEAR(p[0].mass_kg, 1.0, 1e-12);
  EXPECT_LE(p[1].shape->vertices_m.size(), static_cast<std::size_t>(kMaxHullVertices));
  // Within 3% of the sphere's volume (convex_hull_test: the bound for a sphere).
  EXPECT_NEAR(p[1].mass_kg / (4 * M_PI / 3), 1.0, 0.03);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].rfind(path + ": 1 piece's hull reduced to 255 vertices; largest volume "
                                     "change 2.",
                              0),
            0u)
      << warnings[0];
}

// Pieces from the built-in fracture stay far below the limit, so none is simplified and no
// number of a Voronoi scene moves.
TEST_F(MeshFile, VoronoiCellsAreFarBelowTheVertexLimit) {
  DebrisDef d = some_cells();
  d.pieces = 2000;
  std::size_t most = 0;
  for (const Piece& p : make_pieces(d)) most = std::max(most, p.shape->vertices_m.size());
  EXPECT_LT(most, static_cast<std::size_t>(kMaxHullVertices) / 2);
}

TEST_F(MeshFile, EachBadInputIsOneLineNamingFileAndPiece) {
  auto expect_line = [](const std::string& message, const std::string& path,
                        const std::string& part) {
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(part), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  };
  const std::string missing = (dir_ / "missing.obj").string();
  expect_line(error_of(missing), missing, "missing.obj");

  const std::string no_mesh = write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n");
  expect_line(error_of(no_mesh), no_mesh, "no mesh");

  const std::string flat =
      write("flat.obj",
            std::string(kCubeObj) + "o Sheet\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 9 10 11 12\n");
  expect_line(error_of(flat), flat, "piece 2 ('Sheet'): the points are flat");

  const std::string tiny =
      write("tiny.obj", "o Speck\nv 0 0 0\nv 1e-5 0 0\nv 0 1e-5 0\nv 0 0 1e-5\nf 1 2 3\nf 1 2 4\n");
  expect_line(error_of(tiny), tiny, "piece 1 ('Speck'): hull volume");

  const std::string inf =
      write("inf.obj", "o Far\nv 0 0 0\nv 1e999 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n");
  expect_line(error_of(inf), inf, "piece 1 ('Far'): a vertex is not finite");

  std::string many;
  for (int i = 0; i <= kMaxPieces; ++i) {
    many += "o p\nv " + std::to_string(i) + " 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nf -4 -3 -2 -1\n";
  }
  const std::string too_many = write("many.obj", many);
  expect_line(error_of(too_many), too_many, "more than 20000 pieces");

  // gltf_mesh_fuzz's seed vertices_at_1e31.glb: a hull that far out is rounding, not a piece.
  const std::string far =
      write("far.obj", "o Away\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1.5e6\nf 1 2 3\nf 1 2 4\n");
  expect_line(error_of(far), far, "piece 1 ('Away'): a vertex lies farther than 1e6 m");

  const std::string stl = write("piece.stl", "solid\n");
  expect_line(error_of(stl), stl, "unknown mesh format");

  const std::string junk = write("junk.glb", "not a glb at all");
  expect_line(error_of(junk), junk, "not a readable glTF file");
}

}  // namespace
}  // namespace fragsim

namespace fragsim {
namespace {

std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t v = 0;
    for (std::size_t k2 = 0; k2 < 3; ++k2) {
      v = (v << 8) | (k2 < n ? static_cast<unsigned char>(bytes[i + k2]) : 0u);
    }
    for (std::size_t k2 = 0; k2 < 4; ++k2) {
      out += k2 <= n ? k[(v >> (18 - 6 * k2)) & 63] : '=';
    }
  }
  return out;
}

// A buffer's uri is read only when it names a regular file: one naming a folder (here "sub",
// beside the .gltf) is refused in one line, where tinygltf's own reader took a folder's
// stream size, 2^63, as the bytes to allocate (found by gltf_mesh_fuzz). A real buffer file
// beside the .gltf is still read.
TEST_F(MeshFile, GltfBufferUriMustNameARegularFile) {
  fs::create_directories(dir_ / "sub");
  const std::string json =
      R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"URI"}],)"
      R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}]})";
  const auto with_uri = [&](const std::string& uri) {
    std::string j = json;
    j.replace(j.find("URI"), 3, uri);
    return j;
  };
  const std::string path = write("folder.gltf", with_uri("sub"));
  const std::string folder = error_of(path);
  EXPECT_EQ(folder.rfind(path + ": not a readable glTF file: ", 0), 0u) << folder;
  EXPECT_NE(folder.find("not a regular file"), std::string::npos) << folder;
  // Three points of a triangle in a 36-byte file: read (and refused only as a flat piece).
  const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  write("tri.bin", std::string(reinterpret_cast<const char*>(xyz), sizeof xyz));
  const std::string m = error_of(write("tri.gltf", with_uri("tri.bin")));
  EXPECT_EQ(m.find("not a readable glTF file"), std::string::npos) << m;
}

// gltf_mesh_fuzz's seed empty_buffer_beside_bin_chunk.glb: a .glb whose one buffer has
// byteLength 0 beside an 8-byte BIN chunk. tinygltf throws std::out_of_range on it; the reader
// refuses it in the one line of any unreadable glTF file.
TEST_F(MeshFile, GltfReaderExceptionIsOneLineRefusal) {
  const std::string json = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":0}]})";
  const auto le32 = [](std::uint32_t v) {
    std::string b(4, '\0');
    for (int i = 0; i < 4; ++i) b[static_cast<std::size_t>(i)] = static_cast<char>(v >> (8 * i));
    return b;
  };
  const std::string json_chunk = le32(static_cast<std::uint32_t>(json.size())) + "JSON" + json;
  const std::string bin_chunk = le32(8) + std::string("BIN\0", 4) + std::string(8, '\0');
  const std::string glb =
      "glTF" + le32(2) +
      le32(static_cast<std::uint32_t>(12 + json_chunk.size() + bin_chunk.size())) + json_chunk +
      bin_chunk;
  const std::string path = write("empty_buffer.glb", glb);
  const std::string m = error_of(path);
  EXPECT_EQ(m.rfind(path + ": not a readable glTF file: ", 0), 0u) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
}

TEST_F(MeshFile, GltfNodeTransformsAndTheirParentsAreApplied) {
  // A 1 x 2 x 3 box about its origin, in a child node turned 90 degrees about z and moved 0.5 m
  // along x, under a parent moved to (1, 2, 3) and scaled by 2. The piece: a 4 x 2 x 6 box (the
  // turn swaps x and y, the scale doubles), volume 48, centred at (1, 2, 3) + 2 (0.5, 0, 0).
  std::string bytes;
  for (int c = 0; c < 8; ++c) {
    const float v[3] = {c & 1 ? 0.5f : -0.5f, c & 2 ? 1.0f : -1.0f, c & 4 ? 1.5f : -1.5f};
    bytes.append(reinterpret_cast<const char*>(v), sizeof v);
  }
  const double s = std::sqrt(0.5);
  const std::string json =
      R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
      R"("nodes":[{"name":"parent","translation":[1,2,3],"scale":[2,2,2],"children":[1]},)"
      R"({"name":"box","mesh":0,"translation":[0.5,0,0],"rotation":[0,0,)" +
      std::to_string(s) + "," + std::to_string(s) +
      R"(]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":8,"type":"VEC3",)"
      R"("min":[-0.5,-1,-1.5],"max":[0.5,1,1.5]}],)"
      R"("bufferViews":[{"buffer":0,"byteLength":96}],)"
      R"("buffers":[{"byteLength":96,"uri":"data:application/octet-stream;base64,)" +
      base64(bytes) + R"("}]})";
  const std::vector<Piece> p = read_pieces(write("box.gltf", json), 1.0);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR(p[0].shape->volume_m3, 48.0, 48.0 * 1e-6);
  EXPECT_NEAR((p[0].centre_m - Eigen::Vector3d(2, 2, 3)).norm(), 0.0, 1e-6);
  EXPECT_NEAR((p[0].half_extents_m - Eigen::Vector3d(2, 1, 3)).norm(), 0.0, 1e-5);

  // The seed position_count_wraps.gltf of gltf_mesh_fuzz: a POSITION count whose 12-byte positions
  // wrap 64 bits to 8 bytes (12 x 1537228672809129302 = 2^64 + 8) read past the 96-byte buffer; it
  // is refused. So is an accessor that starts past its view's end.
  std::string wraps = json;
  wraps.replace(wraps.find(R"("count":8)"), 9, R"("count":1537228672809129302)");
  const std::string wrapped = write("wraps.gltf", wraps);
  EXPECT_NE(error_of(wrapped).find("piece 1 ('box'): POSITION runs past the end of its buffer"),
            std::string::npos)
      << error_of(wrapped);
  std::string past = json;
  past.replace(past.find(R"("count":8,)"), 10, R"("count":1,"byteOffset":200,)");
  const std::string beyond = write("beyond.gltf", past);
  EXPECT_NE(error_of(beyond).find("POSITION runs past the end of its buffer"), std::string::npos)
      << error_of(beyond);

  // A glTF file whose only node has no mesh has no piece.
  const std::string empty =
      write("empty.gltf", R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{}]})");
  const std::string m = error_of(empty);
  EXPECT_NE(m.find(empty + ": no mesh"), std::string::npos) << m;
}

}  // namespace
}  // namespace fragsim
