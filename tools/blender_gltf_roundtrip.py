# Blender side of hilight's glTF round trip (tests/test_gltf_blender.cpp):
#   blender -b --factory-startup --python tools/blender_gltf_roundtrip.py -- IN.glb OUT.glb REPORT.json [paint]
# Imports IN with Blender's own glTF importer, writes what Blender made of its
# lights (watts, colour, world position and aim, back in glTF's +Y-up axes)
# to REPORT, then exports the scene again with Blender's exporter to OUT.
# With "paint", it first paints every mesh vertex as a designer's colour
# attribute would hold it (linear float colours, a known function of the
# vertex's glTF position, alpha = weight), so hilight can read it as a target.
import json
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
paint = len(args) > 3 and args[3] == "paint"

def to_gltf_axes(v):
    # Blender is +Z up; its glTF importer maps glTF (x, y, z) to (x, -z, y).
    return [v.x, v.z, -v.y]


bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=source)


def painted(p):
    # The known target (glTF axes): a smooth gradient; the far half weighs less.
    colour = (0.2 + 0.1 * p[0], 0.3 + 0.05 * p[2], 0.1 + 0.2 * p[1])
    return colour, (1.0 if p[0] < 3.0 else 0.5)


if paint:
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
    lights.append(entry)

with open(report, "w") as f:
    json.dump({"blender": bpy.app.version_string, "meshes": meshes, "lights": lights}, f, indent=1)

bpy.ops.export_scene.gltf(filepath=target, export_format="GLB", export_lights=True, export_colors=True)
