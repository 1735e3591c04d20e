"""What hilight reads, written from Blender's data: the scene (OBJ + MTL, the
albedos) and the painted target (binary PLY). Both in hilight's axes (+Y up)
and metres, so hilight never goes through a glTF importer."""
import os

import bpy
import numpy

from . import units

DEFAULT_ALBEDO = (0.8, 0.8, 0.8)  # hilight's, for a surface with no material


class InputError(Exception):
    """A one-line reason the run cannot start."""


def metres(context):
    return context.scene.unit_settings.scale_length or 1.0


def albedo_of(material):
    """The diffuse colour hilight will see: a Principled BSDF's Base Color, a
    Diffuse BSDF's Color, else the viewport colour."""
    if material is None:
        return DEFAULT_ALBEDO
    if material.use_nodes and material.node_tree:
        for node in material.node_tree.nodes:
            if node.type == "BSDF_PRINCIPLED":
                return tuple(node.inputs["Base Color"].default_value)[:3]
            if node.type == "BSDF_DIFFUSE":
                return tuple(node.inputs["Color"].default_value)[:3]
    return tuple(material.diffuse_color)[:3]


def scene_objects(context):
    """The meshes hilight sees: every visible, rendered mesh."""
    return [o for o in context.scene.objects
            if o.type == "MESH" and not o.hide_render and o.visible_get()]


def _world_points(obj, mesh, scale):
    n = len(mesh.vertices)
    local = numpy.empty(n * 3, dtype=numpy.float64)
    mesh.vertices.foreach_get("co", local)
    local = local.reshape(n, 3)
    m = numpy.array(obj.matrix_world, dtype=numpy.float64)
    world = local @ m[:3, :3].T + m[:3, 3]
    # Blender (x, y, z) -> hilight (x, z, −y)
    return numpy.stack([world[:, 0], world[:, 2], -world[:, 1]], axis=1) * scale


def _world_normals(obj, mesh):
    n = len(mesh.vertices)
    local = numpy.empty(n * 3, dtype=numpy.float64)
    mesh.vertices.foreach_get("normal", local)
    local = local.reshape(n, 3)
    inv_t = numpy.array(obj.matrix_world.to_3x3().inverted_safe().transposed(), dtype=numpy.float64)
    world = local @ inv_t.T
    world /= numpy.maximum(numpy.linalg.norm(world, axis=1, keepdims=True), 1e-30)
    return numpy.stack([world[:, 0], world[:, 2], -world[:, 1]], axis=1)


def write_scene(context, path):
    """OBJ + MTL beside it; the number of meshes written."""
    depsgraph = context.evaluated_depsgraph_get()
    scale = metres(context)
    mtl_path = os.path.splitext(path)[0] + ".mtl"
    materials = {}  # albedo -> name
    out = [f"mtllib {os.path.basename(mtl_path)}\n"]
    base = 1
    written = 0
    for obj in scene_objects(context):
        evaluated = obj.evaluated_get(depsgraph)
        mesh = evaluated.to_mesh()
        try:
            points = _world_points(obj, mesh, scale)
            if len(points) == 0 or len(mesh.polygons) == 0:
                continue
            out.append(f"o {obj.name.replace(' ', '_')}\n")
            out.append("".join("v %.9g %.9g %.9g\n" % tuple(p) for p in points))
            loops = numpy.empty(len(mesh.loops), dtype=numpy.int64)
            mesh.loops.foreach_get("vertex_index", loops)
            slots = [s.material for s in evaluated.material_slots]
            current = None
            for poly in mesh.polygons:
                material = slots[poly.material_index] if poly.material_index < len(slots) else None
                albedo = tuple(round(c, 6) for c in albedo_of(material))
                name = materials.setdefault(albedo, f"albedo{len(materials)}")
                if name != current:
                    out.append(f"usemtl {name}\n")
                    current = name
                start = poly.loop_start
                out.append("f " + " ".join(str(base + int(v)) for v in loops[start:start + poly.loop_total]) + "\n")
            base += len(points)
            written += 1
        finally:
            evaluated.to_mesh_clear()
    if not written:
        raise InputError("the scene has no visible mesh to light")
    with open(path, "w") as f:
        f.write("".join(out))
    with open(mtl_path, "w") as f:
        for albedo, name in materials.items():
            f.write(f"newmtl {name}\nKd {albedo[0]:.6g} {albedo[1]:.6g} {albedo[2]:.6g}\n")
    return written


