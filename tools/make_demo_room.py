#!/usr/bin/env python3
"""Writes scenes/room.obj + room.mtl: the furnished room of
framework/src/scene_builders.cpp (furnished_room) as an OBJ a user can open.
tests/test_scene_io.cpp checks that the two stay the same scene."""
import os

BOXES = [  # name, lo, hi, albedo, inward
    ("walls", (0, 0, 0), (6, 3, 5), (0.75, 0.73, 0.70), True),
    ("table_top", (1.2, 0.72, 1.4), (2.8, 0.78, 2.4), (0.55, 0.35, 0.2), False),
] + [("table_leg", (x, 0, z), (x + 0.1, 0.72, z + 0.1), (0.45, 0.3, 0.18), False)
     for x in (1.3, 2.6) for z in (1.5, 2.2)] + [
    ("cabinet", (4.6, 0, 0.3), (5.7, 1.9, 0.9), (0.3, 0.45, 0.6), False),
    ("bench", (3.4, 0, 3.6), (5.2, 0.45, 4.3), (0.6, 0.2, 0.2), False),
    ("pillar", (0.8, 0, 3.8), (1.2, 3, 4.2), (0.8, 0.8, 0.78), False),
]
FACES = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = os.path.join(here, "..", "scenes")
    obj, mtl, nv, mats = [], [], 0, {}
    obj.append("# hilight demo: a furnished 6 x 3 x 5 room (tools/make_demo_room.py)\nmtllib room.mtl")
    for i, (name, lo, hi, albedo, inward) in enumerate(BOXES):
        mat = f"{name}_{i}"
        mtl.append(f"newmtl {mat}\nKd {albedo[0]:g} {albedo[1]:g} {albedo[2]:g}\n")
        obj.append(f"o {mat}\nusemtl {mat}")
        for f in FACES:
            quad = list(f)
            if inward:
                quad[1], quad[3] = quad[3], quad[1]
            for c in quad:
                p = [hi[k] if c >> k & 1 else lo[k] for k in range(3)]
                obj.append("v %g %g %g" % tuple(p))
            obj.append(f"f {nv + 1} {nv + 2} {nv + 3} {nv + 4}")
            nv += 4
    with open(os.path.join(out, "room.obj"), "w") as fh:
        fh.write("\n".join(obj) + "\n")
    with open(os.path.join(out, "room.mtl"), "w") as fh:
        fh.write("\n".join(mtl))


if __name__ == "__main__":
    main()
