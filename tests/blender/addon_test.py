# The Blender add-on (frontends/blender, issue 37) as a user meets it, headless
# in Blender 3.4: installed from its zip into a fresh user folder, enabled,
# and driven through its own operators and its modal step (runner.Run.handle,
# what the Solve button's timer calls), running the real hilight.
#
#   blender -b --factory-startup --python-exit-code 1 --python tests/blender/addon_test.py -- \
#     --zip hilight-blender-addon.zip --hilight build/bin/hilight --case solve|cycles|numpy --work DIR
#
# solve:  a room painted (a colour attribute) with hilight's render of seeded
#         random point lights; Solve finds them (place within 1 cm, intensity
#         within 1%); a light moved 15 cm comes back with Fine-tune; a light
#         deleted comes back with Add light; Esc stops hilight; a missing
#         executable and an unpainted scene fail in one line with the reason.
# cycles: the add-on's point, spot and area lights rendered by Cycles (every
#         diffuse bounce) against hilight's render of the same lights file.
# numpy:  enabling the add-on lets Blender 3.4's glTF importer read hilight's
#         glTF with Debian's numpy 1.24 (numpy.bool removed).
import argparse
import json
import math
import os
import random
import struct
import subprocess
import sys
import time

import addon_utils
import bmesh
import bpy
import numpy
from mathutils import Matrix, Vector, kdtree

parser = argparse.ArgumentParser(prog="addon_test.py")
parser.add_argument("--zip", required=True)
parser.add_argument("--hilight", required=True)
parser.add_argument("--case", required=True, choices=["solve", "cycles", "numpy"])
parser.add_argument("--work", required=True)
parser.add_argument("--seed", type=int, default=37)
args = parser.parse_args(sys.argv[sys.argv.index("--") + 1:])
os.makedirs(args.work, exist_ok=True)

failures = []
checks = 0


def check(condition, what):
    global checks
    checks += 1
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def finish():
    print(f"{checks} checks, {len(failures)} failed", flush=True)
    if checks == 0 or failures:
        sys.exit(1)


def install_addon():
    """As a user does: Preferences → Add-ons → Install… (the zip), then enable."""
    started = time.time()
    bpy.ops.preferences.addon_install(filepath=os.path.abspath(args.zip), overwrite=True)
    addon_utils.enable("hilight_blender", default_set=True, handle_error=None)
    import hilight_blender
    where = os.path.dirname(hilight_blender.__file__)
    check(where.startswith(bpy.utils.user_resource("SCRIPTS")), f"installed into the user's scripts ({where})")
    prefs = bpy.context.preferences.addons["hilight_blender"].preferences
    prefs.executable = os.path.abspath(args.hilight)
    prefs.threads = 2
    print(f"installed and enabled in {time.time() - started:.1f} s")
    return hilight_blender


