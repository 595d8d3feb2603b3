#include "debris/mesh_file.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "debris/convex_hull.hpp"
#include "debris/debris_def.hpp"
#include "debris/gltf_load.hpp"
#include "debris/mesh_message.hpp"
#include "debris/obj_check.hpp"
#include "io/atomic_file.hpp"
#include "io/input_file.hpp"

// Vertices read as doubles, so a file written with 17 digits reads back exactly.
#define TINYOBJLOADER_USE_DOUBLE
#include <tiny_obj_loader.h>

namespace fragsim {
namespace {

std::string extension_of(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

struct RawPiece {
  std::string name;
  std::vector<Eigen::Vector3d> points_m;
};

std::vector<RawPiece> raw_obj(const std::string& text, const std::string& path) {
  check_obj_text(text, path);
  std::istringstream in(text);
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn;
  std::string err;
  // Materials do not matter to a piece's shape, so no material reader; mtllib lines are ignored.
  bool ok = false;
  try {  // as for glTF below, a library's exception is a refusal, not a crash
    ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, nullptr, false);
  } catch (const std::exception& e) {
    throw InputError(path + ": not a readable OBJ file: the OBJ reader failed (" +
                     one_line(e.what()) + ")");
  }
  if (!ok) throw InputError(path + ": not a readable OBJ file: " + one_line(err));
  std::vector<RawPiece> out;
  for (const tinyobj::shape_t& s : shapes) {
    if (s.mesh.indices.empty()) continue;
    RawPiece p;
    p.name = s.name;
    std::vector<int> seen;
    for (const tinyobj::index_t& i : s.mesh.indices) seen.push_back(i.vertex_index);
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    for (int v : seen) {
      const std::size_t k = 3 * static_cast<std::size_t>(v);
      if (v < 0 || k + 2 >= attrib.vertices.size()) {
        throw InputError(path + ": piece " + std::to_string(out.size() + 1) + " ('" + p.name +
                         "'): a face names vertex " + std::to_string(v + 1) + ", not in the file");
      }
      p.points_m.emplace_back(attrib.vertices[k], attrib.vertices[k + 1], attrib.vertices[k + 2]);
    }
    out.push_back(std::move(p));
  }
  return out;
}

Eigen::Matrix4d node_transform(const tinygltf::Node& n) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  if (n.matrix.size() == 16) {
    for (int i = 0; i < 16; ++i) m(i % 4, i / 4) = n.matrix[static_cast<std::size_t>(i)];
    return m;
  }
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  if (n.rotation.size() == 4) {
    r = Eigen::Quaterniond(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2])
            .normalized()
            .toRotationMatrix();
  }
  Eigen::Vector3d s = Eigen::Vector3d::Ones();
  if (n.scale.size() == 3) s = Eigen::Vector3d(n.scale[0], n.scale[1], n.scale[2]);
  m.topLeftCorner<3, 3>() = r * s.asDiagonal();
  if (n.translation.size() == 3) {
    m.topRightCorner<3, 1>() =
        Eigen::Vector3d(n.translation[0], n.translation[1], n.translation[2]);
  }
  return m;
}

