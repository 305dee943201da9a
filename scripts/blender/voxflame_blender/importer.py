"""The importer of the voxflame add-on (and of scripts/blender/voxflame_import.py): brings a volume
written by `voxflame render -o OUT.vdb`, or a sequence of them written by `voxflame animate -o
frames/%04d.vdb`, into the current scene and sets it up as voxflame shows it: the `density` and
`color` grids drive an emission-and-absorption material that follows the preset's brightness and
opacity, the preset's mesh becomes a faint shell around it, and a camera takes the preset's place.
The preset comes from the VDB's own metadata.

Everything is placed in the mesh file's coordinates (where voxflame writes the volume), under an
empty turned 90 degrees about X so that a Y-up mesh stands upright in Blender's Z-up world.
"""

import json
import math
import os
import re
import struct

import bpy
from mathutils import Matrix, Vector

# Emission and absorption per unit of normalised density, per bounding-sphere radius of the grid:
# chosen so that a preset at its own brightness and opacity looks about as bright and as dense in
# Cycles as in voxflame (voxflame tone-maps the log density per pixel; Cycles integrates the
# volume's log density along each ray, so the two agree in where light is, not exactly in how much).
EMISSION_PER_BRIGHTNESS = 20.0
ABSORPTION_PER_OPACITY = 1.0


class ImportFailure(Exception):
    """What went wrong, in words for the user (the operator reports it, the script prints it)."""


def fail(message):
    raise ImportFailure(message)


# The VDB file header: magic, file version, library version, grid offsets flag and UUID, then the
# file-level metadata (count, then name, type name and value, each as a 32-bit length and bytes).
# Read by hand when the OpenVDB Python module is missing (Debian's Blender has none built in).
def read_vdb_file_metadata(path):
    with open(path, "rb") as f:
        def read(count):
            data = f.read(count)
            if len(data) != count:
                raise ValueError("the file ends inside its header")
            return data

        def read_string():
            (length,) = struct.unpack("<I", read(4))
            return read(length)

        (magic,) = struct.unpack("<q", read(8))
        if magic != 0x56444220:
            raise ValueError("not a VDB file")
        (file_version,) = struct.unpack("<I", read(4))
        if file_version < 212:
            raise ValueError("VDB file version %d is older than this reader knows" % file_version)
        read(8 + 1 + 36)  # library version, grid offsets flag, UUID
        (count,) = struct.unpack("<i", read(4))
        metadata = {}
        for _ in range(count):
            name = read_string().decode("utf-8")
            type_name = read_string().decode("utf-8")
            value = read_string()
            if type_name == "string":
                metadata[name] = value.decode("utf-8")
        return metadata


def read_preset(path):
    try:
        import pyopenvdb  # Debian: python3-openvdb
        metadata = pyopenvdb.readMetadata(path)
        source = "pyopenvdb"
    except ImportError:
        try:
            metadata = read_vdb_file_metadata(path)
        except (OSError, ValueError) as error:
            fail("cannot read '%s': %s" % (path, error))
        source = "the VDB header"
    if "voxflame_preset" not in metadata:
        fail("'%s' carries no voxflame preset (no voxflame_preset metadata); write it with voxflame render -o OUT.vdb"
             % path)
    return json.loads(metadata["voxflame_preset"]), source


def srgb_to_linear(hex_colour):
    hex_colour = hex_colour.lstrip("#")
    channels = [int(hex_colour[i:i + 2], 16) / 255.0 for i in (0, 2, 4)]
    return [c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4 for c in channels]


def import_volume(path, parent, sequence=False):
    """The VDB as a volume object; with `sequence`, the numbered files beside it (frames/0000.vdb,
    0001.vdb, ...) as one animated volume, Blender's frame 1 showing the first of them."""
    before = set(bpy.data.objects)
    bpy.ops.object.volume_import(filepath=path, directory=os.path.dirname(path),
                                 files=[{"name": os.path.basename(path)}], use_sequence_detection=sequence)
    added = [o for o in bpy.data.objects if o not in before and o.type == "VOLUME"]
    if not added:
        fail("Blender did not import '%s'" % path)
    volume = added[0]
    volume.data.grids.load()
    names = {grid.name for grid in volume.data.grids}
    if not {"density", "color"} <= names:
        fail("'%s' has the grids %s; voxflame writes density and color" % (path, sorted(names)))
    volume.name = "voxflame volume"
    volume.location = (0, 0, 0)
    volume.rotation_euler = (0, 0, 0)
    volume.parent = parent
    return volume