def lambert(name, rho):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (*rho, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    output = nodes.new("ShaderNodeOutputMaterial")
    material.node_tree.links.new(diffuse.outputs["BSDF"], output.inputs["Surface"])
    return material


def box(name, centre, size, cuts, material, inward=False):
    """A subdivided box (Blender axes, metres); a room's faces face in, as
    hilight finds the free space inside by them."""
    mesh = bpy.data.meshes.new(name)
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=1.0)
    bmesh.ops.subdivide_edges(bm, edges=bm.edges[:], cuts=cuts, use_grid_fill=True)
    if inward:
        bmesh.ops.reverse_faces(bm, faces=bm.faces[:])
    bm.to_mesh(mesh)
    bm.free()
    obj = bpy.data.objects.new(name, mesh)
    obj.matrix_world = Matrix.Translation(centre) @ Matrix.Diagonal((*size, 1.0))
    obj.data.materials.append(material)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def build_room():
    """A 4 × 3 m room, 2.5 m high, with a table-sized block (Blender: Z up)."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    room = box("room", (2.0, -1.5, 1.25), (4.0, 3.0, 2.5), 15, lambert("walls", (0.7, 0.7, 0.7)), inward=True)
    block = box("block", (1.4, -1.2, 0.4), (0.8, 0.6, 0.8), 3, lambert("block", (0.4, 0.35, 0.3)))
    return [room, block]


def run_hilight(*argv):
    done = subprocess.run([args.hilight, *argv], capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"hilight {' '.join(argv)}: {done.stderr.strip()}")
    return done


def read_ply(path):
    """hilight's render PLY: binary little-endian vertex floats; positions and RGB."""
    with open(path, "rb") as f:
        header = b""
        while not header.endswith(b"end_header\n"):
            header += f.readline()
        lines = header.decode().split("\n")
        count = int(next(l for l in lines if l.startswith("element vertex")).split()[2])
        names = []
        for l in lines[lines.index(next(l for l in lines if l.startswith("element vertex"))) + 1:]:
            if not l.startswith("property"):
                break
            names.append(l.split()[-1])
        data = numpy.frombuffer(f.read(count * 4 * len(names)), dtype="<f4").reshape(count, len(names))
    column = {n: i for i, n in enumerate(names)}
    return data[:, [column[c] for c in "xyz"]], data[:, [column[c] for c in ("red", "green", "blue")]]


def paint_render_of(hb, lights_path, attribute="wanted"):
    """Renders the scene the add-on writes under the lights with hilight and
    paints it onto the meshes, vertex by vertex: the target a designer would
    have painted if they had wanted exactly these lights."""
    scene_path = os.path.join(args.work, "painted_scene.obj")
    hb.scene_io.write_scene(bpy.context, scene_path)
    run_hilight("render", scene_path, "--unit", "m", "--lights", lights_path, "-o", os.path.join(args.work, "truth.ply"))
    points, rgb = read_ply(os.path.join(args.work, "truth.ply"))
    tree = kdtree.KDTree(len(points))
    for i, p in enumerate(points):
        tree.insert(p, i)
    tree.balance()
    worst = 0.0
    for obj in hb.scene_io.scene_objects(bpy.context):
        mesh = obj.data
        layer = mesh.color_attributes.new(attribute, "FLOAT_COLOR", "POINT")
        values = numpy.empty((len(mesh.vertices), 4), dtype=numpy.float32)
        for v in mesh.vertices:
            p = hb.units.from_blender(obj.matrix_world @ v.co)
            _, index, distance = tree.find(p)
            worst = max(worst, distance)
            values[v.index] = (*rgb[index], 1.0)
        layer.data.foreach_set("color", values.ravel())
    check(worst < 1e-4, f"every Blender vertex is one of hilight's (farthest {worst:.2e} m)")


def step_until_done(run, limit=120.0):
    """What the Solve button's timer does, 4 times a second, until the end."""
    started = time.time()
    result = run.handle(bpy.context, "TIMER")
    statuses = set()
    while "RUNNING_MODAL" in result and time.time() - started < limit:
        statuses.add(run.status_line())
        time.sleep(0.25)
        result = run.handle(bpy.context, "TIMER")
    return result, statuses, time.time() - started


def found_lights(hb):
    return [hb.lights.to_hilight(o) for o in hb.lights.light_objects(bpy.context)]


def match(truth, found, what):
    """Each true light against the nearest found one: within 1 cm and 1%."""
    check(len(found) == len(truth), f"{what}: {len(found)} lights for {len(truth)}")
    for i, t in enumerate(truth):
        nearest = min(found, key=lambda f: (Vector(f["position"]) - Vector(t["position"])).length)
        distance = (Vector(nearest["position"]) - Vector(t["position"])).length
        worst = max(abs(a / b - 1.0) for a, b in zip(nearest["intensity"], t["intensity"]))
        check(distance <= 0.01, f"{what}: light {i} placed {distance * 100:.2f} cm from the truth (≤ 1 cm)")
        check(worst <= 0.01, f"{what}: light {i} intensity off by {worst * 100:.2f}% (≤ 1%)")


