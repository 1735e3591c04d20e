"""The level of Cycles' IES Texture node, so that a luminaire's light is hilight's.

Cycles reads an IES LM-63 file's candela times the candela multiplier, the
ballast factor, the ballast-lamp factor and a fixed 4π/177.83 (its candela to
watt conversion, util/ies.cpp), and its node's Fac is that value. hilight's
luminaire intensity is the light at the profile's peak, its shape the profile
over its own peak. A Fac divided by its largest value is that shape, so the
add-on multiplies the node by 1 / cycles_peak(file): the light's Power then
sets the peak, as for a point light.

Every profile, IES or EULUMDAT (which Cycles cannot read), goes in as the IES
text hilight writes for it (`hilight luminaire F --ies F.ies`: every plane,
the candela hilight reads, factors applied), kept inside the .blend. Its C
planes are mirrored (C → 360° − C): Cycles reads C clockwise about the
light's −Z seen from above (h = atan2(x, y) + π in the light's space), hilight
and LM-63 anticlockwise; the light's frame then turns C = 0 onto hilight's
(lights.py).
"""
import os
import subprocess
import tempfile

# Cycles' candela to watt factor, 4π/177.83 (the D65 illuminant's luminous efficacy).
CYCLES_CANDELA_TO_WATT = 0.0706650768394


class NotIes(ValueError):
    """A profile Cycles' IES node cannot read (EULUMDAT, a damaged file)."""


def _numbers(text):
    for token in text.replace(",", " ").split():
        yield float(token)


def is_eulumdat(path):
    return os.path.splitext(path)[1].lower() == ".ldt"


# Converted profiles by (file, its size and time, the hilight asked): a layout
# of many luminaires of one product runs hilight once, not once a light.
_converted = {}


def ies_for_cycles(path, hilight):
    """The IES LM-63 text hilight writes for the profile at `path`, its C
    planes mirrored for Cycles."""
    stat = os.stat(path)
    key = (os.path.abspath(path), stat.st_size, stat.st_mtime_ns, hilight)
    if key not in _converted:
        _converted[key] = mirrored(ies_written_by_hilight(path, hilight))
    return _converted[key]


def ies_written_by_hilight(path, hilight):
    """The IES LM-63 text hilight writes for the IES or EULUMDAT file at `path`."""
    with tempfile.TemporaryDirectory(prefix="hilight-ies-") as folder:
        out = os.path.join(folder, "profile.ies")
        done = subprocess.run([hilight, "luminaire", path, "--ies", out], capture_output=True, text=True, timeout=60)
        if done.returncode != 0:
            lines = done.stderr.strip().splitlines()
            raise NotIes(lines[-1] if lines else f"{path}: hilight could not convert it (exit {done.returncode})")
        with open(out, "r", encoding="latin-1") as f:
            return f.read()


def mirrored(text):
    """hilight's IES text (TILT=NONE, its planes over the full circle at
    angles symmetric about 180°, or one) with plane C holding what plane
    360° − C held."""
    at = text.find("TILT=NONE\n")
    if at < 0:
        raise NotIes("not IES text as hilight writes it (no TILT=NONE)")
    head, body = text[:at + len("TILT=NONE\n")], text[at + len("TILT=NONE\n"):]
    numbers = body.split()
    vertical, horizontal = int(float(numbers[3])), int(float(numbers[4]))
    start = 13 + vertical + horizontal
    planes = [numbers[start + k * vertical:start + (k + 1) * vertical] for k in range(horizontal)]
    lines = [" ".join(numbers[:10]), " ".join(numbers[10:13]), " ".join(numbers[13:13 + vertical]),
             " ".join(numbers[13 + vertical:start])] + [" ".join(p) for p in reversed(planes)]
    return head + "\n".join(lines) + "\n"


def cycles_peak(path):
    """The largest Fac Cycles' IES Texture node gives for the LM-63 file at `path`."""
    with open(path, "r", encoding="latin-1") as f:
        return cycles_peak_of_text(f.read(), path)


def cycles_peak_of_text(text, path):
    """cycles_peak for LM-63 text (`path` names it in messages)."""
    at = text.find("TILT=")
    if at < 0:
        raise NotIes(f"{path}: no TILT= line (not an IES LM-63 file; Cycles reads no EULUMDAT)")
    line_end = text.find("\n", at)
    tilt = text[at + 5:line_end if line_end >= 0 else len(text)].strip()
    rest = _numbers(text[line_end + 1:] if line_end >= 0 else "")
    try:
        if tilt.upper() == "INCLUDE":
            next(rest)  # lamp-to-luminaire geometry
            for _ in range(2 * int(next(rest))):  # tilt angles and factors
                next(rest)
        next(rest)  # lamps
        next(rest)  # lumens per lamp
        factor = next(rest)  # candela multiplier
        vertical, horizontal = int(next(rest)), int(next(rest))
        next(rest)  # photometric type
        for _ in range(4):  # units, width, length, height
            next(rest)
        factor *= next(rest)  # ballast factor
        factor *= next(rest)  # ballast-lamp photometric factor
        next(rest)  # input watts
        for _ in range(vertical + horizontal):  # the angles
            next(rest)
        candela = [next(rest) for _ in range(vertical * horizontal)]
    except (StopIteration, ValueError) as e:
        raise NotIes(f"{path}: not a complete IES LM-63 file ({e or 'it ends early'})")
    peak = factor * CYCLES_CANDELA_TO_WATT * max(candela, default=0.0)
    if not peak > 0.0:
        raise NotIes(f"{path}: no positive candela value")
    return peak
