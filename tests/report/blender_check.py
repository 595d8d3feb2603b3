# Run inside Blender (blender -b --python-exit-code 1 --python blender_check.py -- ...): imports a
# bake with Blender's own glTF importer and checks it against the run's trajectories.csv: the
# same number of pieces, and at each sampled step every piece's position within TOL_M and its
# rotation matrix within TOL of the CSV's (its unit quaternion). Blender's importer turns glTF's
# Y-up frame into Blender's Z-up one, (x, y, z) -> (x, -z, y); the comparison undoes that. The
# importer keys the animation at frame = t * fps, so the scene's frame rate is set to the run's
# step rate first and step k is frame k (a first key at frame 1 is found and allowed for).
# Usage: blender -b --python-exit-code 1 --python blender_check.py -- BAKE.glb TRAJECTORIES.csv
#        STEP[,STEP...] [TOL_M [TOL]]
# Prints one line per step and a summary; raises (exit 1) on the first failed check.

import csv
import math
import sys

import bpy
from mathutils import Matrix, Quaternion

argv = sys.argv[sys.argv.index("--") + 1:]
bake_path, csv_path, steps_arg = argv[0], argv[1], argv[2]
tol_m = float(argv[3]) if len(argv) > 3 else 1e-5
tol = float(argv[4]) if len(argv) > 4 else 1e-5
steps = [int(s) for s in steps_arg.split(",")]

# The run, from the CSV: per step, per fragment, the position and the quaternion.
rows = {}
times = {}
fragments = set()
with open(csv_path, newline="") as f:
    for r in csv.DictReader(f):
        k = int(r["step"])
        i = int(r["fragment"])
        fragments.add(i)
        times[k] = float(r["t_s"])
        if k in steps:
            rows[(k, i)] = (
                (float(r["x_m"]), float(r["y_m"]), float(r["z_m"])),
                Quaternion((float(r["qw"]), float(r["qx"]), float(r["qy"]), float(r["qz"]))),
            )
missing = [k for k in steps if k not in times]
if missing:
    raise SystemExit(f"blender_check: steps {missing} are not in {csv_path}")
dt = times[1] - times[0] if 1 in times else times[max(times)] / max(times)

# Debian 12's Blender 3.4 glTF importer uses numpy.bool, an alias NumPy 1.24 (Debian 12's)
# removed; it meant the builtin bool, so restoring the alias changes nothing else.
import numpy  # noqa: E402  (after bpy: Blender's own Python path)

if "bool" not in numpy.__dict__:
    numpy.bool = bool

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
# The importer places a key at t seconds on frame t * fps / fps_base: the run's rate makes step k
# frame k.
rate = 1.0 / dt
scene.render.fps = round(rate)
scene.render.fps_base = scene.render.fps / rate
bpy.ops.import_scene.gltf(filepath=bake_path)
pieces = {o.name: o for o in bpy.data.objects if o.name.startswith("fragment_")}
print(f"blender_check: Blender {bpy.app.version_string}, {len(pieces)} pieces imported, "
      f"{len(fragments)} in the CSV")
if len(pieces) != len(fragments):
    raise SystemExit("blender_check: piece count differs")

# glTF (x, y, z) is Blender (x, -z, y): B = C g, so g = C^T B and a rotation R_g = C^T R_B C.
C = Matrix(((1.0, 0.0, 0.0), (0.0, 0.0, -1.0), (0.0, 1.0, 0.0)))
CT = C.transposed()


def errors_at(frame, k):
    scene.frame_set(int(math.floor(frame)), subframe=frame - math.floor(frame))
    worst_pos = 0.0
    worst_rot = 0.0
    for i in sorted(fragments):
        obj = pieces[f"fragment_{i}"]
        loc_b, rot_b, _ = obj.matrix_world.decompose()
        pos = CT @ loc_b
        rot = CT @ rot_b.to_matrix() @ C
        want_pos, want_q = rows[(k, i)]
        want = want_q.normalized().to_matrix()
        worst_pos = max(worst_pos, max(abs(pos[a] - want_pos[a]) for a in range(3)))
        worst_rot = max(worst_rot, max(abs(rot[a][b] - want[a][b])
                                       for a in range(3) for b in range(3)))
    return worst_pos, worst_rot


# Where the importer put step 0: frame 0, or frame 1 in importers that start there (judged at the
# last sampled step: before its first key an animation holds its first pose, so step 0 cannot tell).
last = max(steps)
offset = min((0.0, 1.0), key=lambda o: errors_at(last + o, last)[0])
overall_pos = 0.0
overall_rot = 0.0
for k in steps:
    pos_err, rot_err = errors_at(k + offset, k)
    overall_pos = max(overall_pos, pos_err)
    overall_rot = max(overall_rot, rot_err)
    print(f"blender_check: step {k} (t = {times[k]:.4f} s, frame {k + offset:g}): "
          f"position error {pos_err:.3g} m, rotation error {rot_err:.3g}")
    if not (pos_err <= tol_m and rot_err <= tol):
        raise SystemExit(f"blender_check: step {k} is off the run (tolerances {tol_m} m, {tol})")
print(f"blender_check: passed: {len(pieces)} pieces, steps {steps_arg}, worst position error "
      f"{overall_pos:.3g} m, worst rotation error {overall_rot:.3g}")
