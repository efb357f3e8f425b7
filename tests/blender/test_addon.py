"""The Blender add-on (bindings/blender/ocean_addon) in Blender itself, headless:

    blender -b --factory-startup --python tests/blender/test_addon.py -- \
        --package BUILD/python --addons bindings/blender --out DIR [--width 64 --height 36]

Enables the add-on, adds an ocean, moves to a frame and checks the mesh against the package
queried on its own (a simulator of the same preset at the same time), reads the error of a bad
value as Blender reports it, bakes two frames to EXR, and renders a frame with Cycles on the CPU
to DIR/render.png, checking the picture has sea and sky in it. Exit status 0 when every check
holds; each check prints its figure.
"""
import argparse
import importlib.util
import json
import os
import sys

import addon_utils
import bpy
import numpy as np

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
parser = argparse.ArgumentParser()
parser.add_argument("--package", required=True, help="the folder holding ocean/")
parser.add_argument("--addons", required=True, help="the folder holding ocean_addon/")
parser.add_argument("--out", required=True, help="a folder for the bake and the picture")
parser.add_argument("--width", type=int, default=64)
parser.add_argument("--height", type=int, default=36)
parser.add_argument("--samples", type=int, default=8)
parser.add_argument("--grid", type=int, default=96)
parser.add_argument("--size", type=float, default=80.0, help="side of the ocean's grid, m")
parser.add_argument("--camera-height", type=float, default=9.0, help="m above the mean level")
parser.add_argument("--pitch", type=float, default=11.0, help="camera's look below level, deg")
args = parser.parse_args(argv)

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


os.makedirs(args.out, exist_ok=True)
sys.path.insert(0, os.path.abspath(args.addons))
module = addon_utils.enable("ocean_addon", default_set=True)
check(module is not None and "ocean_addon" in bpy.context.preferences.addons,
      "the add-on is enabled")

scene = bpy.context.scene
scene.render.fps, scene.render.fps_base = 24, 1.0
for obj in list(scene.objects):
    bpy.data.objects.remove(obj)

# Without the package on the path, the add-on says where to point it; then its preference does.
# (Where the package is installed on Blender's own path, e.g. /usr/lib/python3/dist-packages,
# there is no such case to check.)
if importlib.util.find_spec("ocean") is None:
    try:
        bpy.ops.mesh.spectral_ocean_add(grid=4)
        message = ""
    except RuntimeError as e:
        message = str(e)
    check("cannot import the Python package 'ocean'" in message and "package folder" in message,
          f"no package: '{message.strip()}'")
    for obj in list(scene.objects):
        bpy.data.objects.remove(obj)
else:
    print("(the package is importable before the add-on's preference is set: no such check)")
bpy.context.preferences.addons["ocean_addon"].preferences.package_path = args.package

# The ocean: the moderate preset at 128 texels on a grid (80 m by default); frame 30 is
# t = 30/24 s.
SIZE, FRAME = args.size, 30
check(bpy.ops.mesh.spectral_ocean_add(preset="moderate", size=SIZE, grid=args.grid)
      == {"FINISHED"}, "mesh.spectral_ocean_add")
obj = bpy.context.object
import ocean  # noqa: E402  (the add-on put the package folder on sys.path)

obj.ocean_sim.resolution = "128"
scene.frame_set(FRAME)
check(obj.ocean_sim.status == "",
      f"the frame change updates the ocean (status '{obj.ocean_sim.status}')")

mesh = obj.data
n = len(mesh.vertices)
co = np.empty(3 * n, dtype=np.float32)
mesh.vertices.foreach_get("co", co)
co = co.reshape(n, 3).astype(np.float64)
check(n == args.grid ** 2, f"{n} vertices, {args.grid}² asked")

# The package on its own: the same preset, stepped to the same time.
t = FRAME / 24.0
sim = ocean.Simulator(ocean.Preset("moderate").updated(resolution=128))
sim.step(t)
xz = np.column_stack([co[:, 0], -co[:, 1]])  # Blender (X, Y, Z) is the library's (x, −z, y)
h = sim.heights(xz)
error = np.abs(co[:, 2] - h)
# Each vertex is a rest point p moved to p + D(p) at height h(p); heights() inverts that map
# (M.7.7, stopping at 1e-6 m) at the vertex's own position, read back as float32. The vertex's
# x and z are rounded to float32, half an ulp, at most 2^-23·|x|: 5.2e-6 m at |x| < 44 m (the
# 80 m grid and its chop), which moves the height by at most |slope| times that (|slope| < 1
# here); its height is rounded by 2^-24·4 m = 2.4e-7 m (|h| < 4 m); the inverse's stop adds
# 1e-6 m times the slope. So 1e-5 m bounds the difference (scaled with a wider grid) wherever the
# inverse finds this vertex's rest point; a fold (two rest points landing on one position) could
# pick the other, and none is allowed here.
reach = SIZE / 2 + 4.0  # the farthest coordinate, m: the grid's half side and the chop
TOL = 1e-5 * max(1.0, reach / 44.0)
check(error.max() < TOL, f"vertex heights vs Simulator.heights: max |Δ| {error.max():.2e} m "
      f"(mean {error.mean():.2e}) over {n} vertices, tolerance {TOL:g} m")

