"""The side panel (3D viewport, N, tab "hilight")."""
import bpy

from . import lights, scene_io


class VIEW3D_PT_hilight(bpy.types.Panel):
    bl_label = "hilight"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "hilight"

    def draw(self, context):
        s = context.scene.hilight
        layout = self.layout
        col = layout.column()
        col.prop(s, "target_kind")
        if s.target_kind == "PAINT":
            col.prop(s, "attribute")
            col.prop(s, "units")
        else:
            col.prop(s, "workplane")
            col.prop(s, "lux")
        col.separator()
        col.prop(s, "count", text="Lights (0: automatic)")
        col.prop(s, "light_kind", text="Kind")
        if s.light_kind == "AREA":
            row = col.row(align=True)
            row.prop(s, "area_width")
            row.prop(s, "area_height")
        elif s.light_kind == "LUMINAIRE":
            col.prop(s, "luminaire")
        col.prop(s, "placement")
        if s.placement == "CEILING":
            col.prop(s, "ceiling_offset")
        elif s.placement == "REGION":
            col.prop(s, "region")
        col.prop(s, "bounces")
        row = layout.row(align=True)
        row.operator("hilight.solve", icon="LIGHT")
        row.operator("hilight.fine_tune")
        row.operator("hilight.add_light")
        if s.last_summary:
            layout.label(text=s.last_summary)
        found = lights.light_objects(context)
        if found:
            box = layout.box()
            head = box.row()
            for text in ("Light", "cd", "lm", "W (Blender)"):
                head.label(text=text)
            scale = scene_io.metres(context)
            for obj in found:
                f = lights.figures(obj, scale)
                row = box.row()
                row.label(text=obj.name)
                row.label(text=f"{f['candela']:.0f}")
                row.label(text="—" if f["lumens"] is None else f"{f['lumens']:.0f}")
                row.label(text=f"{f['watts']:.1f}")
            box.label(text="cd = 683·I (W/sr); W = 4π·I point, spot; 4·I₀ area")


classes = (VIEW3D_PT_hilight,)
