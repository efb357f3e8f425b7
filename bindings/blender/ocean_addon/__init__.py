"""Spectral Ocean: a Blender add-on drawing the `ocean` package's sea on a grid mesh.

A thin client of the Python package (docs/blender.md): the add-on builds a preset from the
object's properties (`ocean.Preset(name).updated({...})`), steps an `ocean.Simulator` to the
scene's time on every frame change and moves the mesh's vertices by the library's displacement
of their rest points (`Simulator.displacements`, docs/math.md M.7.6). Two point attributes carry
the library's shading fields: `ocean_normal` (`Simulator.surface`, M.7.11) and `ocean_foam` (the
cascades' foam maps combined as the renderer combines them, docs/rendering.md R.11). The bake
operator calls `ocean.bake` with the EXR format. No wave physics lives here.

Axes: the library is Y-up with the sea in the (x, z) plane; Blender is Z-up. A library point
(x, y, z) is Blender's (x, −z, y) in the object's local space (a rotation, so handedness and
wind directions are kept; the glTF convention).
"""

import concurrent.futures
import os
import sys

import bpy
import numpy as np
from bpy.app.handlers import persistent
from bpy.props import (BoolProperty, EnumProperty, FloatProperty, IntProperty, PointerProperty,
                       StringProperty)

bl_info = {
    "name": "Spectral Ocean",
    "author": "The ocean project",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Add > Mesh > Spectral Ocean; Properties > Object > Spectral Ocean",
    "description": "A sea surface from the ocean library's spectral simulation (Python package "
                   "`ocean`): displacement, normal and foam each frame, EXR bakes",
    "category": "Object",
}

_PRESETS = (("calm", "Calm", "presets/calm.json"),
            ("moderate", "Moderate", "presets/moderate.json"),
            ("storm", "Storm", "presets/storm.json"),
            ("FILE", "Preset file", "A preset file (.json) of your own"))


def _package():
    """The `ocean` package, imported from sys.path or the add-on preferences' folder."""
    if "ocean" in sys.modules:
        return sys.modules["ocean"]
    addon = bpy.context.preferences.addons.get(__name__)
    folder = bpy.path.abspath(addon.preferences.package_path) if addon else ""
    if folder and folder not in sys.path:
        sys.path.insert(0, folder)
    try:
        import ocean
    except ImportError as e:
        raise RuntimeError(
            f"cannot import the Python package 'ocean' ({e}): set the add-on's package folder "
            "to the folder holding ocean/ (e.g. build/release/python) or start Blender with "
            "PYTHONPATH set to it") from None
    return ocean


class OceanPreferences(bpy.types.AddonPreferences):
    bl_idname = __name__

    package_path: StringProperty(
        name="Package folder", subtype="DIR_PATH",
        description="The folder holding the package ocean/ (e.g. build/release/python); empty: "
                    "the package must already be importable (PYTHONPATH)")

    def draw(self, context):
        self.layout.prop(self, "package_path")