def _attribute_values(mesh, name):
    """Per-vertex RGBA of a colour attribute (linear; a corner attribute
    averaged over each vertex's corners), or None if the mesh has none."""
    attribute = mesh.color_attributes.get(name) if name else mesh.color_attributes.active_color
    if attribute is None:
        return None
    n = len(attribute.data)
    values = numpy.empty(n * 4, dtype=numpy.float64)
    attribute.data.foreach_get("color", values)  # linear for float and byte colours alike
    values = values.reshape(n, 4)
    if attribute.domain == "POINT":
        return values
    if attribute.domain != "CORNER":
        raise InputError(f"{mesh.name}: colour attribute {attribute.name} is per {attribute.domain.lower()}; paint per vertex or corner")
    corner_vertex = numpy.empty(len(mesh.loops), dtype=numpy.int64)
    mesh.loops.foreach_get("vertex_index", corner_vertex)
    sums = numpy.zeros((len(mesh.vertices), 4))
    numpy.add.at(sums, corner_vertex, values)
    counts = numpy.bincount(corner_vertex, minlength=len(mesh.vertices))[:, None]
    return sums / numpy.maximum(counts, 1)


def write_ply(path, points, normals, rgb, weight):
    n = len(points)
    data = numpy.empty((n, 10), dtype="<f4")
    data[:, 0:3], data[:, 3:6], data[:, 6:9], data[:, 9] = points, normals, rgb, weight
    header = ("ply\nformat binary_little_endian 1.0\n"
              f"comment hilight target written by the Blender add-on\nelement vertex {n}\n"
              + "".join(f"property float {p}\n" for p in ("x", "y", "z", "nx", "ny", "nz", "red", "green", "blue", "weight"))
              + "end_header\n")
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(data.tobytes())


def write_target(context, path, settings):
    """The target as a PLY hilight reads; the number of points.
    Painted: every vertex of a mesh with the colour attribute (alpha: weight,
    0 = don't care). Work-plane: every vertex of that object at settings.lux."""
    depsgraph = context.evaluated_depsgraph_get()
    scale = metres(context)
    chunks = []
    if settings.target_kind == "WORKPLANE":
        plane = settings.workplane
        if plane is None or plane.type != "MESH":
            raise InputError("pick the work-plane (a mesh) in the hilight panel")
        objects = [plane]
    else:
        objects = scene_objects(context)
    for obj in objects:
        evaluated = obj.evaluated_get(depsgraph)
        mesh = evaluated.to_mesh()
        try:
            if settings.target_kind == "WORKPLANE":
                n = len(mesh.vertices)
                rgba = numpy.tile([settings.lux, settings.lux, settings.lux, 1.0], (n, 1))
            else:
                rgba = _attribute_values(mesh, settings.attribute)
                if rgba is None:
                    continue
            chunks.append((_world_points(obj, mesh, scale), _world_normals(obj, mesh), rgba))
        finally:
            evaluated.to_mesh_clear()
    if not chunks:
        if settings.attribute:
            raise InputError(f"no mesh has a colour attribute named {settings.attribute!r}: paint one (Vertex Paint)")
        raise InputError("no mesh has a colour attribute: paint the light you want (Vertex Paint) first")
    points = numpy.concatenate([c[0] for c in chunks])
    normals = numpy.concatenate([c[1] for c in chunks])
    rgba = numpy.concatenate([c[2] for c in chunks])
    if not (rgba[:, 3] > 0).any():
        raise InputError("every painted point has alpha 0 (don't care): nothing to match")
    write_ply(path, points, normals, rgba[:, :3], numpy.clip(rgba[:, 3], 0.0, None))
    return len(points)


def region_box(context, obj):
    """An object's bounds in hilight's axes and metres: x0,y0,z0,x1,y1,z1."""
    from mathutils import Vector
    scale = metres(context)
    corners = [units.from_blender(obj.matrix_world @ Vector(c)) for c in obj.bound_box]
    lo = [min(c[i] for c in corners) * scale for i in range(3)]
    hi = [max(c[i] for c in corners) * scale for i in range(3)]
    return ",".join("%.6g" % v for v in lo + hi)