// The POSITION values of one primitive, checked against the buffer they claim to be in.
void positions_of(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                  const Eigen::Matrix4d& to_file, const std::function<void(std::string)>& fail,
                  std::vector<Eigen::Vector3d>& out) {
  const auto it = prim.attributes.find("POSITION");
  if (it == prim.attributes.end()) return;
  if (it->second < 0 || it->second >= static_cast<int>(model.accessors.size())) {
    fail("its POSITION accessor does not exist");
  }
  const tinygltf::Accessor& acc = model.accessors[static_cast<std::size_t>(it->second)];
  if (acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || acc.type != TINYGLTF_TYPE_VEC3) {
    fail("POSITION is not float VEC3");
  }
  if (acc.sparse.isSparse || acc.bufferView < 0 ||
      acc.bufferView >= static_cast<int>(model.bufferViews.size())) {
    fail("POSITION is sparse or has no buffer view (not supported)");
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(acc.bufferView)];
  if (view.buffer < 0 || view.buffer >= static_cast<int>(model.buffers.size())) {
    fail("POSITION's buffer does not exist");
  }
  const std::vector<unsigned char>& data =
      model.buffers[static_cast<std::size_t>(view.buffer)].data;
  const std::size_t stride = view.byteStride ? view.byteStride : 12;
  if (stride < 12) fail("POSITION's byteStride is below the 12 bytes of a float VEC3");
  // Every bound is in subtractions of checked sizes, as a file's counts and offsets are 64-bit and
  // a product like stride * count would wrap (a count of 1.5e18 would pass a sum check and read
  // past the buffer).
  const bool view_fits =
      view.byteOffset <= data.size() && view.byteLength <= data.size() - view.byteOffset;
  const std::size_t room = view_fits && acc.byteOffset <= view.byteLength
                               ? view.byteLength - acc.byteOffset
                               : 0;  // bytes from the first position to the view's end
  if (!view_fits || (acc.count > 0 && (room < 12 || acc.count - 1 > (room - 12) / stride))) {
    fail("POSITION runs past the end of its buffer");
  }
  const std::size_t start = view.byteOffset + acc.byteOffset;
  for (std::size_t i = 0; i < acc.count; ++i) {
    float xyz[3];
    std::memcpy(xyz, data.data() + start + i * stride, sizeof xyz);
    const Eigen::Vector4d p(xyz[0], xyz[1], xyz[2], 1.0);
    out.push_back((to_file * p).head<3>());
  }
}

std::vector<RawPiece> raw_gltf(const std::string& bytes, const std::string& path, bool binary) {
  const tinygltf::Model model = load_gltf(bytes, path, binary);

  std::vector<int> roots;
  if (!model.scenes.empty()) {
    const int s =
        model.defaultScene >= 0 && model.defaultScene < static_cast<int>(model.scenes.size())
            ? model.defaultScene
            : 0;
    roots = model.scenes[static_cast<std::size_t>(s)].nodes;
  } else {
    // With no scene, every node that is no other's child is a root.
    std::vector<bool> child(model.nodes.size(), false);
    for (const auto& n : model.nodes) {
      for (int c : n.children) {
        if (c >= 0 && c < static_cast<int>(child.size())) child[static_cast<std::size_t>(c)] = true;
      }
    }
    for (std::size_t i = 0; i < child.size(); ++i) {
      if (!child[i]) roots.push_back(static_cast<int>(i));
    }
  }
  std::vector<RawPiece> out;
  std::function<void(int, const Eigen::Matrix4d&, int)> visit =
      [&](int index, const Eigen::Matrix4d& parent, int depth) {
        if (index < 0 || index >= static_cast<int>(model.nodes.size()) || depth > 64) {
          throw InputError(path + ": node " + std::to_string(index) +
                           " does not exist or the node tree has a cycle");
        }
        const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
        const Eigen::Matrix4d to_file = parent * node_transform(node);
        if (node.mesh >= 0) {
          RawPiece p;
          p.name = node.name;
          const auto fail = [&](const std::string& why) {
            throw InputError(path + ": piece " + std::to_string(out.size() + 1) + " ('" + p.name +
                             "'): " + why);
          };
          if (node.mesh >= static_cast<int>(model.meshes.size())) fail("its mesh does not exist");
          for (const auto& prim : model.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
            positions_of(model, prim, to_file, fail, p.points_m);
          }
          out.push_back(std::move(p));
          if (out.size() > static_cast<std::size_t>(kMaxPieces)) return;
        }
        for (int c : node.children) visit(c, to_file, depth + 1);
      };
  for (int r : roots) visit(r, Eigen::Matrix4d::Identity(), 0);
  return out;
}

// A piece's vertices in the object's frame and its faces, counter-clockwise from outside.
void piece_polyhedron(const Piece& p, std::vector<Eigen::Vector3d>& v,
                      std::vector<std::vector<int>>& faces) {
  body_polyhedron(p.shape.get(), p.half_extents_m, v, faces);
  for (Eigen::Vector3d& x : v) x = p.centre_m + p.rotation * x;
}

}  // namespace

void body_polyhedron(const ConvexShape* shape, const Eigen::Vector3d& half_extents_m,
                     std::vector<Eigen::Vector3d>& v, std::vector<std::vector<int>>& faces) {
  v.clear();
  faces.clear();
  if (shape) {
    v = shape->vertices_m;
    faces = shape->faces;
    return;
  }
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d s(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1);
    v.push_back(s.cwiseProduct(half_extents_m));
  }
  // Bit 0 is x, bit 1 y, bit 2 z; each loop counter-clockwise seen from outside.
  faces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
}

