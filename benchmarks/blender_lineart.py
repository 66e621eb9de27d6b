# Blender Line Art, the inexact peer for feature lines (course notes sections 26-28 for what
# the lines are): loads an OFF mesh, looks at it along a direction with an orthographic camera,
# and times Line Art's evaluation alone (silhouettes, creases over a threshold, intersections,
# every occlusion level so that hidden lines are computed too, as `hlr --hidden dashed` does).
# Run by scripts/bench_blender.sh:
#   blender -b -t 2 --factory-startup --python benchmarks/blender_lineart.py -- MESH.off DX,DY,DZ CREASE_DEGREES
import math
import sys
import time

import bpy
from mathutils import Vector

argv = sys.argv[sys.argv.index("--") + 1:]
path, direction, crease = argv[0], Vector([float(x) for x in argv[1].split(",")]), float(argv[2])


def read_off(p):
    with open(p) as f:
        tokens = [line.split("#")[0].split() for line in f]
    lines = [t for t in tokens if t]
    nv, nf = int(lines[1][0]), int(lines[1][1])
    verts = [tuple(float(x) for x in lines[2 + i][:3]) for i in range(nv)]
    faces = [tuple(int(x) for x in lines[2 + nv + i][1:1 + int(lines[2 + nv + i][0])]) for i in range(nf)]
    return verts, faces


t_load = time.perf_counter()
verts, faces = read_off(path)
scene = bpy.context.scene
for o in list(scene.objects):
    bpy.data.objects.remove(o, do_unlink=True)
mesh = bpy.data.meshes.new("mesh")
mesh.from_pydata(verts, [], faces)
mesh.update()
obj = bpy.data.objects.new("mesh", mesh)
scene.collection.objects.link(obj)
lo = Vector([min(v[k] for v in verts) for k in range(3)])
hi = Vector([max(v[k] for v in verts) for k in range(3)])
centre, size = (lo + hi) / 2, (hi - lo).length
cam_data = bpy.data.cameras.new("camera")
cam_data.type = "ORTHO"
cam_data.ortho_scale = size * 1.1
cam_data.clip_end = size * 10
cam = bpy.data.objects.new("camera", cam_data)
scene.collection.objects.link(cam)
d = direction.normalized()
cam.location = centre + d * size * 3
cam.rotation_euler = d.to_track_quat("Z", "Y").to_euler()  # the camera looks down its -Z
scene.camera = cam
gp = bpy.data.grease_pencils.new("lines")
layer = gp.layers.new("lines")
layer.frames.new(scene.frame_current)
mat = bpy.data.materials.new("ink")
bpy.data.materials.create_gpencil_data(mat)
gp.materials.append(mat)
gp_obj = bpy.data.objects.new("lines", gp)
scene.collection.objects.link(gp_obj)
print("lineart setup: %.2f s (%d vertices, %d faces)" % (time.perf_counter() - t_load, len(verts), len(faces)))
del verts, faces
bpy.context.view_layer.update()  # everything but Line Art evaluated first

mod = gp_obj.grease_pencil_modifiers.new("lineart", "GP_LINEART")
mod.source_type = "OBJECT"
mod.source_object = obj
mod.target_layer = "lines"
mod.target_material = mat
mod.use_contour = True
mod.use_crease = True
mod.crease_threshold = math.radians(180 - crease)  # Line Art's angle is between the faces
mod.use_intersection = True
mod.use_material = False
mod.use_edge_mark = False
mod.use_loose = False
mod.use_multiple_levels = True  # hidden lines too (occlusion levels 0..128)
mod.level_start = 0
mod.level_end = 128
t0 = time.perf_counter()
bpy.context.view_layer.update()  # Line Art computes here
t1 = time.perf_counter()
strokes = sum(len(f.strokes) for l in gp_obj.evaluated_get(bpy.context.evaluated_depsgraph_get()).data.layers for f in l.frames)
print("lineart compute: %.3f s, %d strokes" % (t1 - t0, strokes))
