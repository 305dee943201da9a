"""Brings a volume written by `voxflame render -o OUT.vdb` (or the first of a sequence written by
`voxflame animate -o frames/%04d.vdb`) into Blender headless and sets it up as voxflame shows it,
with the importer of the voxflame add-on (voxflame_blender/importer.py, beside this file):

    blender -b --factory-startup --python voxflame_import.py -- VOLUME.vdb [--mesh MESH]
        [--render OUT.png] [--frame N] [--width W] [--height H] [--samples S]
        [--shell ghost|wire|off] [--sequence] [--save OUT.blend]

In Blender itself, install the add-on instead (voxflame_blender.zip; File > Import > voxflame
volume (.vdb)).
"""

import argparse
import os
import sys

import bpy

# The add-on's package beside this file: its folder in the source tree, its zip where installed
# (/usr/share/voxflame/blender/); Python imports from either.
_here = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [_here, os.path.join(_here, "voxflame_blender.zip")]
from voxflame_blender import importer  # noqa: E402 (found through the path above)


def parse_arguments():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="blender -b --python voxflame_import.py --",
                                     description="Import a voxflame VDB volume with its mesh, material and camera.")
    parser.add_argument("volume", help="a VDB written by voxflame render -o OUT.vdb")
    parser.add_argument("--mesh", help="the preset's mesh (needed when the preset names a builtin: mesh)")
    parser.add_argument("--render", metavar="OUT.png", help="render the scene with Cycles on the CPU to this PNG")
    parser.add_argument("--frame", type=int, default=1, help="the scene frame to render (a sequence's frame 1 is "
                                                               "its first file)")
    parser.add_argument("--sequence", action="store_true", help="import the numbered files that follow as one "
                                                                 "animated volume")
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=400)
    parser.add_argument("--samples", type=int, default=32, help="Cycles samples per pixel (no denoising)")
    parser.add_argument("--shell", choices=["auto", "ghost", "wire", "off"], default="auto",
                        help="how the mesh is shown (auto: off when the preset's render.mesh is off, else ghost)")
    parser.add_argument("--save", metavar="OUT.blend", help="save the scene as a .blend file")
    return parser.parse_args(argv)


def main():
    arguments = parse_arguments()
    scene = bpy.context.scene
    scene.render.resolution_x = arguments.width
    scene.render.resolution_y = arguments.height
    scene.render.resolution_percentage = 100
    try:
        # Headless, the startup scene's cube, light and camera would stand in the picture.
        imported = importer.import_voxflame(arguments.volume, mesh_path=arguments.mesh, shell=arguments.shell,
                                            sequence=arguments.sequence, scene=scene,
                                            clear_scene=bpy.app.background)
    except importer.ImportFailure as failure:
        print("voxflame_import: " + str(failure), file=sys.stderr)
        sys.exit(1)
    print("voxflame_import: " + imported.summary)
    scene.cycles.samples = arguments.samples
    if arguments.save:
        bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(arguments.save))
        print("voxflame_import: saved %s" % arguments.save)
    if arguments.render:
        scene.frame_set(arguments.frame)
        scene.render.filepath = os.path.abspath(arguments.render)
        bpy.ops.render.render(write_still=True)
        print("voxflame_import: rendered %s (frame %d, %dx%d, %d samples, Cycles on the CPU)" % (
            arguments.render, arguments.frame, arguments.width, arguments.height, arguments.samples))


if __name__ == "__main__":
    main()
