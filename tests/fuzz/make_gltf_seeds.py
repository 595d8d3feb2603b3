#!/usr/bin/env python3
"""Writes corpus/gltf_mesh/: small glTF files (JSON with data: URI buffers, and binary .glb) that
reach the reader's paths: node transforms (matrix, TRS, parents), strided and offset POSITION
views, several primitives and meshes, and the malformed cases read_pieces refuses (a POSITION past
its buffer, a missing accessor or mesh, a node cycle, a non-float POSITION). Usage:
tests/fuzz/make_gltf_seeds.py (run from anywhere; rewrites the folder's generated files)."""
import base64
import json
import os
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "gltf_mesh")

TETRA = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
CUBE = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]


def floats(points, stride=12):
    out = b""
    for p in points:
        out += struct.pack("<3f", *p) + b"\0" * (stride - 12)
    return out


def model(buffer, views, accessors, meshes, nodes, scenes=None):
    m = {"asset": {"version": "2.0"}, "buffers": [{"byteLength": len(buffer)}],
         "bufferViews": views, "accessors": accessors, "meshes": meshes, "nodes": nodes}
    if scenes is not None:
        m["scenes"] = scenes
        m["scene"] = 0
    return m


def write_gltf(name, m, buffer):
    m["buffers"][0]["uri"] = "data:application/octet-stream;base64," + \
        base64.b64encode(buffer).decode()
    with open(os.path.join(OUT, name), "w") as f:
        json.dump(m, f, separators=(",", ":"))


def write_glb(name, m, buffer):
    js = json.dumps(m, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    buffer += b"\0" * (-len(buffer) % 4)
    body = struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(buffer),
                                                                      0x004E4942) + buffer
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body)


def pos_accessor(view, count, offset=0, ctype=5126, typ="VEC3"):
    return {"bufferView": view, "byteOffset": offset, "componentType": ctype, "count": count,
            "type": typ}


def prim(acc):
    return {"attributes": {"POSITION": acc}}


def main():
    os.makedirs(OUT, exist_ok=True)
    # Two pieces, a cube and a tetrahedron, in one buffer; a scene with both nodes.
    buf = floats(CUBE) + floats(TETRA)
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": 96},
             {"buffer": 0, "byteOffset": 96, "byteLength": 48}]
    accs = [pos_accessor(0, 8), pos_accessor(1, 4)]
    meshes = [{"primitives": [prim(0)]}, {"primitives": [prim(1)]}]
    nodes = [{"name": "cube", "mesh": 0, "translation": [1, 2, 3]},
             {"name": "tetra", "mesh": 1, "rotation": [0, 0, 0.7071068, 0.7071068],
              "scale": [2, 1, 0.5]}]
    m = model(buf, views, accs, meshes, nodes, [{"nodes": [0, 1]}])
    write_gltf("cube_and_tetra.gltf", json.loads(json.dumps(m)), buf)
    write_glb("cube_and_tetra.glb", json.loads(json.dumps(m)), buf)

    # A parent with a matrix, a child with the mesh; no scene (roots are the nodes no one owns).
    buf = floats(TETRA, stride=16)
    m = model(buf, [{"buffer": 0, "byteOffset": 0, "byteLength": 64, "byteStride": 16}],
              [pos_accessor(0, 4)], [{"primitives": [prim(0), prim(0)]}],
              [{"name": "parent", "children": [1],
                "matrix": [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 5, 0, 0, 1]},
               {"name": "child", "mesh": 0}])
    write_gltf("parent_matrix_strided.gltf", m, buf)

    # An accessor offset into its view.
    buf = b"\0" * 8 + floats(TETRA)
    m = model(buf, [{"buffer": 0, "byteOffset": 4, "byteLength": 52}],
              [pos_accessor(0, 4, offset=4)], [{"primitives": [prim(0)]}],
              [{"name": "offset", "mesh": 0}], [{"nodes": [0]}])
    write_glb("offset_accessor.glb", m, buf)

    # Refused: POSITION past its buffer, a missing accessor, a missing mesh, a cycle, not float.
    buf = floats(TETRA)
    base_views = [{"buffer": 0, "byteOffset": 0, "byteLength": 48}]
    write_gltf("position_past_buffer.gltf",
               model(buf, base_views, [pos_accessor(0, 400)], [{"primitives": [prim(0)]}],
                     [{"mesh": 0}], [{"nodes": [0]}]), buf)
    write_gltf("missing_accessor.gltf",
               model(buf, base_views, [pos_accessor(0, 4)], [{"primitives": [prim(7)]}],
                     [{"mesh": 0}], [{"nodes": [0]}]), buf)
    write_gltf("missing_mesh.gltf",
               model(buf, base_views, [pos_accessor(0, 4)], [{"primitives": [prim(0)]}],
                     [{"mesh": 3}], [{"nodes": [0]}]), buf)
    write_gltf("node_cycle.gltf",
               model(buf, base_views, [pos_accessor(0, 4)], [{"primitives": [prim(0)]}],
                     [{"mesh": 0, "children": [1]}, {"children": [0]}], [{"nodes": [0]}]), buf)
    write_glb("not_float_positions.glb",
              model(buf, base_views, [pos_accessor(0, 4, ctype=5123)],
                    [{"primitives": [prim(0)]}], [{"mesh": 0}], [{"nodes": [0]}]), buf)
    # A finding, kept as a seed (the reader is fixed): 12 x this count wraps to 8 in 64 bits, which passed the old bounds
    # check and read past the buffer.
    write_gltf("position_count_wraps.gltf",
               model(floats(TETRA), base_views, [pos_accessor(0, 1537228672809129302)],
                     [{"primitives": [prim(0)]}], [{"mesh": 0}], [{"nodes": [0]}]),
               floats(TETRA))
    write_gltf("flat_piece.gltf",
               model(floats(TETRA[:3]), [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
                     [pos_accessor(0, 3)], [{"primitives": [prim(0)]}], [{"mesh": 0}],
                     [{"nodes": [0]}]), floats(TETRA[:3]))


if __name__ == "__main__":
    main()
