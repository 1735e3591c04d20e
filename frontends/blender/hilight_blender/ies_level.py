"""The level of Cycles' IES Texture node, so that a luminaire's light is hilight's.

Cycles reads an IES LM-63 file's candela times the candela multiplier, the
ballast factor, the ballast-lamp factor and a fixed 4π/177.83 (its candela to
watt conversion, util/ies.cpp), and its node's Fac is that value. hilight's
luminaire intensity is the light at the profile's peak, its shape the profile
over its own peak. A Fac divided by its largest value is that shape, so the
add-on multiplies the node by 1 / cycles_peak(file): the light's Power then
sets the peak, as for a point light.
"""

# Cycles' candela to watt factor, 4π/177.83 (the D65 illuminant's luminous efficacy).
CYCLES_CANDELA_TO_WATT = 0.0706650768394


class NotIes(ValueError):
    """A profile Cycles' IES node cannot read (EULUMDAT, a damaged file)."""


def _numbers(text):
    for token in text.replace(",", " ").split():
        yield float(token)


def cycles_peak(path):
    """The largest Fac Cycles' IES Texture node gives for the LM-63 file at `path`."""
    with open(path, "r", encoding="latin-1") as f:
        text = f.read()
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