def random_lights(rng, count):
    """Seeded point lights inside the room, over the floor, apart (hilight axes, W/sr)."""
    lights = []
    while len(lights) < count:
        p = [rng.uniform(0.6, 3.4), rng.uniform(1.6, 2.2), rng.uniform(0.6, 2.4)]
        if all(math.dist(p, q["position"]) > 1.2 for q in lights):
            lights.append({"type": "point", "position": p, "intensity": [rng.uniform(1.0, 3.0) for _ in range(3)]})
    return lights


def case_solve():
    build_room()  # factory settings first: they unload add-ons
    hb = install_addon()
    truth = random_lights(random.Random(args.seed), 2)
    truth_path = os.path.join(args.work, "truth.json")
    with open(truth_path, "w") as f:
        json.dump({"lights": truth}, f)
    paint_render_of(hb, truth_path)
    settings = bpy.context.scene.hilight
    settings.attribute = "wanted"
    settings.light_kind = "POINT"

    # Solve, through the modal step, automatic count.
    run = hb.runner.Run(bpy.context, "solve")
    result, statuses, seconds = step_until_done(run)
    print(f"solve: {run.message} ({seconds:.1f} s)")
    check(result == {"FINISHED"}, f"Solve finished ({result}, {run.message})")
    check(any("Esc cancels" in s for s in statuses), f"the status bar showed progress: {sorted(statuses)[:3]}")
    check(any(s.split(": ", 1)[1][:1].isalpha() and "starting" not in s for s in statuses) or seconds < 1.0,
          "hilight's stages reached the status line")
    check(not os.path.exists(run.folder), "its temporary folder is gone")
    match(truth, found_lights(hb), "Solve")
    objects = hb.lights.light_objects(bpy.context)
    check(all(o.users_collection[0].name == "hilight lights" for o in objects), "the lights are in the 'hilight lights' collection")
    check(all(o.data.type == "POINT" for o in objects), "point lights come back as Blender point lights")
    for o in objects:
        f = hb.lights.figures(o)
        light = hb.lights.to_hilight(o)
        peak = max(light["intensity"])
        check(abs(o.data.energy - 4 * math.pi * peak) <= 1e-4 * o.data.energy and abs(f["watts"] - o.data.energy) < 1e-6,
              f"{o.name}: Blender power {o.data.energy:.3f} W = 4π × {peak:.4f} W/sr")
        check(abs(f["candela"] - 683 * hb.units.luminance(light["intensity"])) < 1e-6 * f["candela"]
              and abs(f["lumens"] - 4 * math.pi * f["candela"]) < 1e-6 * f["lumens"],
              f"{o.name}: panel figures {f['candela']:.0f} cd, {f['lumens']:.0f} lm, {f['watts']:.1f} W")

    # Fine-tune after the user moves a light 15 cm (the operator itself, as a script calls it).
    moved = objects[0]
    moved.location.x += 0.15
    moved.location.z -= 0.05
    check(bpy.ops.hilight.fine_tune() == {"FINISHED"}, "Fine-tune finished")
    match(truth, found_lights(hb), "Fine-tune after a light was moved 16 cm")

    # Add light after the user deletes one.
    doomed = hb.lights.light_objects(bpy.context)[1]
    bpy.data.objects.remove(doomed, do_unlink=True)
    check(len(hb.lights.light_objects(bpy.context)) == 1, "one light deleted")
    check(bpy.ops.hilight.add_light() == {"FINISHED"}, "Add light finished")
    match(truth, found_lights(hb), "Add light after one was deleted")

    # Esc: hilight is stopped, the lights stay as they were.
    before = [o.name for o in hb.lights.light_objects(bpy.context)]
    run = hb.runner.Run(bpy.context, "solve")
    check(run.handle(bpy.context, "TIMER") == {"RUNNING_MODAL"}, "a second Solve runs")
    check(run.handle(bpy.context, "MOUSEMOVE") == {"PASS_THROUGH"}, "other events pass through while it runs")
    check(run.handle(bpy.context, "ESC") == {"CANCELLED"}, "Esc cancels it")
    check(run.job.proc.poll() is not None, f"hilight was stopped (exit {run.job.proc.poll()})")
    check([o.name for o in hb.lights.light_objects(bpy.context)] == before, "the lights are untouched")

    # Work-plane: a 1 m desk top above the block to receive 300 lux, one light.
    mesh = bpy.data.meshes.new("desk")
    bm = bmesh.new()
    bmesh.ops.create_grid(bm, x_segments=8, y_segments=8, size=0.5)
    bm.to_mesh(mesh)
    bm.free()
    desk = bpy.data.objects.new("desk", mesh)
    desk.location = (1.4, -1.2, 0.81)
    desk.data.materials.append(lambert("desk", (0.5, 0.5, 0.5)))
    bpy.context.scene.collection.objects.link(desk)
    settings.target_kind, settings.workplane, settings.lux, settings.count = "WORKPLANE", desk, 300.0, 1
    run = hb.runner.Run(bpy.context, "solve")
    check(run.argv[run.argv.index("--units"):][:4] == ["--units", "photometric", "--target-quantity", "illuminance"],
          f"a work-plane is a lux target: {' '.join(run.argv[run.argv.index('--bounces'):])}")
    result, _, seconds = step_until_done(run)
    lamps = found_lights(hb)
    check(result == {"FINISHED"} and len(lamps) == 1 and lamps[0]["position"][1] > 0.82,
          f"the work-plane solve found 1 light above the desk ({run.message}, {seconds:.1f} s)")
    bpy.data.objects.remove(desk, do_unlink=True)
    settings.target_kind, settings.count = "PAINT", 0

    # Errors: one line, with the reason.
    prefs = bpy.context.preferences.addons["hilight_blender"].preferences
    prefs.executable = os.path.join(args.work, "no-such-hilight")
    try:
        hb.runner.Run(bpy.context, "solve")
        check(False, "a missing executable is refused")
    except hb.scene_io.InputError as e:
        check("\n" not in str(e) and "no-such-hilight" in str(e) and "preferences" in str(e), f"missing executable: {e}")
    prefs.executable = os.path.abspath(args.hilight)
    settings.attribute = "never painted"
    try:
        hb.runner.Run(bpy.context, "solve")
        check(False, "an unpainted scene is refused")
    except hb.scene_io.InputError as e:
        check("\n" not in str(e) and "never painted" in str(e), f"unpainted: {e}")
    settings.attribute = "wanted"
    # A failure inside hilight: an area light no scene unit allows.
    settings.light_kind = "LUMINAIRE"
    settings.luminaire = os.path.join(args.work, "truth.json")  # not a photometry file
    run = hb.runner.Run(bpy.context, "solve")
    result, _, _ = step_until_done(run)
    check(result == {"CANCELLED"} and run.state == "failed", f"a failed hilight run is an error ({run.state})")
    check("\n" not in run.message and "truth.json" in run.message, f"its one line names the reason: {run.message}")
    finish()