def import_mesh(path, parent):
    extension = os.path.splitext(path)[1].lower()
    before = set(bpy.data.objects)
    # No axis conversion: the mesh stays in its file's coordinates, like the volume.
    if extension == ".obj":
        bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z")
    elif extension == ".ply":
        bpy.ops.import_mesh.ply(filepath=path)
    elif extension == ".stl":
        bpy.ops.import_mesh.stl(filepath=path, axis_forward="Y", axis_up="Z")
    else:
        fail("Blender imports OBJ, PLY and STL meshes here, not '%s'; convert it or pass --mesh" % path)
    added = [o for o in bpy.data.objects if o not in before and o.type == "MESH"]
    if not added:
        fail("Blender read no mesh from '%s'" % path)
    mesh = added[0]
    mesh.name = "voxflame mesh"
    mesh.matrix_basis = Matrix.Identity(4)
    mesh.parent = parent
    return mesh


def mesh_bounds(mesh):
    points = [v.co for v in mesh.data.vertices]
    low = Vector((min(p.x for p in points), min(p.y for p in points), min(p.z for p in points)))
    high = Vector((max(p.x for p in points), max(p.y for p in points), max(p.z for p in points)))
    return low, high


def volume_bounds(volume):
    corners = [Vector(c) for c in volume.bound_box]
    return (Vector((min(c.x for c in corners), min(c.y for c in corners), min(c.z for c in corners))),
            Vector((max(c.x for c in corners), max(c.y for c in corners), max(c.z for c in corners))))


def grid_box(low, high, resolution, margin=1):
    """voxflame's grid over the mesh's bounds (core::gridOverBox): cubic voxels, `resolution` of
    them along the longest axis including a margin of one voxel on each side, centred on the box."""
    extent = high - low
    voxel = max(extent) / (resolution - 2 * margin)
    centre = (low + high) / 2
    size = Vector([min(resolution, max(1, math.ceil(extent[a] / voxel - 1e-9)) + 2 * margin) * voxel
                   for a in range(3)])
    return centre - size / 2, centre + size / 2


def place_camera(preset_camera, low, high, aspect, parent, scene):
    """The camera of core::orbitCamera: it orbits the target about the Y axis of the mesh's frame,
    at `distance` radii of the grid's bounding sphere."""
    radius = 0.5 * (high - low).length
    centre = (low + high) / 2
    azimuth = math.radians(preset_camera.get("azimuth_deg", 30.0))
    elevation = math.radians(preset_camera.get("elevation_deg", 15.0))
    roll = math.radians(preset_camera.get("roll_deg", 0.0))
    to_eye = Vector((math.cos(elevation) * math.sin(azimuth), math.sin(elevation),
                     math.cos(elevation) * math.cos(azimuth)))
    up_from_angles = Vector((-math.sin(elevation) * math.sin(azimuth), math.cos(elevation),
                             -math.sin(elevation) * math.cos(azimuth)))
    target = centre + Vector(preset_camera.get("target", [0, 0, 0])) * radius
    eye = target + preset_camera.get("distance", 2.6) * radius * to_eye
    forward = -to_eye
    right0 = forward.cross(up_from_angles.normalized()).normalized()
    up0 = right0.cross(forward)
    right = math.cos(roll) * right0 + math.sin(roll) * up0
    up = math.cos(roll) * up0 - math.sin(roll) * right0

    data = bpy.data.cameras.new("voxflame camera")
    camera = bpy.data.objects.new("voxflame camera", data)
    scene.collection.objects.link(camera)
    # A Blender camera looks down its local -Z with +Y up.
    camera.matrix_basis = Matrix((
        (right.x, up.x, -forward.x, eye.x),
        (right.y, up.y, -forward.y, eye.y),
        (right.z, up.z, -forward.z, eye.z),
        (0, 0, 0, 1)))
    camera.parent = parent
    data.sensor_fit = "VERTICAL"
    if preset_camera.get("projection", "perspective") == "orthographic":
        data.type = "ORTHO"
        data.ortho_scale = preset_camera.get("ortho_height", 2.2) * radius * max(1.0, aspect)
    else:
        data.angle_y = math.radians(preset_camera.get("fov_deg", 35.0))
    to_centre = (centre - eye).length
    near, far = preset_camera.get("near", 0.0), preset_camera.get("far", 0.0)
    data.clip_start = near * radius if near > 0 else max(1e-4 * radius, to_centre - 1.01 * radius)
    data.clip_end = far * radius if far > 0 else to_centre + 1.01 * radius
    scene.camera = camera
    return camera, radius


