"""hilight's lights in Blender's terms: the one place the conversions live.

No bpy here, so the tests and tests/blender/cycles_reference.py use the same
numbers as the add-on. hilight: intensity I in W/sr per RGB channel, +Y up.
Blender: a light's Power (W) and Color (largest channel 1), +Z up.
The factors were measured against Cycles 3.4 on a plane (docs/blender.md §6):
  point      Power = 4π·I     (Cycles: I = P/4π)
  spot       Power = 4π·I, its cone hilight's smoothstep in cos α
  area       Power = 4·I₀     (Cycles 3.4's area light has I₀ = P/4 along its normal)
"""
import math

EFFICACY = 683.0  # lm/W at 555 nm: cd = 683 × W/sr (docs/rendering-model.md "Units")


def to_blender(v):
    """hilight / glTF axes (+Y up) to Blender's (+Z up), as Blender's glTF importer maps them."""
    return (v[0], -v[2], v[1])


def from_blender(v):
    return (v[0], v[2], -v[1])


def rgb(intensity):
    """A light's intensity as three channels (a single number is white)."""
    if isinstance(intensity, (int, float)):
        return [float(intensity)] * 3
    return [float(c) for c in intensity]


def peak_and_colour(intensity):
    """Blender splits an RGB intensity into its largest channel and a colour."""
    channels = rgb(intensity)
    peak = max(channels)
    colour = [c / peak for c in channels] if peak > 0 else [1.0, 1.0, 1.0]
    return peak, colour


def luminance(channels):
    """Rec. 709 Y: one figure of three channels, as hilight's report uses."""
    return 0.2126 * channels[0] + 0.7152 * channels[1] + 0.0722 * channels[2]


WATTS_PER_W_SR = {"point": 4.0 * math.pi, "spot": 4.0 * math.pi, "luminaire": 4.0 * math.pi,
                  "rectangle": 4.0, "disk": 4.0, "line": 4.0}


def blender_watts(kind, peak):
    """Blender Power (W) of a hilight light whose largest channel is `peak` W/sr."""
    return WATTS_PER_W_SR[kind] * peak


def peak_from_watts(kind, watts):
    return watts / WATTS_PER_W_SR[kind]


def spot_blend(cutoff_deg, falloff_deg):
    """Blender's Spot Blend whose edge is hilight's: both are a smoothstep in
    cos α, Blender's over (1 − cos(size/2))·blend, hilight's over
    cos(cutoff − falloff) − cos(cutoff)."""
    c_out = math.cos(math.radians(cutoff_deg))
    c_in = math.cos(math.radians(max(cutoff_deg - falloff_deg, 0.0)))
    return 0.0 if c_out >= 1.0 else min(max((c_in - c_out) / (1.0 - c_out), 0.0), 1.0)


def falloff_from_blend(cutoff_deg, blend):
    c_out = math.cos(math.radians(cutoff_deg))
    c_in = min(c_out + blend * (1.0 - c_out), 1.0)
    return cutoff_deg - math.degrees(math.acos(c_in))


def solid_angle(light):
    """Ω of Φ = I·Ω (hilight's luminous_flux_lm): 4π for a point, the cone for
    a spot (its smoothstep edge counts half), π for a Lambertian source (its
    flux is π·I₀); None for a luminaire (its profile decides)."""
    kind = light.get("type", "point")
    if kind == "point":
        return 4.0 * math.pi
    if kind == "spot":
        c_out = math.cos(math.radians(light["cutoff_deg"]))
        c_in = math.cos(math.radians(light["cutoff_deg"] - light.get("falloff_deg", 0.0)))
        return 2.0 * math.pi * (1.0 - c_in) + math.pi * (c_in - c_out)
    if kind in ("rectangle", "disk", "line") and "profile" not in light:
        return math.pi
    return None


def figures(light):
    """What the panel shows of one hilight light (intensity in W/sr):
    candela (Y of the peak), lumens (None where the profile decides) and Blender watts."""
    channels = rgb(light.get("intensity", 0.0))
    kind = light.get("type", "point")
    y = luminance(channels)
    omega = solid_angle(light)
    return {"candela": EFFICACY * y,
            "lumens": None if omega is None else EFFICACY * y * omega,
            "watts": blender_watts(kind, max(channels))}


def camera(eye, target, fov_deg):
    """hilight's --camera (eye, target, vertical fov; +Y up; framework/src/camera.cpp)
    as a Blender camera: its world matrix columns (right, up, back, eye, in
    Blender's axes) and the lens (mm) on a 24 mm vertical sensor."""
    forward = [t - e for t, e in zip(target, eye)]
    norm = math.sqrt(sum(c * c for c in forward))
    forward = [c / norm for c in forward]
    hint = (0.0, 0.0, -1.0) if abs(forward[1]) > 0.99 else (0.0, 1.0, 0.0)

    def cross(a, b):
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

    right = cross(forward, hint)
    norm = math.sqrt(sum(c * c for c in right))
    right = [c / norm for c in right]
    up = cross(right, forward)
    columns = [to_blender(right), to_blender(up), to_blender([-c for c in forward]), to_blender(eye)]
    return columns, 12.0 / math.tan(math.radians(fov_deg) / 2.0)
