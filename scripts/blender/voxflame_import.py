"""Brings a volume written by `voxflame render -o OUT.vdb` into Blender and sets it up as voxflame
shows it: the `density` and `color` grids drive an emission-and-absorption material that follows
the preset's brightness and opacity, the preset's mesh becomes a faint shell around it, and a
camera takes the preset's place. The preset comes from the VDB's own metadata.

Headless (renders with Cycles on the CPU when --render is given):

    blender -b --factory-startup --python voxflame_import.py -- VOLUME.vdb [--mesh MESH]
        [--render OUT.png] [--width W] [--height H] [--samples S] [--shell ghost|wire|off]
        [--save OUT.blend]

From Blender's Text editor: open this file, set VOLUME (and MESH when the preset's mesh is built
into voxflame) in TEXT_EDITOR_ARGUMENTS below and press Run Script; the volume, shell and camera
are added to the current scene.

Everything is placed in the mesh file's coordinates (where voxflame writes the volume), under an
empty turned 90 degrees about X so that a Y-up mesh stands upright in Blender's Z-up world.
"""

import argparse
import json
import math
import os
import struct
import sys

import bpy
from mathutils import Matrix, Vector

TEXT_EDITOR_ARGUMENTS = ["/path/to/volume.vdb"]  # e.g. ["lorenz.vdb", "--mesh", "bunny.obj"]

# Emission and absorption per unit of normalised density, per bounding-sphere radius of the grid:
# chosen so that a preset at its own brightness and opacity looks about as bright and as dense in
# Cycles as in voxflame (voxflame tone-maps the log density per pixel; Cycles integrates the
# volume's log density along each ray, so the two agree in where light is, not exactly in how much).
EMISSION_PER_BRIGHTNESS = 20.0
ABSORPTION_PER_OPACITY = 1.0


def fail(message):
    print("voxflame_import: " + message, file=sys.stderr)
    if bpy.app.background:
        sys.exit(1)
    raise RuntimeError(message)


def parse_arguments():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else TEXT_EDITOR_ARGUMENTS
    parser = argparse.ArgumentParser(prog="blender -b --python voxflame_import.py --",
                                     description="Import a voxflame VDB volume with its mesh, material and camera.")
    parser.add_argument("volume", help="a VDB written by voxflame render -o OUT.vdb")
    parser.add_argument("--mesh", help="the preset's mesh (needed when the preset names a builtin: mesh)")
    parser.add_argument("--render", metavar="OUT.png", help="render the scene with Cycles on the CPU to this PNG")
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=400)
    parser.add_argument("--samples", type=int, default=32, help="Cycles samples per pixel (no denoising)")
    parser.add_argument("--shell", choices=["ghost", "wire", "off"],
                        help="how the mesh is shown (default: off when the preset's render.mesh is off, else ghost)")
    parser.add_argument("--save", metavar="OUT.blend", help="save the scene as a .blend file")
    return parser.parse_args(argv)


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
    print("voxflame_import: preset read from %s" % source)
    return json.loads(metadata["voxflame_preset"])


def srgb_to_linear(hex_colour):
    hex_colour = hex_colour.lstrip("#")
    channels = [int(hex_colour[i:i + 2], 16) / 255.0 for i in (0, 2, 4)]
    return [c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4 for c in channels]


def import_volume(path, parent):
    before = set(bpy.data.objects)
    bpy.ops.object.volume_import(filepath=path, directory=os.path.dirname(path),
                                 files=[{"name": os.path.basename(path)}], use_sequence_detection=False)
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


def place_camera(preset_camera, low, high, aspect, parent):
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
    bpy.context.scene.collection.objects.link(camera)
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
    bpy.context.scene.camera = camera
    return camera, radius


def volume_material(tone, radius):
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
    emission_scale.inputs[1].default_value = EMISSION_PER_BRIGHTNESS * brightness / radius
    absorption_scale = nodes.new("ShaderNodeMath")
    absorption_scale.operation = "MULTIPLY"
    absorption_scale.inputs[1].default_value = ABSORPTION_PER_OPACITY * tone.get("opacity", 1.0) / radius
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


def set_up_render(scene, arguments, background):
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = arguments.samples
    scene.cycles.use_denoising = False  # Debian's Blender is built without OpenImageDenoise
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.max_bounces = 8
    scene.cycles.volume_bounces = 0  # emission and absorption only: nothing scatters
    scene.cycles.transparent_max_bounces = 16
    scene.cycles.volume_step_rate = 1.0
    scene.render.resolution_x = arguments.width
    scene.render.resolution_y = arguments.height
    scene.render.resolution_percentage = 100
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


def main():
    arguments = parse_arguments()
    volume_path = os.path.abspath(arguments.volume)
    if not os.path.isfile(volume_path):
        fail("no such file: '%s'" % arguments.volume)
    preset = read_preset(volume_path)
    scene = bpy.context.scene
    if bpy.app.background:
        # The startup scene's cube, light and camera would stand in the picture.
        for obj in list(scene.objects):
            bpy.data.objects.remove(obj, do_unlink=True)

    root = bpy.data.objects.new("voxflame", None)
    scene.collection.objects.link(root)
    root.rotation_euler = (math.radians(90), 0, 0)  # Y up (the mesh's frame) to Blender's Z up
    volume = import_volume(volume_path, root)

    mesh_path = arguments.mesh or preset.get("mesh", {}).get("path", "")
    mesh = None
    if mesh_path.startswith("builtin:"):
        print("voxflame_import: the preset's mesh is %s, compiled into voxflame: pass --mesh with that file (the "
              "repository has it under presets/%s) to show the shell and place the camera exactly; without it the "
              "camera frames the volume's own bounds" % (mesh_path, mesh_path[len("builtin:"):]), file=sys.stderr)
    elif mesh_path:
        if not os.path.isfile(mesh_path):
            fail("the preset's mesh '%s' is not there; pass --mesh MESH" % mesh_path)
        mesh = import_mesh(mesh_path, root)

    if mesh is not None:
        low, high = grid_box(*mesh_bounds(mesh), preset.get("grid", {}).get("resolution", 192))
    else:
        low, high = volume_bounds(volume)
    aspect = arguments.width / arguments.height
    camera, radius = place_camera(preset.get("camera", {}), low, high, aspect, root)

    volume.data.materials.append(volume_material(preset.get("tone", {}), radius))
    render = preset.get("render", {})
    shell = arguments.shell or ("off" if render.get("mesh", "silhouette") == "off" else "ghost")
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

    set_up_render(scene, arguments, preset.get("tone", {}).get("background", "#05060a"))
    print("voxflame_import: '%s' (%s) from %s: grids %s, shell %s, camera at %.3g radii (radius %.4g)" % (
        preset.get("name", "?"), ", ".join(layer.get("attractor", "?") for layer in preset.get("layers", [])),
        os.path.basename(volume_path), ", ".join(sorted(g.name for g in volume.data.grids)),
        shell if mesh is not None else "none", preset.get("camera", {}).get("distance", 2.6), radius))
    if arguments.save:
        bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(arguments.save))
        print("voxflame_import: saved %s" % arguments.save)
    if arguments.render:
        scene.render.filepath = os.path.abspath(arguments.render)
        bpy.ops.render.render(write_still=True)
        print("voxflame_import: rendered %s (%dx%d, %d samples, Cycles on the CPU)" % (
            arguments.render, arguments.width, arguments.height, arguments.samples))


if __name__ == "__main__":
    main()
