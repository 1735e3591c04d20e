"""The panel's options (saved with the .blend) and the add-on's preferences
(saved with Blender's preferences)."""
import bpy
from bpy.props import EnumProperty, FloatProperty, IntProperty, PointerProperty, StringProperty

from .runner import ADDON_ID


def _is_mesh(self, obj):
    return obj.type == "MESH"


class HilightSettings(bpy.types.PropertyGroup):
    target_kind: EnumProperty(
        name="Target", items=[("PAINT", "Painted", "the colour attribute painted on the meshes (Vertex Paint)"),
                              ("WORKPLANE", "Work-plane", "this mesh's surface to receive the lux given")],
        default="PAINT")
    attribute: StringProperty(name="Colour attribute", default="",
                              description="the painted colour attribute (empty: each mesh's active one); alpha 0: don't care")
    units: EnumProperty(
        name="Paint is", items=[("RADIANCE", "Radiance", "W/(sr·m²), hilight's own unit"),
                                ("LUMINANCE", "Luminance", "cd/m²"),
                                ("LUX", "Illuminance", "lux on the surface")], default="RADIANCE")
    workplane: PointerProperty(name="Work-plane", type=bpy.types.Object, poll=_is_mesh)
    lux: FloatProperty(name="Lux", default=500.0, min=0.0, soft_max=5000.0)
    count: IntProperty(name="Lights", default=0, min=0, max=10000, description="how many lights (0: automatic)")
    placement: EnumProperty(
        name="Placement", items=[("ANYWHERE", "Anywhere", "wherever the light is best"),
                                 ("CEILING", "Ceiling", "mounted below the ceiling"),
                                 ("REGION", "Region", "inside an object's bounds")], default="ANYWHERE")
    ceiling_offset: FloatProperty(name="Below ceiling", default=0.2, min=0.001, unit="LENGTH")
    region: PointerProperty(name="Region", type=bpy.types.Object)
    light_kind: EnumProperty(
        name="Lights", items=[("AUTO", "Points and spots", "point lights, spots where points fall short"),
                              ("POINT", "Points", "point lights only"),
                              ("AREA", "Area", "rectangular Lambertian panels"),
                              ("LUMINAIRE", "Luminaire", "every light is an IES/EULUMDAT luminaire")], default="AUTO")
    area_width: FloatProperty(name="Width", default=0.6, min=0.001, unit="LENGTH")
    area_height: FloatProperty(name="Height", default=0.6, min=0.001, unit="LENGTH")
    luminaire: StringProperty(name="IES file", subtype="FILE_PATH")
    bounces: EnumProperty(
        name="Bounces", items=[("ALL", "Every bounce", "light reflected until it converges (as Cycles renders)"),
                               ("1", "One bounce", "direct light and its first reflection"),
                               ("0", "Direct only", "no reflected light")], default="ALL")
    last_summary: StringProperty(name="Last run", default="")


class HilightPreferences(bpy.types.AddonPreferences):
    bl_idname = ADDON_ID
    executable: StringProperty(name="hilight executable", subtype="FILE_PATH", default="",
                               description="the hilight program (empty: the one on PATH)")
    threads: IntProperty(name="Threads", default=0, min=0, max=1024, description="threads hilight uses (0: all cores)")

    def draw(self, context):
        self.layout.prop(self, "executable")
        self.layout.prop(self, "threads")
