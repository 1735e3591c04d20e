# Blender Cycles as an outside reference for hilight's every-bounce render
# (issue 32, item 4; tests/test_cycles_cross.cpp, docs/blender.md "Cycles").
#
#   blender -b --factory-startup --python-exit-code 1 --python tests/blender/cycles_reference.py -- \
#     --scene room.glb --lights lights.json --camera "ex,ey,ez,tx,ty,tz,fov" \
#     --width 160 --height 120 --samples 256 --output cycles.exr \
#     [--compare all=hilight_all.exr --compare one=hilight_1.exr --report report.json] [--reuse]
#
# The scene is hilight's own glTF export (`hilight export SCENE -o room.glb`),
# read by Blender's glTF importer. Everything else is set here from hilight's
# rendering model (docs/rendering-model.md), not from the importer:
# - every material a pure Lambertian Diffuse BSDF (roughness 0) with the
#   glTF base colour as its albedo ρ; the world black; no clamping, no light
#   threshold, no denoising, diffuse bounces only (--bounces, default 128);
# - the lights from hilight's lights JSON (glTF axes, +Y up), in Blender's
#   +Z-up axes (x, -z, y) as its glTF importer maps them:
#     point     I [W/sr]  -> Power 4π·I W, radius 0 (Cycles: I = P/4π)
#     spot      I, cutoff -> a point light of the same power whose emission
#               shader is hilight's cone S(α) (Cycles' own spot light also
#               multiplies by cos α, so it is not used)
#     rectangle I₀ (W/sr along the normal), size [w, h], up -> Area light,
#               shape Rectangle, Size X = w along up, Size Y = h, emitting
#               along `direction` (its −Z), Power 4·I₀ W (measured on a
#               plane: Cycles 3.4's area light of power P has I₀ = P/4, not
#               the P/π of a Lambertian emitter of flux P); not seen by the
#               camera
#     colour = I / max(I), the power from max(I);
# - the camera as hilight's --camera: eye, target, vertical fov, +Y up (its
#   basis: camera.cpp), a box pixel filter one pixel wide, the view transform
#   Standard, exposure 0, written as a 32-bit linear EXR.
# The pixel values are then outgoing radiance ρ/π·E in W/(sr m²), hilight's
# EXR quantity.
#
# --compare NAME=FILE (repeatable) compares hilight EXRs of the same camera
# with the Cycles image and writes the figures to --report (JSON): per pixel
# and per block (--block, default 8: block means, which average Cycles' noise),
# the ratio hilight/Cycles of the channel sum over pixels both cover and
# Cycles lights above 1% of its median; median, mean and 90th percentile of
# |ratio − 1|, the fraction within 5%, and the ratio of the image sums.
# --reuse: do not render if --output exists (for exploring the comparison).
import argparse
import json
import math
import os
import sys
import time

import bpy
import numpy
from mathutils import Matrix, Vector

# The conversions (axes, powers) are the Blender add-on's: one module for both.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "frontends", "blender", "hilight_blender"))
import units  # noqa: E402  (no bpy inside: importable on its own)

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which Debian's
# numpy 1.24 removed; it meant the builtin bool (docs/blender.md).
if "bool" not in numpy.__dict__:
    numpy.bool = bool

parser = argparse.ArgumentParser(prog="cycles_reference.py")
parser.add_argument("--scene", required=True)
parser.add_argument("--lights", required=True)
parser.add_argument("--camera", required=True)
parser.add_argument("--width", type=int, default=160)
parser.add_argument("--height", type=int, default=120)
parser.add_argument("--samples", type=int, default=256)
parser.add_argument("--bounces", type=int, default=128)
parser.add_argument("--seed", type=int, default=1)
parser.add_argument("--threads", type=int, default=0)
parser.add_argument("--output", required=True)
parser.add_argument("--compare", action="append", default=[])
parser.add_argument("--report", default="")
parser.add_argument("--block", type=int, default=8)
parser.add_argument("--reuse", action="store_true")
args = parser.parse_args(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])


def to_blender(v):
    """glTF / hilight axes (+Y up) to Blender's (+Z up), as its glTF importer maps them."""
    return Vector(units.to_blender(v))


