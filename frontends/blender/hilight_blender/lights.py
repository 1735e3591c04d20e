"""hilight's lights as Blender lights in a collection of their own, and back.

Each light object keeps the hilight light it came from (custom property
"hilight", JSON) for what Blender cannot hold (a line source, a profile's
file); what Blender holds (place, aim, power, colour, cone, size) is read
from the object, so a light the user moved or dimmed is fine-tuned as it is.
"""
import json
import math
import os
import subprocess

import bpy
from mathutils import Matrix, Vector

from . import compat, ies_level, scene_io, units

COLLECTION = "hilight lights"


def collection(context, create=True):
    found = bpy.data.collections.get(COLLECTION)
    if found is None and create:
        found = bpy.data.collections.new(COLLECTION)
    if found is not None and create and found.name not in context.scene.collection.children:
        context.scene.collection.children.link(found)
    return found


def light_objects(context):
    found = collection(context, create=False)
    if found is None:
        return []
    return sorted((o for o in found.objects if o.type == "LIGHT"), key=lambda o: o.name)


def clear(context):
    for obj in light_objects(context):
        data = obj.data
        bpy.data.objects.remove(obj, do_unlink=True)
        if data.users == 0:
            bpy.data.lights.remove(data)


def frame(location, minus_z, x_axis=None):
    """A world matrix at `location` whose local −Z is `minus_z` (local X
    `x_axis` made perpendicular to it, if given)."""
    z = -Vector(minus_z).normalized()
    if x_axis is None or abs(Vector(x_axis).normalized().dot(z)) > 0.999:
        x_axis = Vector((1.0, 0.0, 0.0)) if abs(z.x) < 0.9 else Vector((0.0, 1.0, 0.0))
    x_axis = Vector(x_axis)
    x = (x_axis - z * x_axis.dot(z)).normalized()
    y = z.cross(x)
    m = Matrix.Identity(4)
    for r in range(3):
        m[r][0], m[r][1], m[r][2], m[r][3] = x[r], y[r], z[r], location[r]
    return m


def _emission(data):
    data.use_nodes = True
    tree = data.node_tree
    return tree, next(n for n in tree.nodes if n.type == "EMISSION")


def _divide_cos(data):
    """Emission × 1/cos α (α from the light's −Z): undoes the cos α that
    Cycles before 4.0 puts on a spot's cone, leaving hilight's S(α)."""
    tree, emission = _emission(data)
    coordinates = tree.nodes.new("ShaderNodeTexCoord")
    split = tree.nodes.new("ShaderNodeSeparateXYZ")
    clamp = tree.nodes.new("ShaderNodeMath")
    clamp.operation = "MINIMUM"  # z = −cos α; kept below −10⁻³ off a cone of 90° or more
    clamp.inputs[1].default_value = -1e-3
    divide = tree.nodes.new("ShaderNodeMath")
    divide.operation = "DIVIDE"
    divide.inputs[0].default_value = -1.0
    tree.links.new(coordinates.outputs["Normal"], split.inputs["Vector"])
    tree.links.new(split.outputs["Z"], clamp.inputs[0])
    tree.links.new(clamp.outputs["Value"], divide.inputs[1])
    tree.links.new(divide.outputs["Value"], emission.inputs["Strength"])


def _hilight():
    from . import runner  # runner imports this module
    return runner.executable(bpy.context)


def _ies_text_block(name, text):
    """The .blend's text block holding `text`: one a profile, shared by its
    luminaires (Blender numbers a second block of the same name)."""
    for block in bpy.data.texts:
        if block.name.startswith(name) and block.as_string() == text:
            return block
    block = bpy.data.texts.new(name)
    block.write(text)
    return block


def _ies_node(data, profile):
    """The profile's shape on the emission: Cycles' IES Fac over its peak
    (ies_level.py), so the light's Power sets the peak as hilight's
    intensity does; the profile as the IES text hilight writes for it, its
    planes mirrored for Cycles, kept in the .blend. Without hilight an IES
    file is read as it is (a profile symmetric in C comes out right). A
    profile that cannot be read gets no node: the light then shines its peak
    every way (its custom property keeps the profile for hilight)."""
    path = bpy.path.abspath(profile)
    internal = None
    try:
        try:
            text = ies_level.ies_for_cycles(path, _hilight())
        except scene_io.InputError:  # no hilight to ask
            if ies_level.is_eulumdat(path):
                raise
            text = None
        if text is not None:
            peak = ies_level.cycles_peak_of_text(text, path)
            internal = _ies_text_block(os.path.basename(path) + ".ies", text)
        else:
            peak = ies_level.cycles_peak(path)
    except (OSError, ValueError, subprocess.SubprocessError, scene_io.InputError) as e:  # NotIes is a ValueError
        print(f"hilight: {e}: the luminaire comes in as a point light of its peak intensity")
        return
    tree, emission = _emission(data)
    ies = tree.nodes.new("ShaderNodeTexIES")
    if internal is not None:
        ies.mode = "INTERNAL"
        ies.ies = internal
    else:
        ies.mode = "EXTERNAL"
        ies.filepath = profile
    level = tree.nodes.new("ShaderNodeMath")
    level.operation = "MULTIPLY"
    level.inputs[1].default_value = 1.0 / peak
    tree.links.new(ies.outputs["Fac"], level.inputs[0])
    tree.links.new(level.outputs["Value"], emission.inputs["Strength"])