def case_numpy():
    # Debian 12: Blender 3.4 with numpy 1.24, which has no numpy.bool.
    if "bool" in numpy.__dict__:
        del numpy.bool  # as Debian's numpy 1.24 is, if this one is older
    glb = os.path.join(args.work, "room.glb")
    run_hilight("export", os.path.join(os.path.dirname(__file__), "..", "..", "scenes", "room.obj"),
                "--lights", os.path.join(os.path.dirname(__file__), "cycles_room_lights.json"), "-o", glb)
    try:
        bpy.ops.import_scene.gltf(filepath=glb)
        broke = None
    except Exception as e:  # what a Debian user saw
        text = str(e)
        broke = next((l.strip() for l in text.splitlines() if "bool" in l), text.strip().splitlines()[-1])
    print(f"without the add-on: {broke}")
    check(broke is not None and "bool" in broke, f"without the add-on Blender 3.4's importer breaks on numpy.bool: {broke}")
    bpy.ops.wm.read_factory_settings(use_empty=True)
    install_addon()
    check("bool" in numpy.__dict__, "enabling the add-on gives numpy.bool back")
    bpy.ops.import_scene.gltf(filepath=glb)
    meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
    lamps = [o for o in bpy.context.scene.objects if o.type == "LIGHT"]
    check(len(meshes) > 0 and len(lamps) == 4, f"then hilight's glTF imports: {len(meshes)} meshes, {len(lamps)} lights")
    addon_utils.disable("hilight_blender", default_set=True, handle_error=None)
    check("hilight_blender" not in bpy.context.preferences.addons and not hasattr(bpy.types.Scene, "hilight"),
          "the add-on disables cleanly (its settings and classes unregistered)")
    finish()


