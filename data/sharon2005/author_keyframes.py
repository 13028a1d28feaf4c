#!/usr/bin/env python3
"""Writes the hand-authored keyframe files of Sharon & van de Panne 2005 (Figures 5a, 6a, 6c, 7a).

The paper shows its keyframes only as pictures. The poses below were authored by hand, as a user
of the library would, to depict those figures: joint angles in degrees (hip + = extension, knee + =
flexion, ankle + = plantarflexion; torso pitch + = forward lean; docs/models.md), with each foot
given by its world pitch (+ = toe down) from which the ankle angle follows. What this script adds is
bookkeeping a user would otherwise do with a ruler: the root position of each keyframe is placed so
that the named stance-foot point (heel or toe) rests on the ground at the given x, and the stride
(`advance`) is the one that keeps the trailing toe planted across the mirror-image wrap.

Geometry: the 7-link human of Table I (thigh 0.46 m, shin 0.44 m, foot 0.22 m through the ankle at
the sole, heel a quarter of the foot behind the ankle, as models/sharon2005.hpp builds it). The 16-link human uses its own leg lengths (passed in). Run:  python3 author_keyframes.py
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
HEEL_FRACTION = 0.25  # heel behind the ankle, fraction of the foot length (models/sharon2005.hpp)


def leg(root, pitch, hip, knee, foot, L):
    """World heel, toe and the ankle angle of one leg (the foot runs through the ankle at the sole,
    its heel HEEL_FRACTION of its length behind the ankle, as in models/sharon2005.hpp)."""
    th, sh, ft = L
    a = math.radians(pitch + hip)
    k = (root[0] - th * math.sin(a), root[1] - th * math.cos(a))
    b = math.radians(pitch + hip + knee)
    an = (k[0] - sh * math.sin(b), k[1] - sh * math.cos(b))
    f = math.radians(foot)
    back, front = HEEL_FRACTION * ft, (1 - HEEL_FRACTION) * ft
    heel = (an[0] - back * math.cos(f), an[1] + back * math.sin(f))
    toe = (an[0] + front * math.cos(f), an[1] - front * math.sin(f))
    return heel, toe, foot - (pitch + hip + knee)


def place(pitch, R, L, anchor, lengths, ground_slope_deg=0.0):
    """Root (x, z) so that the anchor point (side, 'heel'|'toe', x) lies on the ground z = x tan(slope)."""
    side, point, x = anchor
    legs = {"r": R, "l": L}
    an, toe, _ = leg((0.0, 0.0), pitch, *legs[side], lengths)
    p = an if point == "heel" else toe
    zg = x * math.tan(math.radians(ground_slope_deg))
    root = (x - p[0], zg - p[1])
    out = {s: leg(root, pitch, *l, lengths) for s, l in legs.items()}
    return root, out


def build(name, model, description, figure, keys, end_time, lengths, stance="right",
          slope=0.0, trailing_toe_x=None, extra_defaults=None, upper=None):
    """keys: list of (time, torso pitch, R (hip, knee, foot), L (hip, knee, foot), anchor)."""
    frames = []
    for i, (t, pitch, R, L, anchor) in enumerate(keys):
        root, out = place(pitch, R, L, anchor, lengths, slope)
        pose = {"root_x": round(root[0], 4), "root_z": round(root[1], 4), "root_pitch": pitch}
        for side, (hip, knee, foot) in (("r", R), ("l", L)):
            pose[side + "hip"] = hip
            pose[side + "knee"] = knee
            pose[side + "ankle"] = round(out[side][2], 3)
        if upper is not None:
            pose.update(upper[i])
        frames.append({"time": t, "pose": pose})
        print(f"  {name} key {i} t={t}: root ({root[0]:.3f}, {root[1]:.3f})  "
              f"r heel ({out['r'][0][0]:.3f},{out['r'][0][1]:.3f}) toe ({out['r'][1][0]:.3f},{out['r'][1][1]:.3f})  "
              f"l heel ({out['l'][0][0]:.3f},{out['l'][0][1]:.3f}) toe ({out['l'][1][0]:.3f},{out['l'][1][1]:.3f})")
    # Stride: the trailing (left) toe of keyframe 0 becomes, mirrored and advanced, the right toe
    # that the last keyframe has planted at trailing_toe_x.
    root0, out0 = place(*keys[0][1:], lengths, slope)
    tx = trailing_toe_x if trailing_toe_x is not None else keys[-1][4][2]
    dx = tx - out0["l"][1][0]
    advance = {"root_x": round(dx, 4)}
    if slope != 0.0:
        advance["root_z"] = round(dx * math.tan(math.radians(slope)), 4)
    doc = {
        "format": "gaitsynth.keyframes/1",
        "model": model,
        "description": description,
        "figure": figure,
        "units": "degrees",
        "symmetric": True,
        "stance": stance,
        "end_time": end_time,
        "advance": advance,
    }
    if extra_defaults:
        doc["defaults"] = extra_defaults
    doc["keyframes"] = frames
    with open(os.path.join(HERE, name), "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")
    print(f"wrote {name}: stride {dx:.3f} m per step, {dx / end_time:.2f} m/s")


H7 = (0.46, 0.44, 0.22)

# Figure 5a: a normal walk. Right heel strike -> loading -> mid-stance -> heel off; the left leg
# pushes off, swings through with the knee bent and reaches forward. One step = 0.55 s.
build("normal_walk.keyframes.json", "sharon2005_human7",
      "Normal walk of the 7-link human (Sharon & van de Panne 2005, Figure 5a), one step listed; "
      "the next step is its mirror image.", "5a",
      [(0.00, 4, (-19, 3, -5), (14, 14, 22), ("r", "heel", 0.0)),
       (0.13, 4, (-13, 12, 0), (2, 45, 40), ("r", "heel", 0.0)),
       (0.27, 4, (-1, 5, 0), (-20, 55, 15), ("r", "heel", 0.0)),
       (0.41, 4, (11, 3, 10), (-26, 12, -3), ("r", "toe", 0.22))],
      0.55, H7)