def volume_material(tone, radius, emission_strength=1.0, absorption=1.0):
    material = bpy.data.materials.new("voxflame volume")
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    density = nodes.new("ShaderNodeAttribute")
    density.attribute_name = "density"
    color = nodes.new("ShaderNodeAttribute")
    color.attribute_name = "color"
    # Emission follows brightness and exposure, absorption follows opacity; both per radius, so a
    # mesh modelled in millimetres looks like one modelled in metres.
    brightness = tone.get("brightness", 4.0) * 2.0 ** tone.get("exposure", 0.0)
    emission_scale = nodes.new("ShaderNodeMath")
    emission_scale.operation = "MULTIPLY"
    emission_scale.inputs[1].default_value = emission_strength * EMISSION_PER_BRIGHTNESS * brightness / radius
    absorption_scale = nodes.new("ShaderNodeMath")
    absorption_scale.operation = "MULTIPLY"
    absorption_scale.inputs[1].default_value = absorption * ABSORPTION_PER_OPACITY * tone.get("opacity", 1.0) / radius
    emission = nodes.new("ShaderNodeEmission")
    absorption = nodes.new("ShaderNodeVolumeAbsorption")
    absorption.inputs["Color"].default_value = (0, 0, 0, 1)  # absorbs every channel alike
    both = nodes.new("ShaderNodeAddShader")
    links.new(density.outputs["Fac"], emission_scale.inputs[0])
    links.new(density.outputs["Fac"], absorption_scale.inputs[0])
    links.new(color.outputs["Color"], emission.inputs["Color"])
    links.new(emission_scale.outputs[0], emission.inputs["Strength"])
    links.new(absorption_scale.outputs[0], absorption.inputs["Density"])
    links.new(emission.outputs[0], both.inputs[0])
    links.new(absorption.outputs[0], both.inputs[1])
    links.new(both.outputs[0], output.inputs["Volume"])
    for i, node in enumerate([density, color, emission_scale, absorption_scale, emission, absorption, both, output]):
        node.location = (200 * i - 800, 0)
    return material


def shell_material(render, style, radius):
    """A faint shell: a clear surface whose rim glows in the preset's mesh colour (like voxflame's
    ghost), or a thin glowing wire."""
    material = bpy.data.materials.new("voxflame shell")
    material.use_nodes = True
    material.blend_method = "BLEND"
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Color"].default_value = (*srgb_to_linear(render.get("mesh_color", "#c2d3e8")), 1)
    strength = render.get("mesh_strength", 0.3)
    if style == "wire":
        # Seen from both sides and dense on a fine mesh: a quarter of the rim's strength stays faint.
        emission.inputs["Strength"].default_value = 0.25 * strength
        links.new(emission.outputs[0], output.inputs["Surface"])
        return material
    clear = nodes.new("ShaderNodeBsdfTransparent")
    rim = nodes.new("ShaderNodeLayerWeight")
    rim.inputs["Blend"].default_value = 0.2
    rim_power = nodes.new("ShaderNodeMath")
    rim_power.operation = "POWER"
    rim_power.inputs[1].default_value = 3.0
    rim_strength = nodes.new("ShaderNodeMath")
    rim_strength.operation = "MULTIPLY"
    rim_strength.inputs[1].default_value = strength
    glow = nodes.new("ShaderNodeAddShader")
    links.new(rim.outputs["Facing"], rim_power.inputs[0])
    links.new(rim_power.outputs[0], rim_strength.inputs[0])
    links.new(rim_strength.outputs[0], emission.inputs["Strength"])
    links.new(clear.outputs[0], glow.inputs[0])
    links.new(emission.outputs[0], glow.inputs[1])
    links.new(glow.outputs[0], output.inputs["Surface"])
    return material


def set_up_render(scene, background, samples=32):
    """Cycles on the CPU, emission and absorption only, voxflame's background, sRGB without a
    filmic curve; the resolution is left as it is."""
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False  # Debian's Blender is built without OpenImageDenoise
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.max_bounces = 8
    scene.cycles.volume_bounces = 0  # emission and absorption only: nothing scatters
    scene.cycles.transparent_max_bounces = 16
    scene.cycles.volume_step_rate = 1.0
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"  # voxflame writes sRGB without a filmic curve
    scene.view_settings.look = "None"
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.color_depth = "8"
    world = scene.world or bpy.data.worlds.new("voxflame background")
    scene.world = world
    world.use_nodes = True
    world_output = world.node_tree.nodes.get("Background")
    if world_output is None:
        world_output = world.node_tree.nodes.new("ShaderNodeBackground")
    world_output.inputs["Color"].default_value = (*srgb_to_linear(background), 1)
    world_output.inputs["Strength"].default_value = 1.0


class Imported:
    """What import_voxflame made, and a line that says so."""

    def __init__(self, root, volume, mesh, camera, preset, frames, summary):
        self.root, self.volume, self.mesh, self.camera = root, volume, mesh, camera
        self.preset, self.frames, self.summary = preset, frames, summary