std::vector<Piece> read_pieces(const std::string& path, double density_kgpm3,
                               const AxisConvention& frame, std::vector<std::string>* warnings) {
  const std::string ext = extension_of(path);
  if (ext != ".obj" && ext != ".gltf" && ext != ".glb") {
    throw InputError(path + ": unknown mesh format '" + ext + "' (expected .obj, .gltf or .glb)");
  }
  return parse_pieces(read_input_file(path, "mesh file"), path, density_kgpm3, frame, warnings);
}

std::vector<Piece> parse_pieces(const std::string& bytes, const std::string& path,
                                double density_kgpm3, const AxisConvention& frame,
                                std::vector<std::string>* warnings) {
  const std::string ext = extension_of(path);
  std::vector<RawPiece> raw;
  if (ext == ".obj") {
    raw = raw_obj(bytes, path);
  } else if (ext == ".gltf" || ext == ".glb") {
    raw = raw_gltf(bytes, path, ext == ".glb");
  } else {
    throw InputError(path + ": unknown mesh format '" + ext + "' (expected .obj, .gltf or .glb)");
  }
  if (raw.empty()) throw InputError(path + ": no mesh (a piece is an object with faces)");
  if (raw.size() > static_cast<std::size_t>(kMaxPieces)) {
    throw InputError(path + ": more than " + std::to_string(kMaxPieces) + " pieces");
  }
  if (!frame.is_identity()) {
    for (RawPiece& r : raw) {
      for (Eigen::Vector3d& v : r.points_m) v = position_to_fragsim(frame, v);
    }
  }
  std::vector<Piece> out;
  out.reserve(raw.size());
  int reduced = 0;
  double largest_change = 0.0;  // relative volume change of a simplified hull
  for (std::size_t i = 0; i < raw.size(); ++i) {
    // Beyond the scene's own reach (object.distance_m <= 1e6 m) a hull loses its small features to
    // rounding; a fuzzed tetrahedron at 1e31 m reads with volume 2e77 m^3 and writes back -8e74.
    for (const Eigen::Vector3d& v : raw[i].points_m) {
      if (v.allFinite() && v.cwiseAbs().maxCoeff() > kMaxMeshCoordinate_m) {
        throw InputError(path + ": piece " + std::to_string(i + 1) + " ('" + raw[i].name +
                         "'): a vertex lies farther than 1e6 m from the file's origin");
      }
    }
    try {
      const HullPiece h = convex_hull(raw[i].points_m);
      if (h.full_vertices > 0) {
        ++reduced;
        largest_change = std::max(
            largest_change, std::abs(h.full_volume_m3 - h.shape->volume_m3) / h.full_volume_m3);
      }
      Piece p;
      p.centre_m = h.centre_m;
      p.shape = h.shape;
      p.half_extents_m = h.shape->half_extents_m;
      p.mass_kg = density_kgpm3 * h.shape->volume_m3;
      out.push_back(std::move(p));
    } catch (const DegenerateHull& e) {
      throw InputError(path + ": piece " + std::to_string(i + 1) + " ('" + raw[i].name +
                       "'): " + e.what());
    }
  }
  if (warnings != nullptr) {
    char line[256];
    if (reduced > 0) {
      std::snprintf(line, sizeof line,
                    ": %d piece%s hull%s reduced to %d vertices; largest volume change %.2g%%",
                    reduced, reduced == 1 ? "'s" : "s'", reduced == 1 ? "" : "s", kMaxHullVertices,
                    100.0 * largest_change);
      warnings->push_back(path + line);
    }
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    for (const RawPiece& r : raw) {
      for (const Eigen::Vector3d& v : r.points_m) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
    }
    const double across_m = (hi - lo).maxCoeff();
    if (frame.unit_m == 1.0 && across_m > kLargeObject_m) {
      std::snprintf(line, sizeof line,
                    ": the object is %.3g m across; if the file is in centimetres set "
                    "object.mesh_unit_m = 0.01",
                    across_m);
      warnings->push_back(path + line);
    }
  }
  return out;
}