# The vertices themselves: rest point + Simulator.displacements, Z up, stored as float32: half an
# ulp, at most 2^-23 times the farthest coordinate.
rest = np.linspace(-SIZE / 2, SIZE / 2, args.grid)
rx, ry = np.meshgrid(rest, rest)
rest_xz = np.column_stack([rx.ravel(), -ry.ravel()])
d = sim.displacements(rest_xz)
moved_xz = rest_xz + d[:, [0, 2]]
expected = np.column_stack([moved_xz[:, 0], -moved_xz[:, 1], d[:, 1]])
ulp_tol = 2.0 ** -23 * reach
check(np.abs(co - expected).max() <= ulp_tol,
      f"vertices vs rest + Simulator.displacements: max |Δ| {np.abs(co - expected).max():.2e} m, "
      f"half an ulp {ulp_tol:.1e} m")
moved = np.hypot(d[:, 0], d[:, 2])
check(np.std(co[:, 2]) > 0.1 and moved.max() > 0.05,
      f"the grid is displaced: std of heights {np.std(co[:, 2]):.3f} m, largest horizontal "
      f"move {moved.max():.3f} m")

# The normal attribute: the library's surface normal at each vertex, Y up turned to Z up.
normal = np.empty(3 * n, dtype=np.float32)
mesh.attributes["ocean_normal"].data.foreach_get("vector", normal)
normal = normal.reshape(n, 3)
expected = sim.surface(moved_xz)["normal"]
expected = np.column_stack([expected[:, 0], -expected[:, 2], expected[:, 1]])
# The same query at the same points, stored as float32: half an ulp of a unit component, 6e-8.
check(np.abs(normal - expected).max() < 1e-7,
      f"ocean_normal vs Simulator.surface: max |Δ| {np.abs(normal - expected).max():.2e}")
# Against the mesh's own vertex normals, which see the surface through the grid's spacing only.
mesh.calc_normals_split()
vertex_normal = np.empty(3 * n, dtype=np.float32)
mesh.vertices.foreach_get("normal", vertex_normal)
dots = np.sum(normal * vertex_normal.reshape(n, 3), axis=1)
check(np.median(dots) > 0.99,
      f"ocean_normal · the mesh's vertex normal: median {np.median(dots):.4f}, "
      f"minimum {dots.min():.3f}")
foam = np.empty(n, dtype=np.float32)
mesh.attributes["ocean_foam"].data.foreach_get("value", foam)
check(foam.min() >= 0.0 and foam.max() <= 1.0,
      f"ocean_foam in [0, 1]: [{foam.min():.3g}, {foam.max():.3g}], mean {foam.mean():.4f}")

# Foam on a grid whose vertices are texels of both cascades: the storm on 32 texels of 64 m and
# 16 m (2 m and 0.5 m apart) under a 64 m grid of 33² vertices 2 m apart. Bilinear sampling at a
# texel is the texel's value (M.7.6), so each vertex's foam is R.11's Σ_c w_c·foam_c of the
# texels the vertex starts at: (col, row) = (x, z)/(L_c/N) mod N with z = −Y. The preset is made
# anew by the change (a new simulator stepped once, as the one here), so the foam of both has
# the same history. The check fails on a swapped row and column or a flipped axis.
storm = os.path.join(args.out, "storm_64m.json")
aligned = ocean.Preset("storm").updated(resolution=32, cascades_m=[64.0, 16.0])
aligned.save(storm)
saved = (obj.ocean_sim.size, obj.ocean_sim.grid, obj.ocean_sim.resolution)
obj.ocean_sim.preset, obj.ocean_sim.preset_file = "FILE", storm
obj.ocean_sim.size, obj.ocean_sim.grid, obj.ocean_sim.resolution = 64.0, 33, "PRESET"
check(bpy.ops.object.spectral_ocean_update() == {"FINISHED"}, "the storm from a preset file")
foam = np.empty(33 * 33, dtype=np.float32)
mesh.attributes["ocean_foam"].data.foreach_get("value", foam)
storm_sim = ocean.Simulator(aligned)
storm_sim.step(t)
s = np.linspace(-32.0, 32.0, 33)
bx, by = np.meshgrid(s, s)
x, z = bx.ravel(), -by.ravel()
expected = np.zeros(33 * 33)
for c, (w, patch) in enumerate(zip(storm_sim.foam_weights, storm_sim.patch_sizes)):
    texel = patch / 32
    col = np.round(x / texel).astype(int) % 32
    row = np.round(z / texel).astype(int) % 32
    expected += w * storm_sim.fields(c)["foam"][row, col]