class OceanSettings(bpy.types.PropertyGroup):
    """An object's sea: which preset, what it changes, and the mesh that shows it."""
    enabled: BoolProperty(name="Spectral ocean", default=False,
                          description="This object is a spectral ocean, updated on frame change")
    preset: EnumProperty(name="Preset", items=[(k, n, d) for k, n, d in _PRESETS],
                         default="moderate", description="The sea state to start from")
    preset_file: StringProperty(name="Preset file", subtype="FILE_PATH",
                                description="A preset document (.json), as `ocean --preset FILE`")
    override_sea: BoolProperty(
        name="Wind sea from these values", default=False,
        description="Replace the preset's wind speed, fetch and direction")
    # Hard bounds wider than the library's ranges on purpose: the library checks every value
    # and its message names the key and the range (shown as the error).
    wind_speed: FloatProperty(name="Wind speed", default=10.0, min=0.0, max=1000.0,
                              soft_min=0.5, soft_max=40.0, unit="VELOCITY",
                              description="U10, m/s (sea.wind_sea.wind_speed_mps)")
    fetch_km: FloatProperty(name="Fetch", default=100.0, min=0.0, max=1e6, soft_min=1.0,
                            soft_max=1000.0, description="Fetch, km (sea.wind_sea.fetch_m)")
    direction_deg: FloatProperty(
        name="Direction", default=0.0, min=-3600.0, max=3600.0,
        description="Wind direction, degrees from the library's +x axis toward +z, i.e. from "
                    "Blender's +X toward −Y (sea.wind_sea.direction_deg)")
    override_choppiness: BoolProperty(name="Choppiness", default=False,
                                      description="Replace the preset's choppiness")
    choppiness: FloatProperty(name="Choppiness", default=1.0, min=-100.0, max=100.0,
                              soft_min=0.0, soft_max=2.0,
                              description="λ of the horizontal displacement (choppiness)")
    resolution: EnumProperty(
        name="Resolution", default="PRESET",
        items=[("PRESET", "Preset's", "The preset's resolution"), ("32", "32", ""),
               ("64", "64", ""), ("128", "128", ""), ("256", "256", ""), ("512", "512", "")],
        description="Texels per side of every cascade")
    seed: IntProperty(name="Seed", default=-1, min=-1,
                      description="Random seed of the spectrum's phases; -1: the preset's")
    size: FloatProperty(name="Size", default=200.0, min=0.01, soft_max=5000.0, unit="LENGTH",
                        description="Side of the square grid, m")
    grid: IntProperty(name="Grid", default=128, min=2, max=2048,
                      description="Vertices per side of the grid")
    time_offset: FloatProperty(name="Time offset", default=0.0, unit="TIME_ABSOLUTE",
                               description="Simulation time at frame 0, s")
    bake_path: StringProperty(name="Bake folder", subtype="DIR_PATH", default="//ocean_bake",
                              description="Where the bake writes its EXR files and manifest.json")
    status: StringProperty(name="Status", default="",
                           description="The last update's error, empty when it succeeded")

    def changes(self):
        """The preset keys these properties set, as `Preset.updated` takes them."""
        out = {}
        if self.override_sea:
            out["sea.wind_sea.wind_speed_mps"] = self.wind_speed
            out["sea.wind_sea.fetch_m"] = self.fetch_km * 1000.0
            out["sea.wind_sea.direction_deg"] = self.direction_deg
        if self.override_choppiness:
            out["choppiness"] = self.choppiness
        if self.resolution != "PRESET":
            out["resolution"] = int(self.resolution)
        if self.seed >= 0:
            out["seed"] = self.seed
        return out


def preset_of(settings):
    """The ocean.Preset of an object's settings; ValueError/OSError name the bad value."""
    ocean = _package()
    if settings.preset == "FILE":
        path = bpy.path.abspath(settings.preset_file)
        if not settings.preset_file:
            raise ValueError("preset file: none given (choose a .json preset file)")
        base = ocean.Preset(path)
    else:
        base = ocean.Preset(settings.preset)
    return base.updated(settings.changes())


def scene_time(scene, settings, frame=None):
    """Simulation time of a frame, s: time offset + frame / fps."""
    fps = scene.render.fps / scene.render.fps_base
    return settings.time_offset + (scene.frame_current if frame is None else frame) / fps


def rest_points(settings):
    """The grid's undisplaced points (x, z), m, row-major, as the library's (n, 2) array."""
    n = settings.grid
    s = np.linspace(-0.5 * settings.size, 0.5 * settings.size, n)
    x, y = np.meshgrid(s, s)  # Blender's local (X, Y); the library's z is −Y
    return np.column_stack([x.ravel(), -y.ravel()])


def sample_wrapped(field, patch_m, xz):
    """A cascade map [row][col] sampled bilinearly with wrap addressing at world (x, z) (M.7.6:
    texel (col, row) is the point that starts at (col, row)·L/N), as a GPU samples it."""
    n = field.shape[0]
    u = xz[:, 0] * (n / patch_m)
    v = xz[:, 1] * (n / patch_m)
    c0, r0 = np.floor(u), np.floor(v)
    fu, fv = u - c0, v - r0
    c0 = c0.astype(np.int64) % n
    r0 = r0.astype(np.int64) % n
    c1, r1 = (c0 + 1) % n, (r0 + 1) % n
    f = np.asarray(field, dtype=np.float64)
    return ((1 - fv) * ((1 - fu) * f[r0, c0] + fu * f[r0, c1]) +
            fv * ((1 - fu) * f[r1, c0] + fu * f[r1, c1]))


