# Blender side of hilight's glTF round trip (tests/test_gltf_blender.cpp):
#   blender -b --factory-startup --python tools/blender_gltf_roundtrip.py -- IN.glb OUT.glb REPORT.json [paint|bake]
# Imports IN with Blender's own glTF importer, writes what Blender made of its
# lights (watts, colour, world position and aim, back in glTF's +Y-up axes)
# to REPORT, then exports the scene again with Blender's exporter to OUT.
# With "paint", it first paints every mesh vertex as a designer's colour
# attribute would hold it (linear float colours, a known function of the
# vertex's glTF position, alpha = weight), so hilight can read it as a target.
# With "bake", it bakes the direct light of IN's lights into the vertex
# colours by its own rays (hilight's rendering model: L = ρ/π · Σ I |cos θ| / d²
# on each side, shadows by Blender's ray casts) and removes the lights: the
# exported file is a target whose lights hilight must find.
import json
import math
import sys

import bpy
import numpy
from mathutils import Vector

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which Debian's
# numpy 1.24 removed; it meant the builtin bool.
if "bool" not in numpy.__dict__:
    numpy.bool = bool

args = sys.argv[sys.argv.index("--") + 1:]
source, target, report = args[:3]
mode = args[3] if len(args) > 3 else ""

def to_gltf_axes(v):
    # Blender is +Z up; its glTF importer maps glTF (x, y, z) to (x, -z, y).
    return [v.x, v.z, -v.y]


bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=source)


def painted(p):
    # The known target (glTF axes): a smooth gradient; the far half weighs less.
    colour = (0.2 + 0.1 * p[0], 0.3 + 0.05 * p[2], 0.1 + 0.2 * p[1])
    return colour, (1.0 if p[0] < 3.0 else 0.5)


def base_colour(material):
    if material and material.use_nodes:
        for node in material.node_tree.nodes:
            if node.type == "BSDF_PRINCIPLED":
                return list(node.inputs["Base Color"].default_value)[:3]
    return [0.8, 0.8, 0.8]


def bake():
    depsgraph = bpy.context.evaluated_depsgraph_get()
    lamps = []
    for obj in bpy.context.scene.objects:
        if obj.type == "LIGHT" and obj.data.type == "POINT":
            # The importer's watts = 4π × hilight's W/sr.
            lamps.append((obj.matrix_world.translation.copy(), [c * obj.data.energy / (4 * math.pi) for c in obj.data.color]))
    for obj in [o for o in bpy.context.scene.objects if o.type == "MESH"]:
        mesh = obj.data
        albedo = [None] * len(mesh.vertices)
        for poly in mesh.polygons:
            colour = base_colour(obj.material_slots[poly.material_index].material if obj.material_slots else None)
            for v in poly.vertices:
                if albedo[v] is None:
                    albedo[v] = colour
        attribute = mesh.color_attributes.new("Baked", "FLOAT_COLOR", "POINT")
        normal_matrix = obj.matrix_world.to_3x3().inverted().transposed()
        for v in mesh.vertices:
            p = obj.matrix_world @ v.co
            n = (normal_matrix @ v.normal).normalized()
            radiance = [0.0, 0.0, 0.0]
            for position, intensity in lamps:
                to_lamp = position - p
                d = to_lamp.length
                cos = n.dot(to_lamp) / d
                side = 1.0 if cos >= 0 else -1.0
                origin = p + n * (side * 1e-4)
                hit = bpy.context.scene.ray_cast(depsgraph, origin, to_lamp.normalized(), distance=d - 2e-4)[0]
                if hit:
                    continue
                for c in range(3):
                    radiance[c] += (albedo[v.index] or [0.8] * 3)[c] / math.pi * intensity[c] * abs(cos) / (d * d)
            attribute.data[v.index].color = (*radiance, 1.0)
        mesh.color_attributes.active_color = attribute
    for obj in [o for o in bpy.context.scene.objects if o.type == "LIGHT"]:
        bpy.data.objects.remove(obj)


if mode == "bake":
    bake()

if mode == "paint":
    for obj in bpy.context.scene.objects:
        if obj.type != "MESH":
            continue
        mesh = obj.data
        attribute = mesh.color_attributes.new("Painted", "FLOAT_COLOR", "POINT")
        for v in mesh.vertices:
            colour, weight = painted(to_gltf_axes(obj.matrix_world @ v.co))
            attribute.data[v.index].color = (*colour, weight)
        mesh.color_attributes.active_color = attribute

lights = []
meshes = 0
for obj in bpy.context.scene.objects:
    if obj.type == "MESH":
        meshes += 1
    if obj.type != "LIGHT":
        continue
    light = obj.data
    aim = obj.matrix_world.to_3x3() @ Vector((0.0, 0.0, -1.0))
    entry = {
        "name": obj.name,
        "type": light.type,
        "watts": light.energy,
        "color": list(light.color),
        "position": to_gltf_axes(obj.matrix_world.translation),
        "direction": to_gltf_axes(aim.normalized()),
    }
    if light.type == "SPOT":
        entry["spot_size"] = light.spot_size
        entry["spot_blend"] = light.spot_blend
    # The glTF light's extras, as the importer keeps them (custom properties).
    extras = {}
    for key in light.keys():
        value = light[key]
        extras[key] = value.to_dict() if hasattr(value, "to_dict") else value if isinstance(value, (int, float, str)) else str(value)
    entry["extras"] = extras
    lights.append(entry)

with open(report, "w") as f:
    json.dump({"blender": bpy.app.version_string, "meshes": meshes, "lights": lights}, f, indent=1)

bpy.ops.export_scene.gltf(filepath=target, export_format="GLB", export_lights=True, export_colors=True)