def luminaire_matrix(position, direction, spin_deg):
    """A luminaire's Blender frame: local −Z its aim, local X hilight's C = 90°
    plane and −Y its C = 0° (LuminaireFrame: C = 0 along hilight's +X made
    perpendicular to the aim, +Z where the aim is near ±X, turned by the spin
    about the aim), which is where Cycles reads the mirrored profile's C."""
    reference = (1.0, 0.0, 0.0) if abs(direction[0]) <= 0.9 else (0.0, 0.0, 1.0)
    base = frame(position, units.to_blender(direction), units.to_blender(reference))  # local X: C = 0, Y: C = 90
    return base @ Matrix.Rotation(math.radians(spin_deg) + math.pi / 2.0, 4, "Z")


def make_light(light, name, scale=1.0):
    """A Blender light object (not linked) for one hilight light (W/sr, metres)."""
    kind = light.get("type", "point")
    peak, colour = units.peak_and_colour(light.get("intensity", 0.0))
    position = Vector(units.to_blender(light["position"])) / scale
    direction = light.get("direction", [0.0, -1.0, 0.0])
    minus_z = units.to_blender(direction)
    if kind == "point":
        data = bpy.data.lights.new(name, "POINT")
        matrix = Matrix.Translation(position)
    elif kind == "spot":
        data = bpy.data.lights.new(name, "SPOT")
        data.spot_size = math.radians(2.0 * light["cutoff_deg"])
        data.spot_blend = units.spot_blend(light["cutoff_deg"], light.get("falloff_deg", 0.0))
        data.show_cone = True
        if compat.SPOT_MULTIPLIES_COS:
            _divide_cos(data)
        matrix = frame(position, minus_z)
    elif kind in ("rectangle", "disk", "line"):
        data = bpy.data.lights.new(name, "AREA")
        size = light["size"]
        if kind == "disk":
            data.shape, data.size = "DISK", size[0] / scale
        else:  # a line: a strip 1 cm wide, the nearest Blender has
            data.shape = "RECTANGLE"
            data.size = size[0] / scale
            data.size_y = (size[1] if kind == "rectangle" else 0.01) / scale
        matrix = frame(position, minus_z, units.to_blender(light.get("up", [1.0, 0.0, 0.0])))
    elif kind == "luminaire":
        data = bpy.data.lights.new(name, "POINT")
        if light.get("profile"):
            _ies_node(data, light["profile"])
        matrix = luminaire_matrix(position, direction, light.get("spin_deg", 0.0))
    else:
        raise ValueError(f"light type {kind!r} has no Blender light")
    data.shadow_soft_size = 0.0 if data.type != "AREA" else data.shadow_soft_size
    data.energy = units.blender_watts(kind, peak)
    data.color = colour
    obj = bpy.data.objects.new(name, data)
    obj.matrix_world = matrix
    obj["hilight"] = json.dumps(light)
    compat.hide_from_camera(obj)
    return obj


def bring_in(context, lights, scale=1.0):
    """Replaces the collection's lights with these; the new objects."""
    clear(context)
    target = collection(context)
    made = []
    for i, light in enumerate(lights):
        obj = make_light(light, f"hilight {i + 1:02d}", scale)
        target.objects.link(obj)
        made.append(obj)
    return made


def to_hilight(obj, scale=1.0):
    """The hilight light (W/sr, metres) this Blender light is now."""
    stored = json.loads(obj.get("hilight", "{}"))
    data = obj.data
    default = {"POINT": "point", "SPOT": "spot", "AREA": "disk" if data.type == "AREA" and data.shape in ("DISK", "ELLIPSE") else "rectangle"}
    kind = stored.get("type", default.get(data.type, "point"))
    if kind not in units.WATTS_PER_W_SR:
        kind = "point"
    matrix = obj.matrix_world
    light = dict(stored)
    light["type"] = kind
    light["position"] = [c * scale for c in units.from_blender(matrix.translation)]
    peak = units.peak_from_watts(kind, data.energy)
    light["intensity"] = [peak * c for c in data.color]
    light.pop("dimming", None)  # the power is Blender's now
    aim = (matrix.to_3x3() @ Vector((0.0, 0.0, -1.0))).normalized()
    if kind != "point":
        light["direction"] = list(units.from_blender(aim))
    if kind == "spot" and data.type == "SPOT":
        cutoff = math.degrees(data.spot_size) / 2.0
        light["cutoff_deg"] = cutoff
        light["falloff_deg"] = units.falloff_from_blend(cutoff, data.spot_blend)
    if kind in ("rectangle", "line") and data.type == "AREA":
        light["up"] = list(units.from_blender((matrix.to_3x3() @ Vector((1.0, 0.0, 0.0))).normalized()))
        light["size"] = [data.size * scale] + ([data.size_y * scale] if kind == "rectangle" else [])
    if kind == "disk" and data.type == "AREA":
        light["size"] = [data.size * scale]
    if kind == "luminaire":
        light["spin_deg"] = luminaire_spin(matrix, light["direction"])
    return light


def luminaire_spin(matrix, direction):
    """The spin luminaire_matrix turned a luminaire by: its C = 0 plane (the
    object's −Y) against the unturned one, about the aim."""
    nadir = Vector(direction).normalized()
    reference = Vector((1.0, 0.0, 0.0) if abs(nadir.x) <= 0.9 else (0.0, 0.0, 1.0))
    c0 = (reference - nadir * reference.dot(nadir)).normalized()
    c90 = c0.cross(nadir)
    turned = Vector(units.from_blender((matrix.to_3x3() @ Vector((0.0, -1.0, 0.0))).normalized()))
    return math.degrees(math.atan2(turned.dot(c90), turned.dot(c0)))


def figures(obj, scale=1.0):
    """candela, lumens, Blender watts of a light as it is now."""
    return units.figures(to_hilight(obj, scale))