_WORKERS = os.cpu_count() or 1
_pool = []  # the thread pool, made on first use and shut down by unregister()


def in_parallel(query, xz):
    """query(xz) split over the cores: the package releases the GIL while it queries, and
    queries of one simulator run at once (docs/python.md, "Height queries and threads")."""
    if not _pool:
        _pool.append(concurrent.futures.ThreadPoolExecutor(max_workers=_WORKERS))
    parts = list(_pool[0].map(query, np.array_split(xz, max(1, min(len(xz), _WORKERS)))))
    if isinstance(parts[0], dict):
        return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
    return np.concatenate(parts)


def foam_at(sim, xz):
    """Foam coverage at undisplaced points as the renderer draws it (docs/rendering.md R.11):
    Σ_c w_c·foam_c with the breaking source's weights, else 1 − Π_c(1 − foam_c/(1 + 0.6c)).
    None when the preset's outputs carry no foam."""
    weights = sim.foam_weights
    maps = []
    for c, patch in enumerate(sim.patch_sizes):
        fields = sim.fields(c)
        if "foam" not in fields:
            return None
        maps.append(sample_wrapped(fields["foam"], patch, xz))
    if weights:
        return np.clip(sum(w * f for w, f in zip(weights, maps)), 0.0, 1.0)
    none = np.ones(len(xz))
    for c, f in enumerate(maps):
        none *= 1.0 - f / (1.0 + 0.6 * c)
    return np.clip(1.0 - none, 0.0, 1.0)


class _Cache:
    """One simulator per object, remade when the object's preset document changes."""
    sims = {}

    @classmethod
    def simulator(cls, obj, preset):
        key = obj.name
        document = preset.to_json()
        held = cls.sims.get(key)
        if held is None or held[0] != document:
            held = (document, _package().Simulator(preset))
            cls.sims[key] = held
        return held[1]

    @classmethod
    def prune(cls):
        """Drops the simulators of objects that are gone (deleted or renamed)."""
        for key in [k for k in cls.sims if k not in bpy.data.objects]:
            del cls.sims[key]

    @classmethod
    def clear(cls):
        cls.sims.clear()


def build_grid(mesh, settings):
    """Makes `mesh` the settings' flat grid (vertices row-major as rest_points, quads)."""
    n = settings.grid
    xz = rest_points(settings)
    co = np.column_stack([xz[:, 0], -xz[:, 1], np.zeros(len(xz))])
    r, c = np.meshgrid(np.arange(n - 1), np.arange(n - 1), indexing="ij")
    a = (r * n + c).ravel()
    quads = np.column_stack([a, a + 1, a + 1 + n, a + n])
    mesh.clear_geometry()
    mesh.vertices.add(len(co))
    mesh.vertices.foreach_set("co", co.astype(np.float32).ravel())
    mesh.loops.add(quads.size)
    mesh.loops.foreach_set("vertex_index", quads.astype(np.int32).ravel())
    mesh.polygons.add(len(quads))
    mesh.polygons.foreach_set("loop_start", np.arange(0, quads.size, 4, dtype=np.int32))
    mesh.polygons.foreach_set("loop_total", np.full(len(quads), 4, dtype=np.int32))
    mesh.polygons.foreach_set("use_smooth", np.ones(len(quads), dtype=bool))
    mesh.update(calc_edges=True)
    mesh.validate()


def _attribute(mesh, name, kind):
    attribute = mesh.attributes.get(name)
    if attribute is not None and (attribute.data_type != kind or attribute.domain != "POINT"):
        mesh.attributes.remove(attribute)
        attribute = None
    return attribute or mesh.attributes.new(name, kind, "POINT")