std::string pieces_obj(const std::vector<Piece>& pieces) {
  std::string out = "# fragsim pieces: " + std::to_string(pieces.size()) +
                    ", one object each, metres, the object's centre at the origin\n";
  std::vector<Eigen::Vector3d> v;
  std::vector<std::vector<int>> faces;
  std::size_t base = 1;  // OBJ's indices count from 1 over the whole file
  char line[128];
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    piece_polyhedron(pieces[i], v, faces);
    out += "o piece_" + std::to_string(i + 1) + "\n";
    for (const auto& x : v) {
      std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", x.x(), x.y(), x.z());
      out += line;
    }
    for (const auto& f : faces) {
      out += "f";
      for (int k : f) out += " " + std::to_string(base + static_cast<std::size_t>(k));
      out += "\n";
    }
    base += v.size();
  }
  return out;
}

std::string pieces_glb(const std::vector<Piece>& pieces) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "fragsim fracture";
  model.buffers.emplace_back();
  std::vector<unsigned char>& data = model.buffers.front().data;
  auto append = [&data](const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    data.insert(data.end(), b, b + n);
  };
  tinygltf::Scene scene;
  std::vector<Eigen::Vector3d> v;
  std::vector<std::vector<int>> faces;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Piece& piece = pieces[i];
    piece_polyhedron(piece, v, faces);
    const std::string name = "piece_" + std::to_string(i + 1);
    // Positions are about the centre of mass, which the node carries in double precision, so the
    // 32-bit floats only round the piece's own size.
    tinygltf::Accessor pos;
    pos.bufferView = static_cast<int>(model.bufferViews.size());
    pos.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    pos.type = TINYGLTF_TYPE_VEC3;
    pos.count = v.size();
    pos.minValues.assign(3, std::numeric_limits<double>::infinity());
    pos.maxValues.assign(3, -std::numeric_limits<double>::infinity());
    tinygltf::BufferView pos_view;
    pos_view.buffer = 0;
    pos_view.byteOffset = data.size();
    pos_view.target = TINYGLTF_TARGET_ARRAY_BUFFER;
    for (const auto& x : v) {
      const Eigen::Vector3f f = (x - piece.centre_m).cast<float>();
      append(f.data(), 3 * sizeof(float));
      for (int k = 0; k < 3; ++k) {
        pos.minValues[k] = std::min(pos.minValues[k], static_cast<double>(f[k]));
        pos.maxValues[k] = std::max(pos.maxValues[k], static_cast<double>(f[k]));
      }
    }
    pos_view.byteLength = data.size() - pos_view.byteOffset;
    model.bufferViews.push_back(pos_view);
    model.accessors.push_back(pos);

    tinygltf::Accessor idx;
    idx.bufferView = static_cast<int>(model.bufferViews.size());
    idx.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    idx.type = TINYGLTF_TYPE_SCALAR;
    tinygltf::BufferView idx_view;
    idx_view.buffer = 0;
    idx_view.byteOffset = data.size();
    idx_view.target = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
    for (const auto& f : faces) {
      for (std::size_t k = 1; k + 1 < f.size(); ++k) {
        const std::uint32_t t[3] = {static_cast<std::uint32_t>(f[0]),
                                    static_cast<std::uint32_t>(f[k]),
                                    static_cast<std::uint32_t>(f[k + 1])};
        append(t, sizeof t);
        idx.count += 3;
      }
    }
    idx_view.byteLength = data.size() - idx_view.byteOffset;
    model.bufferViews.push_back(idx_view);
    model.accessors.push_back(idx);

    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = static_cast<int>(model.accessors.size()) - 2;
    prim.indices = static_cast<int>(model.accessors.size()) - 1;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(prim);
    tinygltf::Node node;
    node.name = name;
    node.mesh = static_cast<int>(model.meshes.size());
    node.translation = {piece.centre_m.x(), piece.centre_m.y(), piece.centre_m.z()};
    model.meshes.push_back(mesh);
    scene.nodes.push_back(static_cast<int>(model.nodes.size()));
    model.nodes.push_back(node);
  }
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true)) {
    throw std::runtime_error("glTF writer failed");
  }
  return out.str();
}

void write_pieces(const std::vector<Piece>& pieces, const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext != ".obj" && ext != ".glb") {
    throw InputError(path + ": unknown mesh format '" + ext + "' (expected .obj or .glb)");
  }
  write_file_atomically(path, ext == ".obj" ? pieces_obj(pieces) : pieces_glb(pieces));
}

}  // namespace fragsim
