"""voxflame volumes for Blender: File > Import > voxflame volume (.vdb).

Imports a volume written by `voxflame render -o OUT.vdb`, or the sequence written by `voxflame
animate -o frames/%04d.vdb` as one animated volume, with the preset's emission-and-absorption
material, its mesh as a faint shell and its camera (importer.py). Install the zip the build makes
(voxflame_blender.zip; the Debian package puts it in /usr/share/voxflame/blender/) from Edit >
Preferences > Add-ons > Install, then enable "voxflame volumes".
"""

bl_info = {
    "name": "voxflame volumes",
    "author": "voxflame",
    "version": (1, 0, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > voxflame volume (.vdb)",
    "description": "Import voxflame's VDB volumes and frame sequences with their material, mesh shell and camera",
    "category": "Import-Export",
}

import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, StringProperty
from bpy_extras.io_utils import ImportHelper

from . import importer


class ImportVoxflameVolume(bpy.types.Operator, ImportHelper):
    """Import a volume (or a numbered sequence of them) written by voxflame"""

    bl_idname = "import_scene.voxflame_volume"
    bl_label = "Import voxflame volume"
    bl_options = {"REGISTER", "UNDO"}

    filename_ext = ".vdb"
    filter_glob: StringProperty(default="*.vdb", options={"HIDDEN"})
    mesh: StringProperty(
        name="Mesh",
        description="The preset's mesh file, when the preset names one built into voxflame (builtin:); "
                    "otherwise the path stored in the volume is used",
        subtype="FILE_PATH", default="")
    shell: EnumProperty(
        name="Mesh shell",
        items=[("AUTO", "As the preset", "Off when the preset shows no mesh, else a ghost"),
               ("GHOST", "Ghost", "A clear surface whose rim glows in the preset's mesh colour"),
               ("WIRE", "Wire", "A thin glowing wireframe"),
               ("OFF", "Off", "No shell")],
        default="AUTO")
    emission_strength: FloatProperty(
        name="Emission strength", description="Times the emission that matches the preset's brightness",
        default=1.0, min=0.0, soft_max=10.0)
    absorption: FloatProperty(
        name="Absorption", description="Times the absorption that matches the preset's opacity",
        default=1.0, min=0.0, soft_max=10.0)
    sequence: BoolProperty(
        name="Frame sequence", description="Import the numbered files that follow this one as one animated volume",
        default=True)

    def execute(self, context):
        try:
            imported = importer.import_voxflame(
                self.filepath, mesh_path=bpy.path.abspath(self.mesh) if self.mesh else None,
                shell=self.shell.lower(), emission_strength=self.emission_strength, absorption=self.absorption,
                sequence=self.sequence, scene=context.scene)
        except importer.ImportFailure as failure:
            self.report({"ERROR"}, str(failure))
            return {"CANCELLED"}
        self.report({"INFO"}, "voxflame: " + imported.summary)
        return {"FINISHED"}


def menu_entry(self, context):
    self.layout.operator(ImportVoxflameVolume.bl_idname, text="voxflame volume (.vdb)")


def register():
    bpy.utils.register_class(ImportVoxflameVolume)
    bpy.types.TOPBAR_MT_file_import.append(menu_entry)


def unregister():
    bpy.types.TOPBAR_MT_file_import.remove(menu_entry)
    bpy.utils.unregister_class(ImportVoxflameVolume)