def update_object(obj, scene):
    """Steps the object's simulator to the scene's time and moves its vertices; raises
    ValueError, OSError or RuntimeError with the library's one-line message."""
    settings = obj.ocean_sim
    preset = preset_of(settings)
    sim = _Cache.simulator(obj, preset)
    mesh = obj.data
    if len(mesh.vertices) != settings.grid ** 2:
        build_grid(mesh, settings)
    xz = rest_points(settings)
    sim.step(scene_time(scene, settings))
    d = in_parallel(sim.displacements, xz)  # (Dx, h, Dz) of each rest point, m
    moved = xz + d[:, [0, 2]]  # where the library draws it
    co = np.column_stack([moved[:, 0], -moved[:, 1], d[:, 1]])
    mesh.vertices.foreach_set("co", co.astype(np.float32).ravel())
    normal = in_parallel(sim.surface, moved)["normal"]  # (nx, ny, nz), y up
    _attribute(mesh, "ocean_normal", "FLOAT_VECTOR").data.foreach_set(
        "vector", np.column_stack([normal[:, 0], -normal[:, 2], normal[:, 1]])
        .astype(np.float32).ravel())
    foam = foam_at(sim, xz)
    if foam is not None:
        _attribute(mesh, "ocean_foam", "FLOAT").data.foreach_set(
            "value", foam.astype(np.float32))
    elif mesh.attributes.get("ocean_foam") is not None:  # a preset without foam: none is shown
        mesh.attributes.remove(mesh.attributes["ocean_foam"])
    mesh.update()
    settings.status = ""


def _errors():
    """The exceptions that carry the library's or the add-on's one-line message."""
    return (ValueError, OSError, RuntimeError, TypeError, KeyError, NotImplementedError)


@persistent
def on_frame_change(scene, depsgraph=None):
    _Cache.prune()
    for obj in scene.objects:
        if obj.type == "MESH" and obj.ocean_sim.enabled:
            try:
                update_object(obj, scene)
            except _errors() as e:
                obj.ocean_sim.status = str(e)
                print(f"Spectral Ocean: {obj.name}: {e}", file=sys.stderr)


@persistent
def on_load(filename, *rest):
    """A file opened: its oceans start simulators of their own."""
    _Cache.clear()


