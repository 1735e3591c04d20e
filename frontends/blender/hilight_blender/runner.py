"""One Solve, Fine-tune or Add light: files written, hilight started, polled,
the lights brought back. The modal operator drives it from a timer; scripts
and tests drive the same object (step / handle)."""
import json
import os
import shutil
import tempfile

from . import job as job_module
from . import lights, scene_io, units

ADDON_ID = __package__


def preferences(context):
    addon = context.preferences.addons.get(ADDON_ID)
    return addon.preferences if addon is not None else None


def executable(context):
    prefs = preferences(context)
    chosen = prefs.executable.strip() if prefs is not None else ""
    if chosen:
        path = os.path.abspath(os.path.expanduser(chosen))
        if not os.access(path, os.X_OK):
            raise scene_io.InputError(f"hilight executable {path} not found or not executable (add-on preferences)")
        return path
    found = shutil.which("hilight")
    if found is None:
        raise scene_io.InputError("hilight not found on PATH: set its path in the add-on's preferences")
    return found


def photometric(settings):
    return settings.units != "RADIANCE" or settings.target_kind == "WORKPLANE"


def solve_arguments(context, settings, mode, folder):
    """hilight solve's command line for these settings; writes its inputs."""
    scene_path = os.path.join(folder, "scene.obj")
    target_path = os.path.join(folder, "target.ply")
    scene_io.write_scene(context, scene_path)
    scene_io.write_target(context, target_path, settings)
    argv = [executable(context), "solve", scene_path, "--target", target_path, "--unit", "m",
            "-o", os.path.join(folder, "lights.json"), "--report", os.path.join(folder, "report.json"),
            "--bounces", settings.bounces.lower()]
    if photometric(settings):
        argv += ["--units", "photometric", "--target-quantity",
                 "illuminance" if settings.target_kind == "WORKPLANE" or settings.units == "LUX" else "luminance"]
    if settings.count > 0:
        argv += ["--lights", str(settings.count)]
    if settings.placement == "ANYWHERE":  # the panel's choice, not hilight's default for buildings (the ceiling)
        argv += ["--place", "anywhere"]
    elif settings.placement == "CEILING":
        argv += ["--place", f"ceiling:{settings.ceiling_offset:g}"]
    elif settings.placement == "REGION":
        if settings.region is None:
            raise scene_io.InputError("pick the object whose bounds are the region lights may stand in")
        argv += ["--place", "box:" + scene_io.region_box(context, settings.region)]
    if settings.light_kind == "LUMINAIRE":
        profile = bpy_abspath(settings.luminaire)
        if not profile or not os.path.isfile(profile):
            raise scene_io.InputError(f"luminaire file {profile or '(none)'} not found: pick an IES or EULUMDAT file")
        argv += ["--luminaire", profile]
    elif settings.light_kind == "AREA":
        argv += ["--area-light", f"rectangle:{settings.area_width:g}x{settings.area_height:g}"]
    elif settings.light_kind == "POINT":
        argv += ["--no-propose-spots"]
    prefs = preferences(context)
    if prefs is not None and prefs.threads > 0:
        argv += ["--threads", str(prefs.threads)]
    if mode != "solve":
        current = [lights.to_hilight(o, scene_io.metres(context)) for o in lights.light_objects(context)]
        if not current:
            raise scene_io.InputError("no lights in the 'hilight lights' collection to " + ("fine-tune" if mode == "fine-tune" else "add to") + ": Solve first")
        factor = units.EFFICACY if photometric(settings) else 1.0
        for light in current:
            light["intensity"] = [c * factor for c in light["intensity"]]
        initial = os.path.join(folder, "initial.json")
        with open(initial, "w") as f:
            json.dump({"length_unit": "m", "lights": current}, f, indent=1)
        argv += ["--initial", initial, "--mode", mode]
    return argv


def bpy_abspath(path):
    import bpy
    return os.path.abspath(bpy.path.abspath(path)) if path else ""


class Run:
    """States: running, done, failed, cancelled."""

    def __init__(self, context, mode="solve"):
        self.mode = mode
        self.state = "running"
        self.message = ""
        self.settings = context.scene.hilight
        self.photometric = photometric(self.settings)
        self.scale = scene_io.metres(context)
        self.folder = tempfile.mkdtemp(prefix="hilight-blender-")
        try:
            self.argv = solve_arguments(context, self.settings, mode, self.folder)
            self.job = job_module.Job(self.argv, cwd=self.folder)
            try:
                self.job.start()
            except OSError as e:
                raise scene_io.InputError(f"cannot run {self.argv[0]}: {e.strerror or e}")
        except Exception:
            shutil.rmtree(self.folder, ignore_errors=True)
            raise

    def status_line(self):
        stage = self.job.last_line()
        if stage.startswith("hilight: "):
            stage = stage[len("hilight: "):]
        return f"hilight {self.mode}: {stage or 'starting'} ({self.job.seconds():.0f} s) — Esc cancels"

    def step(self):
        """Polls hilight; the state."""
        if self.state != "running":
            return self.state
        code = self.job.poll()
        if code is None:
            return self.state
        if code == 0 or (code == 3 and os.path.exists(os.path.join(self.folder, "lights.json"))):
            self.state = "finished"  # lights to bring in (exit 3: above --max-dbar, lights still written)
        else:
            self.state = "failed"
            self.message = self.error_line(code)
        return self.state

    def error_line(self, code):
        lines = [l for l in self.job.lines() if not l.endswith("...")]
        reason = lines[-1] if lines else f"hilight exited with code {code}"
        return reason if reason.startswith("hilight") else "hilight: " + reason

    def apply(self, context):
        """Brings the lights in; the summary line."""
        with open(os.path.join(self.folder, "lights.json")) as f:
            found = json.load(f)["lights"]
        factor = 1.0 / units.EFFICACY if self.photometric else 1.0
        for light in found:
            if "intensity" in light:
                light["intensity"] = [c * factor for c in units.rgb(light["intensity"])]
            if light.get("profile") and not os.path.isabs(light["profile"]):
                light["profile"] = os.path.join(self.folder, light["profile"])
        made = lights.bring_in(context, found, self.scale)
        summary = self.job.last_line()
        self.state = "done"
        self.message = summary or f"hilight: {len(made)} lights"
        self.report = {}
        try:
            with open(os.path.join(self.folder, "report.json")) as f:
                self.report = json.load(f)
        except (OSError, ValueError):
            pass
        context.scene.hilight.last_summary = self.message
        return self.message

    def cancel(self):
        self.job.cancel()
        self.state = "cancelled"
        self.message = "hilight: cancelled"

    def handle(self, context, event_type):
        """The modal operator's step: TIMER polls, ESC cancels. Returns the
        operator's result set."""
        if event_type == "ESC":
            self.cancel()
            self.cleanup()
            return {"CANCELLED"}
        if event_type != "TIMER":
            return {"PASS_THROUGH"}
        state = self.step()
        if state == "running":
            return {"RUNNING_MODAL"}
        if state == "finished":
            try:
                self.apply(context)
            except (OSError, ValueError, KeyError) as e:
                self.state = "failed"
                self.message = f"hilight: its lights could not be read: {e}"
        self.cleanup()
        return {"FINISHED"} if self.state == "done" else {"CANCELLED"}

    def cleanup(self):
        if os.environ.get("HILIGHT_BLENDER_KEEP"):  # for a look at what was run
            return
        shutil.rmtree(self.folder, ignore_errors=True)