CAMERA = ((0.3, 2.2, 0.3), (3.0, 0.6, 2.5), 80.0)  # hilight axes: a corner, looking at the block
WIDTH, HEIGHT = 80, 60


def cycles_render(hb, path, bounces, samples):
    """The scene as it is (Lambertian materials, the add-on's lights) in Cycles:
    black world, diffuse bounces only, no clamping, linear 32-bit EXR."""
    scene = bpy.context.scene
    world = bpy.data.worlds.new("black")
    world.use_nodes = False
    world.color = (0.0, 0.0, 0.0)
    scene.world = world
    columns, lens = hb.units.camera(*CAMERA)
    data = bpy.data.cameras.new("hilight camera")
    data.sensor_fit, data.sensor_height, data.lens = "VERTICAL", 24.0, lens
    data.clip_start = 1e-3
    camera = bpy.data.objects.new("hilight camera", data)
    m = Matrix.Identity(4)
    for c, v in enumerate(columns):
        for r in range(3):
            m[r][c] = v[r]
    camera.matrix_world = m
    scene.collection.objects.link(camera)
    scene.camera = camera
    render = scene.render
    render.engine = "CYCLES"
    render.resolution_x, render.resolution_y, render.resolution_percentage = WIDTH, HEIGHT, 100
    render.threads_mode, render.threads = "FIXED", 2
    render.image_settings.file_format, render.image_settings.color_depth = "OPEN_EXR", "32"
    render.filepath, render.use_file_extension = path, False
    c = scene.cycles
    c.device, c.samples, c.use_adaptive_sampling, c.use_denoising, c.seed = "CPU", samples, False, False, 5
    c.max_bounces = c.diffuse_bounces = bounces
    c.glossy_bounces = c.transmission_bounces = c.volume_bounces = c.transparent_max_bounces = 0
    c.caustics_reflective = c.caustics_refractive = False
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.pixel_filter_type, c.filter_width = "BOX", 1.0
    scene.view_settings.view_transform, scene.view_settings.exposure = "Standard", 0.0
    started = time.time()
    bpy.ops.render.render(write_still=True)
    return time.time() - started


def load_exr(path):
    image = bpy.data.images.load(path, check_existing=False)
    image.colorspace_settings.name = "Linear"
    w, h = image.size
    pixels = numpy.empty(w * h * 4, dtype=numpy.float32)
    image.pixels.foreach_get(pixels)
    bpy.data.images.remove(image)
    return pixels.reshape(h, w, 4)


def write_downlight_ies(path, multiplier, ballast, ballast_lamp):
    """An LM-63 type C downlight, rotationally symmetric: 1000·cos^1.5 γ cd
    (times the factors) every 5° to the horizontal, where it ends at 0."""
    angles = list(range(0, 95, 5))
    candela = [1000.0 * max(0.0, math.cos(math.radians(a))) ** 1.5 for a in angles]
    with open(path, "w") as f:
        f.write("IESNA:LM-63-2002\n[TEST] hilight add-on test downlight\nTILT=NONE\n")
        f.write(f"1 -1 {multiplier} {len(angles)} 1 1 2 0 0 0\n{ballast} {ballast_lamp} 20\n")
        f.write(" ".join(str(a) for a in angles) + "\n0\n")
        f.write(" ".join(f"{c:.4f}" for c in candela) + "\n")


