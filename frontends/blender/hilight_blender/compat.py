"""Everything that differs between Blender 3.4 (Debian 12, the legacy add-on)
and Blender 4.2+ (the extension): kept here, small.

Tested in Blender 3.4 only; the 4.x branches follow Blender's documented API
(docs/blender.md, "The add-on").
"""
import bpy

VERSION = tuple(bpy.app.version)

# Cycles before 4.0 multiplies a spot light's cone by cos α (measured in 3.4,
# docs/blender.md §6); 4.0 made point and spot lights spheres whose cone is
# the smoothstep alone. Before 4.0 the add-on's spot lights divide it out.
SPOT_MULTIPLIES_COS = VERSION < (4, 0, 0)


def install_numpy_shim():
    """Blender 3.4's glTF importer calls numpy.bool, which numpy 1.24 removed
    (Debian 12 ships both); it meant the builtin bool. Returns True if added."""
    try:
        import numpy
    except ImportError:
        return False
    if "bool" in numpy.__dict__:
        return False
    numpy.bool = bool
    return True


def set_status(context, text):
    """Blender's status bar (None clears it); nothing without a workspace (background)."""
    workspace = getattr(context, "workspace", None)
    if workspace is not None:
        workspace.status_text_set(text)


def hide_from_camera(obj):
    """A light's own surface is not part of hilight's images."""
    if hasattr(obj, "visible_camera"):
        obj.visible_camera = False
