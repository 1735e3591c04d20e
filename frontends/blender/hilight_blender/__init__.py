"""hilight in Blender: paint the light you want, Solve, get the lights back
(docs/blender.md, "The add-on"). One package for both forms: Blender 4.2+
reads blender_manifest.toml (an extension), Blender 3.4 reads bl_info."""

bl_info = {
    "name": "hilight",
    "author": "hilight developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "3D Viewport > Sidebar (N) > hilight",
    "description": "Find the lights that give the painted light (runs hilight solve)",
    "category": "Lighting",
}

import bpy
from bpy.props import PointerProperty

from . import compat, operators, panel, properties

_classes = (properties.HilightSettings, properties.HilightPreferences) + operators.classes + panel.classes


def register():
    # Blender 3.4's glTF importer needs numpy.bool, which Debian's numpy 1.24 lacks.
    compat.install_numpy_shim()
    for cls in _classes:
        bpy.utils.register_class(cls)
    bpy.types.Scene.hilight = PointerProperty(type=properties.HilightSettings)


def unregister():
    del bpy.types.Scene.hilight
    for cls in reversed(_classes):
        bpy.utils.unregister_class(cls)