def light_frame(location, minus_z, x_axis=None):
    """A world matrix whose local −Z is `minus_z` (and local X `x_axis`, if given)."""
    z = -minus_z.normalized()
    if x_axis is None:
        helper = Vector((1.0, 0.0, 0.0)) if abs(z.x) < 0.9 else Vector((0.0, 1.0, 0.0))
        x_axis = helper - z * helper.dot(z)
    x = (x_axis - z * x_axis.dot(z)).normalized()
    y = z.cross(x)
    m = Matrix.Identity(4)
    for r in range(3):
        m[r][0], m[r][1], m[r][2], m[r][3] = x[r], y[r], z[r], location[r]
    return m


def albedo_of(material):
    """The glTF base colour factor the importer put on its Principled BSDF."""
    if material is None or not material.use_nodes:
        return None
    for node in material.node_tree.nodes:
        if node.type == "BSDF_PRINCIPLED":
            socket = node.inputs["Base Color"]
            if socket.is_linked:
                raise RuntimeError(f"material {material.name}: a textured base colour is not supported here")
            return list(socket.default_value)[:3]
    return None


def lambertian(name, rho):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (rho[0], rho[1], rho[2], 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0  # 0: Lambert (above: Oren-Nayar)
    output = nodes.new("ShaderNodeOutputMaterial")
    material.node_tree.links.new(diffuse.outputs["BSDF"], output.inputs["Surface"])
    return material


def spot_cone(data, cos_cutoff, cos_inner):
    """Emission × S(α), α from the light's local −Z (its aim)."""
    data.use_nodes = True
    tree = data.node_tree
    nodes = tree.nodes
    emission = next(n for n in nodes if n.type == "EMISSION")
    coordinates = nodes.new("ShaderNodeTexCoord")
    split = nodes.new("ShaderNodeSeparateXYZ")
    cone = nodes.new("ShaderNodeMapRange")
    cone.clamp = True
    # z = −cos α (the emitted direction in the light's frame, aim along −Z);
    # 1 for z ≤ −cos(inner), 0 for z ≥ −cos(cutoff): 1 − s(1 − t) = s(t).
    soft = cos_inner - cos_cutoff > 1e-6
    cone.interpolation_type = "SMOOTHSTEP" if soft else "LINEAR"
    cone.inputs["From Min"].default_value = -cos_inner if soft else -cos_cutoff - 1e-6
    cone.inputs["From Max"].default_value = -cos_cutoff
    cone.inputs["To Min"].default_value = 1.0
    cone.inputs["To Max"].default_value = 0.0
    tree.links.new(coordinates.outputs["Normal"], split.inputs["Vector"])
    tree.links.new(split.outputs["Z"], cone.inputs["Value"])
    tree.links.new(cone.outputs["Result"], emission.inputs["Strength"])


def add_light(index, light):
    kind = light.get("type", "point")
    peak, colour = units.peak_and_colour(light["intensity"])
    position = to_blender(light["position"])
    name = f"hilight {index}"
    if kind == "point":
        data = bpy.data.lights.new(name, "POINT")
        data.energy = units.blender_watts(kind, peak)
        data.shadow_soft_size = 0.0
        matrix = Matrix.Translation(position)
    elif kind == "spot":
        # Cycles 3.4's own spot multiplies its cone by cos α (measured: 17%
        # off hilight's on a plane under a 40° cone), so hilight's spot is a
        # point light whose emission shader is hilight's cone: 1 inside
        # cutoff − falloff, 0 beyond cutoff, a smoothstep in cos α between.
        data = bpy.data.lights.new(name, "POINT")
        data.energy = units.blender_watts(kind, peak)
        data.shadow_soft_size = 0.0
        cutoff = math.radians(light["cutoff_deg"])
        inner = math.radians(light["cutoff_deg"] - light.get("falloff_deg", 0.0))
        spot_cone(data, math.cos(cutoff), math.cos(inner))
        matrix = light_frame(position, to_blender(light["direction"]))
    elif kind == "rectangle":
        data = bpy.data.lights.new(name, "AREA")
        data.shape = "RECTANGLE"
        data.size, data.size_y = light["size"][0], light["size"][1]
        data.energy = units.blender_watts(kind, peak)
        matrix = light_frame(position, to_blender(light["direction"]), to_blender(light.get("up", [1.0, 0.0, 0.0])))
    else:
        raise RuntimeError(f"light {index}: type {kind} is not converted here")
    data.color = colour
    obj = bpy.data.objects.new(name, data)
    obj.matrix_world = matrix
    obj.visible_camera = False  # an area light's face is not part of hilight's image
    bpy.context.scene.collection.objects.link(obj)


def build_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=args.scene)
    scene = bpy.context.scene
    # Only hilight's lights, converted here.
    for obj in [o for o in scene.objects if o.type in ("LIGHT", "CAMERA")]:
        bpy.data.objects.remove(obj, do_unlink=True)
    grey = None
    replaced = {}
    for obj in [o for o in scene.objects if o.type == "MESH"]:
        if not obj.material_slots:
            grey = grey or lambertian("hilight default", [0.8, 0.8, 0.8])  # hilight's default albedo
            obj.data.materials.append(grey)
            continue
        for slot in obj.material_slots:
            old = slot.material
            if old is None or old.name not in replaced:
                rho = albedo_of(old) or [0.8, 0.8, 0.8]
                replaced[old.name if old else ""] = lambertian(f"lambert {old.name if old else ''}", rho)
            slot.material = replaced[old.name if old else ""]
    with open(args.lights) as f:
        lights = json.load(f)["lights"]
    for i, light in enumerate(lights):
        add_light(i, light)

    world = bpy.data.worlds.new("black")
    world.use_nodes = False
    world.color = (0.0, 0.0, 0.0)
    scene.world = world

    # The camera: hilight's basis (framework/src/camera.cpp) in Blender's axes.
    values = [float(v) for v in args.camera.split(",")]
    eye, target, fov = values[0:3], values[3:6], values[6]
    forward = (Vector(target) - Vector(eye)).normalized()
    up_hint = Vector((0.0, 0.0, -1.0)) if abs(forward.y) > 0.99 else Vector((0.0, 1.0, 0.0))
    right = forward.cross(up_hint).normalized()
    up = right.cross(forward)
    camera_data = bpy.data.cameras.new("hilight camera")
    camera_data.sensor_fit = "VERTICAL"
    camera_data.sensor_height = 24.0
    camera_data.lens = 12.0 / math.tan(math.radians(fov) / 2.0)
    camera_data.clip_start = 1e-3
    camera_data.clip_end = 1e6
    camera = bpy.data.objects.new("hilight camera", camera_data)
    m = Matrix.Identity(4)
    columns = [to_blender(right), to_blender(up), -to_blender(forward), to_blender(eye)]
    for c, v in enumerate(columns):
        for r in range(3):
            m[r][c] = v[r]
    camera.matrix_world = m
    scene.collection.objects.link(camera)
    scene.camera = camera

    render = scene.render
    render.engine = "CYCLES"
    render.resolution_x, render.resolution_y, render.resolution_percentage = args.width, args.height, 100
    render.pixel_aspect_x = render.pixel_aspect_y = 1.0
    render.film_transparent = False
    if args.threads > 0:
        render.threads_mode = "FIXED"
        render.threads = args.threads
    render.image_settings.file_format = "OPEN_EXR"
    render.image_settings.color_depth = "32"
    render.image_settings.exr_codec = "ZIP"
    render.filepath = args.output
    render.use_file_extension = False
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = args.samples
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.seed = args.seed
    cycles.use_animated_seed = False
    cycles.max_bounces = args.bounces
    cycles.diffuse_bounces = args.bounces
    cycles.glossy_bounces = 0
    cycles.transmission_bounces = 0
    cycles.volume_bounces = 0
    cycles.transparent_max_bounces = 0
    cycles.caustics_reflective = False
    cycles.caustics_refractive = False
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.light_sampling_threshold = 0.0
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    cycles.film_exposure = 1.0
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.display_settings.display_device = "sRGB"