def sequence_length(path):
    """How many numbered files follow `path`'s number in its folder without a gap (1 for a file
    without a number)."""
    folder, name = os.path.split(path)
    match = re.match(r"^(.*?)(\d+)(\.vdb)$", name, re.IGNORECASE)
    if not match:
        return 1
    prefix, digits, extension = match.groups()
    count, number = 0, int(digits)
    while os.path.isfile(os.path.join(folder, "%s%0*d%s" % (prefix, len(digits), number + count, extension))):
        count += 1
    return max(count, 1)


def import_voxflame(path, mesh_path=None, shell="auto", emission_strength=1.0, absorption=1.0, sequence=True,
                    scene=None, clear_scene=False):
    """Adds the volume (or the sequence starting at `path`), its shell and its camera to `scene`.
    `shell`: "auto" (off when the preset's render.mesh is off, else ghost), "ghost", "wire" or "off".
    Raises ImportFailure with a message for the user."""
    scene = scene or bpy.context.scene
    volume_path = os.path.abspath(path)
    if not os.path.isfile(volume_path):
        fail("no such file: '%s'" % path)
    preset, source = read_preset(volume_path)
    if clear_scene:
        for obj in list(scene.objects):
            bpy.data.objects.remove(obj, do_unlink=True)
    frames = sequence_length(volume_path) if sequence else 1
    root = bpy.data.objects.new("voxflame", None)
    scene.collection.objects.link(root)
    root.rotation_euler = (math.radians(90), 0, 0)  # Y up (the mesh's frame) to Blender's Z up
    volume = import_volume(volume_path, root, sequence=frames > 1)
    if frames > 1:
        # Frame 1 shows the first file, and the scene plays the whole sequence.
        volume.data.is_sequence = True
        volume.data.frame_start = 1
        volume.data.frame_duration = frames
        volume.data.frame_offset = int(re.search(r"(\d+)\.vdb$", volume_path, re.IGNORECASE).group(1)) - 1
        volume.data.sequence_mode = "CLIP"
        scene.frame_start = 1
        scene.frame_end = frames
        scene.frame_set(1)
        volume.data.grids.load()  # the first file's grids, under the sequence's own settings

    notes = []
    mesh_path = mesh_path or preset.get("mesh", {}).get("path", "")
    mesh = None
    if mesh_path.startswith("builtin:"):
        notes.append("the preset's mesh is %s, compiled into voxflame: give its file (the repository has it under "
                     "presets/%s) to show the shell and place the camera exactly; without it the camera frames the "
                     "volume's own bounds" % (mesh_path, mesh_path[len("builtin:"):]))
    elif mesh_path:
        if not os.path.isfile(mesh_path):
            fail("the preset's mesh '%s' is not there; give the mesh's file" % mesh_path)
        mesh = import_mesh(mesh_path, root)

    if mesh is not None:
        low, high = grid_box(*mesh_bounds(mesh), preset.get("grid", {}).get("resolution", 192))
    else:
        low, high = volume_bounds(volume)
    aspect = scene.render.resolution_x / max(1, scene.render.resolution_y)
    camera, radius = place_camera(preset.get("camera", {}), low, high, aspect, root, scene)

    volume.data.materials.append(volume_material(preset.get("tone", {}), radius, emission_strength, absorption))
    render = preset.get("render", {})
    shell = shell.lower()
    if shell == "auto":
        shell = "off" if render.get("mesh", "silhouette") == "off" else "ghost"
    if mesh is not None:
        if shell == "off":
            mesh.hide_render = True
            mesh.hide_viewport = True
        else:
            mesh.data.materials.clear()
            mesh.data.materials.append(shell_material(render, shell, radius))
            mesh.visible_shadow = False
            if shell == "wire":
                wire = mesh.modifiers.new("voxflame wire", "WIREFRAME")
                wire.thickness = 0.001 * radius
                wire.use_replace = True
    set_up_render(scene, preset.get("tone", {}).get("background", "#05060a"))
    summary = "'%s' (%s) from %s%s: grids %s, shell %s, camera at %.3g radii (radius %.4g); preset read from %s" % (
        preset.get("name", "?"), ", ".join(layer.get("attractor", "?") for layer in preset.get("layers", [])),
        os.path.basename(volume_path), " and %d more frames" % (frames - 1) if frames > 1 else "",
        ", ".join(sorted(g.name for g in volume.data.grids)), shell if mesh is not None else "none",
        preset.get("camera", {}).get("distance", 2.6), radius, source)
    return Imported(root, volume, mesh, camera, preset, frames, "; ".join([summary] + notes))