# float32 storage of values below 1: half an ulp, 6e-8; the weights' sum rounds the same way.
check(np.abs(foam - expected).max() < 2e-7 and expected.max() > 0.05,
      f"ocean_foam at texel vertices vs Σ w_c·foam_c: max |Δ| {np.abs(foam - expected).max():.2e}"
      f" (foam up to {expected.max():.3f}, mean {expected.mean():.4f})")
obj.ocean_sim.preset = "moderate"
obj.ocean_sim.size, obj.ocean_sim.grid, obj.ocean_sim.resolution = saved

# Bad values reach the user as the library's one-line message, reported by the operator.
obj.ocean_sim.override_sea = True
obj.ocean_sim.wind_speed = 500.0
try:
    bpy.ops.object.spectral_ocean_update()
    message = ""
except RuntimeError as e:  # an operator's ERROR report raises here
    message = str(e)
check("wind_speed" in message and "out of range" in message,
      f"wind speed 500 m/s reported: '{message.strip()}'")
check("wind_speed" in obj.ocean_sim.status, "and kept as the object's status")
obj.ocean_sim.override_sea = False
obj.ocean_sim.preset, obj.ocean_sim.preset_file = "FILE", "/nonexistent/sea.json"
try:
    bpy.ops.object.spectral_ocean_update()
    message = ""
except RuntimeError as e:
    message = str(e)
check("/nonexistent/sea.json" in message, f"a missing preset file reported: '{message.strip()}'")
obj.ocean_sim.preset = "moderate"
check(bpy.ops.object.spectral_ocean_update() == {"FINISHED"} and obj.ocean_sim.status == "",
      "the update succeeds again once the values are fixed")

# The bake: two frames from frame 30 through ocean.bake, EXR; first a folder relative to the
# .blend file, which is not saved here.
scene.frame_start, scene.frame_end = FRAME, FRAME + 1
try:
    bpy.ops.object.spectral_ocean_bake()
    message = ""
except RuntimeError as e:
    message = str(e)
check("relative to the .blend file" in message, f"a relative bake folder reported: "
      f"'{message.strip()}'")
obj.ocean_sim.bake_path = os.path.join(args.out, "bake")
check(bpy.ops.object.spectral_ocean_bake() == {"FINISHED"}, "object.spectral_ocean_bake")
with open(os.path.join(args.out, "bake", "manifest.json")) as f:
    manifest = json.load(f)
exr = [name for frame in manifest["frames"] for name in frame["files"] if name.endswith(".exr")]
check(manifest["complete"] and manifest["frame_count"] == 2 and
      abs(manifest["frames"][0]["time_s"] - t) < 1e-12 and
      all(os.path.isfile(os.path.join(args.out, "bake", e)) for e in exr) and len(exr) >= 2,
      f"bake: complete {manifest['complete']}, {manifest['frame_count']} frames from "
      f"t = {manifest['frames'][0]['time_s']:.4f} s, {len(exr)} EXR files")

# A picture: Cycles on the CPU, a camera above the water looking along +Y, the sun ahead.
scene.frame_set(FRAME)
camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
scene.collection.objects.link(camera)
camera.location = (0.0, -SIZE / 2 + 2.0, args.camera_height)
camera.rotation_euler = (np.radians(90.0 - args.pitch), 0.0, 0.0)
camera.data.lens = 24.0
scene.camera = camera
sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
sun.data.energy = 3.0
sun.rotation_euler = (np.radians(70.0), 0.0, np.radians(180.0))
scene.collection.objects.link(sun)
world = bpy.data.worlds.new("Sky")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.35, 0.55, 0.85, 1.0)
scene.world = world
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = args.samples
scene.cycles.use_denoising = False
scene.render.resolution_x, scene.render.resolution_y = args.width, args.height
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "PNG"
scene.render.filepath = os.path.join(args.out, "render.png")
bpy.ops.render.render(write_still=True)
image = bpy.data.images.load(scene.render.filepath)
pixels = np.array(image.pixels[:]).reshape(args.height, args.width, 4)[::-1]  # top row first
luma = pixels[..., :3] @ np.array([0.2126, 0.7152, 0.0722])
top, bottom = luma[: args.height // 4].mean(), luma[-args.height // 4:].mean()
check(np.isfinite(luma).all() and luma.std() > 0.02 and top - bottom > 0.1,
      f"render.png {args.width}×{args.height}: luminance std {luma.std():.3f}, sky (top quarter) "
      f"{top:.3f} vs sea (bottom quarter) {bottom:.3f}")
sea = luma[-args.height // 2:]
check(sea.std() > 0.005, f"the sea is not uniform: luminance std {sea.std():.4f} in the lower half")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