def water_material():
    """A water material reading the attributes: foam over a dark, glossy water."""
    mat = bpy.data.materials.new("Spectral Ocean Water")
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    bsdf = nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (0.004, 0.03, 0.05, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.05
    foam = nodes.new("ShaderNodeAttribute")
    foam.attribute_name = "ocean_foam"
    mix = nodes.new("ShaderNodeMixRGB")
    mix.inputs["Color1"].default_value = (0.004, 0.03, 0.05, 1.0)
    mix.inputs["Color2"].default_value = (0.85, 0.85, 0.85, 1.0)
    links.new(foam.outputs["Fac"], mix.inputs["Fac"])
    links.new(mix.outputs["Color"], bsdf.inputs["Base Color"])
    return mat


class OCEAN_OT_add(bpy.types.Operator):
    """Add a spectral ocean: a grid displaced by the ocean library's simulation"""
    bl_idname = "mesh.spectral_ocean_add"
    bl_label = "Spectral Ocean"
    bl_options = {"REGISTER", "UNDO"}

    preset: EnumProperty(name="Preset", items=[(k, n, d) for k, n, d in _PRESETS[:3]],
                         default="moderate")
    size: FloatProperty(name="Size", default=200.0, min=0.01, unit="LENGTH")
    grid: IntProperty(name="Grid", default=128, min=2, max=2048)

    def execute(self, context):
        mesh = bpy.data.meshes.new("Spectral Ocean")
        obj = bpy.data.objects.new("Spectral Ocean", mesh)
        context.collection.objects.link(obj)
        settings = obj.ocean_sim
        settings.preset, settings.size, settings.grid = self.preset, self.size, self.grid
        build_grid(mesh, settings)
        mesh.materials.append(water_material())
        settings.enabled = True
        for o in context.selected_objects:
            o.select_set(False)
        obj.select_set(True)
        context.view_layer.objects.active = obj
        try:
            update_object(obj, context.scene)
        except _errors() as e:
            settings.status = str(e)
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        return {"FINISHED"}


class _OnOcean:
    @classmethod
    def poll(cls, context):
        obj = context.object
        return obj is not None and obj.type == "MESH" and obj.ocean_sim.enabled


class OCEAN_OT_update(_OnOcean, bpy.types.Operator):
    """Recompute the ocean at the current frame (after changing its grid or preset)"""
    bl_idname = "object.spectral_ocean_update"
    bl_label = "Update Ocean"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        obj = context.object
        try:
            build_grid(obj.data, obj.ocean_sim)
            update_object(obj, context.scene)
        except _errors() as e:
            obj.ocean_sim.status = str(e)
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        return {"FINISHED"}


class OCEAN_OT_bake(_OnOcean, bpy.types.Operator):
    """Bake the scene's frame range to EXR files with `ocean.bake` (displacement and maps per
    cascade and frame, and manifest.json)"""
    bl_idname = "object.spectral_ocean_bake"
    bl_label = "Bake Ocean to EXR"

    def execute(self, context):
        settings, scene = context.object.ocean_sim, context.scene
        if not settings.bake_path:
            self.report({"ERROR"}, "bake folder: none given")
            return {"CANCELLED"}
        if settings.bake_path.startswith("//") and not bpy.data.filepath:
            self.report({"ERROR"}, f"bake folder '{settings.bake_path}' is relative to the "
                        ".blend file, which is not saved: save it or give an absolute folder")
            return {"CANCELLED"}
        folder = bpy.path.abspath(settings.bake_path)
        frames = scene.frame_end - scene.frame_start + 1
        try:
            ocean = _package()
            ocean.bake(preset_of(settings), folder, frames=frames,
                       fps=scene.render.fps / scene.render.fps_base,
                       time=scene_time(scene, settings, scene.frame_start), formats=["exr"])
        except _errors() as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        self.report({"INFO"}, f"baked {frames} frames to {folder}")
        return {"FINISHED"}


class OCEAN_PT_panel(bpy.types.Panel):
    bl_label = "Spectral Ocean"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "object"

    @classmethod
    def poll(cls, context):
        return context.object is not None and context.object.type == "MESH"

    def draw(self, context):
        settings = context.object.ocean_sim
        layout = self.layout
        layout.prop(settings, "enabled")
        if not settings.enabled:
            return
        layout.prop(settings, "preset")
        if settings.preset == "FILE":
            layout.prop(settings, "preset_file")
        layout.prop(settings, "override_sea")
        column = layout.column()
        column.enabled = settings.override_sea
        column.prop(settings, "wind_speed")
        column.prop(settings, "fetch_km")
        column.prop(settings, "direction_deg")
        row = layout.row()
        row.prop(settings, "override_choppiness", text="")
        sub = row.row()
        sub.enabled = settings.override_choppiness
        sub.prop(settings, "choppiness")
        layout.prop(settings, "resolution")
        layout.prop(settings, "seed")
        layout.prop(settings, "size")
        layout.prop(settings, "grid")
        layout.prop(settings, "time_offset")
        layout.operator(OCEAN_OT_update.bl_idname)
        layout.prop(settings, "bake_path")
        layout.operator(OCEAN_OT_bake.bl_idname)
        if settings.status:
            layout.label(text=settings.status, icon="ERROR")


def _menu(self, context):
    self.layout.operator(OCEAN_OT_add.bl_idname, icon="MOD_OCEAN")


_classes = (OceanPreferences, OceanSettings, OCEAN_OT_add, OCEAN_OT_update, OCEAN_OT_bake,
            OCEAN_PT_panel)


def register():
    for cls in _classes:
        bpy.utils.register_class(cls)
    bpy.types.Object.ocean_sim = PointerProperty(type=OceanSettings)
    bpy.types.VIEW3D_MT_mesh_add.append(_menu)
    bpy.app.handlers.frame_change_post.append(on_frame_change)
    bpy.app.handlers.load_post.append(on_load)


def unregister():
    bpy.app.handlers.load_post.remove(on_load)
    bpy.app.handlers.frame_change_post.remove(on_frame_change)
    bpy.types.VIEW3D_MT_mesh_add.remove(_menu)
    del bpy.types.Object.ocean_sim
    for cls in reversed(_classes):
        bpy.utils.unregister_class(cls)
    _Cache.clear()
    while _pool:
        _pool.pop().shutdown()