def load_exr(path):
    image = bpy.data.images.load(path, check_existing=False)
    image.colorspace_settings.name = "Linear"
    w, h = image.size
    pixels = numpy.empty(w * h * 4, dtype=numpy.float32)
    image.pixels.foreach_get(pixels)
    bpy.data.images.remove(image)
    # Blender's rows run bottom to top; flip to the file's (and hilight's) order.
    return pixels.reshape(h, w, 4)[::-1]


def stats(ratio):
    if ratio.size == 0:
        return {"count": 0}
    dev = numpy.abs(ratio - 1.0)
    return {
        "count": int(ratio.size),
        "median_abs": float(numpy.median(dev)),
        "mean_abs": float(numpy.mean(dev)),
        "p90_abs": float(numpy.percentile(dev, 90)),
        "within_5pct": float(numpy.mean(dev <= 0.05)),
        "median_ratio": float(numpy.median(ratio)),
    }


def compare(cycles_rgba, hilight_rgba, block):
    c = cycles_rgba[..., :3].astype(numpy.float64).sum(axis=2)
    h = hilight_rgba[..., :3].astype(numpy.float64).sum(axis=2)
    covered = hilight_rgba[..., 3] > 0.5
    floor = 0.01 * numpy.median(c[covered]) if covered.any() else 0.0
    mask = covered & (c > floor)
    result = {"pixels": stats(h[mask] / c[mask]),
              "sum_ratio": float(h[covered].sum() / max(c[covered].sum(), 1e-30))}
    # Smooth pixels: away from geometric and shadow edges (hilight's image
    # varies by < 10% over the 3x3 neighbourhood).
    pad = numpy.pad(h, 1, mode="edge")
    lo = numpy.min([pad[dy:dy + h.shape[0], dx:dx + h.shape[1]] for dy in range(3) for dx in range(3)], axis=0)
    hi = numpy.max([pad[dy:dy + h.shape[0], dx:dx + h.shape[1]] for dy in range(3) for dx in range(3)], axis=0)
    smooth = mask & (hi <= 1.1 * numpy.maximum(lo, 1e-30))
    result["smooth_pixels"] = stats(h[smooth] / c[smooth])
    result["smooth_fraction"] = float(smooth.sum() / max(mask.sum(), 1))
    by, bx = c.shape[0] // block, c.shape[1] // block
    cb = c[:by * block, :bx * block].reshape(by, block, bx, block).sum(axis=(1, 3))
    hb = h[:by * block, :bx * block].reshape(by, block, bx, block).sum(axis=(1, 3))
    full = covered[:by * block, :bx * block].reshape(by, block, bx, block).all(axis=(1, 3))
    bmask = full & (cb > floor * block * block)
    result["blocks"] = stats(hb[bmask] / cb[bmask])
    result["block_size"] = block
    return result


def main():
    started = time.time()
    rendered = False
    if not (args.reuse and os.path.exists(args.output)):
        build_scene()
        bpy.ops.render.render(write_still=True)
        rendered = True
    seconds = time.time() - started
    report = {"cycles": {"output": args.output, "rendered": rendered, "seconds": seconds, "samples": args.samples,
                         "bounces": args.bounces, "width": args.width, "height": args.height, "seed": args.seed,
                         "version": bpy.app.version_string}}
    if args.compare:
        cycles_image = load_exr(args.output)
        report["cycles"]["mean_radiance_sum"] = float(cycles_image[..., :3].sum(axis=2).mean())
        for item in args.compare:
            name, path = item.split("=", 1)
            hilight_image = load_exr(path)
            if hilight_image.shape != cycles_image.shape:
                raise RuntimeError(f"{path}: {hilight_image.shape} pixels, Cycles {cycles_image.shape}")
            report[name] = compare(cycles_image, hilight_image, args.block)
            report[name]["mean_radiance_sum"] = float(hilight_image[..., :3].sum(axis=2).mean())
    text = json.dumps(report, indent=1)
    print(text)
    if args.report:
        with open(args.report, "w") as f:
            f.write(text)


main()