def write_panel_ldt(path):
    """A EULUMDAT panel (Isym 4: C0–C90 stored), wide along C0–C180 and
    narrow across it, so a plane turned the wrong way shows: (120 + 90 cos 2C
    sin γ) cos γ cd/klm below the horizontal, 2000 lm, 20 W."""
    c_angles, gammas = list(range(0, 360, 15)), list(range(0, 185, 5))
    stored = [c for c in c_angles if c <= 90]
    lines = ["hilight add-on test", "1", "4", str(len(c_angles)), "15", str(len(gammas)), "5", "report", "test panel", "P1",
             "panel.ldt", "2026-11-27"] + ["600"] * 5 + ["0"] * 4 + ["100", "80", "1", "0", "1", "1", "LED", "2000", "3000", "80", "20"]
    lines += ["0.5"] * 10 + [str(c) for c in c_angles] + [str(g) for g in gammas]
    for c in stored:
        for g in gammas:
            cos_g = math.cos(math.radians(g))
            value = (120.0 + 90.0 * math.cos(math.radians(2 * c)) * math.sin(math.radians(g))) * cos_g if g < 90 else 0.0
            lines.append(f"{max(0.0, value):.4f}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def case_cycles():
    """The add-on's lights, one of each kind Blender draws, in Cycles against
    hilight's render of the same lights file: the image's mean radiance."""
    build_room()
    hb = install_addon()
    rng = random.Random(args.seed)
    lights = [
        {"type": "point", "position": [rng.uniform(2.6, 3.4), rng.uniform(1.6, 2.2), rng.uniform(0.5, 1.0)],
         "intensity": [rng.uniform(1.0, 3.0) for _ in range(3)]},
        {"type": "spot", "position": [rng.uniform(1.0, 1.8), 2.3, rng.uniform(1.0, 1.4)],
         "direction": [0.3, -0.9539392, 0.0], "cutoff_deg": rng.uniform(30.0, 45.0), "falloff_deg": 10.0,
         "intensity": [rng.uniform(3.0, 6.0) for _ in range(3)]},
        {"type": "rectangle", "position": [rng.uniform(2.5, 3.0), 2.45, rng.uniform(2.0, 2.4)], "direction": [0, -1, 0],
         "up": [1, 0, 0], "size": [0.8, 0.4], "intensity": [rng.uniform(2.0, 4.0) for _ in range(3)]},
    ]
    # A luminaire: a downlight's IES profile whose candela multiplier and
    # ballast factors Cycles folds into its IES node (ies_level.py).
    profile = os.path.join(args.work, "downlight.ies")
    write_downlight_ies(profile, multiplier=2.0, ballast=0.9, ballast_lamp=0.95)
    lights.append({"type": "luminaire", "profile": profile, "position": [rng.uniform(1.6, 2.4), 2.3, rng.uniform(1.2, 1.8)],
                   "direction": [0.0, -1.0, 0.0], "intensity": [rng.uniform(2.0, 4.0) for _ in range(3)]})
    # A EULUMDAT luminaire, which Cycles cannot read: the add-on gives Cycles
    # the IES text hilight writes for it (ies_level.py), turned about its aim.
    panel = os.path.join(args.work, "panel.ldt")
    write_panel_ldt(panel)
    lights.append({"type": "luminaire", "profile": panel, "position": [rng.uniform(2.6, 3.2), 2.3, rng.uniform(2.2, 2.8)],
                   "direction": [0.0, -1.0, 0.0], "spin_deg": rng.uniform(20.0, 70.0),
                   "intensity": [rng.uniform(2.0, 4.0) for _ in range(3)]})
    lights_path = os.path.join(args.work, "lights.json")
    with open(lights_path, "w") as f:
        json.dump({"lights": lights}, f)
    made = hb.lights.bring_in(bpy.context, lights)
    check([o.data.type for o in made] == ["POINT", "SPOT", "AREA", "POINT", "POINT"],
          "point, spot, rectangle and luminaires come in as Blender point, spot, area and point lights")
    ldt_nodes = [n for n in made[4].data.node_tree.nodes if n.type == "TEX_IES"] if made[4].data.node_tree else []
    check(len(ldt_nodes) == 1 and ldt_nodes[0].mode == "INTERNAL" and ldt_nodes[0].ies is not None,
          "the EULUMDAT luminaire has an IES node reading hilight's IES text, kept in the .blend")
    back = hb.lights.to_hilight(made[4])
    turn = (back["spin_deg"] - lights[4]["spin_deg"] + 180.0) % 360.0 - 180.0
    check(abs(turn) < 1e-3 and max(abs(a - b) for a, b in zip(back["direction"], lights[4]["direction"])) < 1e-6,
          f"the luminaire's aim and spin read back from Blender ({back['spin_deg']:.4f} for {lights[4]['spin_deg']:.4f})")
    scene_path = os.path.join(args.work, "scene.obj")
    hb.scene_io.write_scene(bpy.context, scene_path)
    camera = ",".join("%g" % v for v in (*CAMERA[0], *CAMERA[1], CAMERA[2]))
    # Direct light of each light alone (each conversion, little noise), then
    # all of them with every bounce.
    runs = [(f"{light['type']}_{i}", [i], "0", 0, 16, 0.01) for i, light in enumerate(lights)]
    runs.append(("all", [0, 1, 2], "all", 128, 64, 0.03))
    for name, chosen, bounces, cycles_bounces, samples, tolerance in runs:
        subset = os.path.join(args.work, f"{name}.json")
        with open(subset, "w") as f:
            json.dump({"lights": [lights[i] for i in chosen]}, f)
        for i, o in enumerate(made):
            o.hide_render = i not in chosen
        ours = os.path.join(args.work, f"hilight_{name}.exr")
        theirs = os.path.join(args.work, f"cycles_{name}.exr")
        run_hilight("render", scene_path, "--unit", "m", "--lights", subset, "-o", ours, "--camera", camera,
                    "--width", str(WIDTH), "--height", str(HEIGHT), "--bounces", bounces)
        seconds = cycles_render(hb, theirs, cycles_bounces, samples)
        h, c = load_exr(ours), load_exr(theirs)
        covered = h[..., 3] > 0.5
        ratio = h[..., :3].sum(axis=2)[covered].mean() / c[..., :3].sum(axis=2)[covered].mean()
        check(covered.mean() > 0.99 and c[..., :3].sum() > 0, f"{name}: both images cover the frame, lit")
        check(abs(ratio - 1.0) <= tolerance,
              f"{name} (hilight --bounces {bounces}): hilight/Cycles pixel mean {ratio:.4f} (within {tolerance:.0%}; Cycles {samples} samples, {cycles_bounces} bounces, {seconds:.1f} s)")
        if name.startswith("luminaire"):
            # Where the light falls, not only how much: a profile turned or
            # mirrored moves its wide lobe to other blocks of the image.
            hs, cs = h[..., :3].sum(axis=2), c[..., :3].sum(axis=2)
            bh, bw = hs.shape[0] // 4, hs.shape[1] // 4
            ratios = [hs[y:y + bh, x:x + bw].mean() / cs[y:y + bh, x:x + bw].mean()
                      for y in range(0, 4 * bh, bh) for x in range(0, 4 * bw, bw)
                      if cs[y:y + bh, x:x + bw].mean() > 0.05 * cs.mean()]
            worst = max(abs(r - 1.0) for r in ratios)
            check(worst <= 0.05, f"{name}: each lit 4x4 block of the image within 5% of Cycles' (worst {worst:.3f}, {len(ratios)} blocks)")
    finish()


if args.case == "cycles":
    case_cycles()
elif args.case == "solve":
    case_solve()
elif args.case == "numpy":
    case_numpy()
