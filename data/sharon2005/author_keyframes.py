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
        g = math.tan(math.radians(slope))
        def above(p):
            return p[1] - p[0] * g
        print(f"  {name} key {i} t={t}: root ({root[0]:.3f}, {root[1]:.3f})  heights above ground: "
              f"r heel {above(out['r'][0]):.3f} toe {above(out['r'][1]):.3f}  "
              f"l heel {above(out['l'][0]):.3f} toe {above(out['l'][1]):.3f}")
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
H16 = (0.430181, 0.448623, 0.262979)  # sharon2005_human16() defaults (de Leva reference male)

# Figure 5a: a normal walk. Right heel strike -> loading -> mid-stance -> heel off; the left leg
# pushes off, swings through with the knee bent and reaches forward. One step = 0.55 s.
build("normal_walk.keyframes.json", "sharon2005_human7",
      "Normal walk of the 7-link human (Sharon & van de Panne 2005, Figure 5a), one step listed; "
      "the next step is its mirror image.", "5a",
      [(0.00, 4, (-19, 3, -5), (14, 14, 22), ("r", "heel", 0.0)),
       (0.13, 4, (-13, 12, 0), (0, 55, 45), ("r", "heel", 0.0)),
       (0.27, 4, (-1, 5, 0), (-24, 70, 18), ("r", "heel", 0.0)),
       (0.41, 4, (11, 3, 10), (-27, 15, -3), ("r", "toe", 0.22))],
      0.55, H7)

# Figure 6a: prolonged double stance and an exaggerated knee lift in the fourth keyframe. The left
# toe stays on the ground through keyframe 1 (double stance), then the knee rises to hip height.
build("high_knee.keyframes.json", "sharon2005_human7",
      "Stylized walk of the 7-link human with a prolonged double stance and a high knee lift "
      "(Sharon & van de Panne 2005, Figure 6a), one step listed; the next step is its mirror image.",
      "6a",
      [(0.00, 4, (-19, 3, -5), (14, 14, 22), ("r", "heel", 0.0)),
       (0.20, 4, (-8, 6, 0), (22, 22, 45), ("r", "heel", 0.0)),
       (0.32, 4, (-2, 5, 0), (-15, 75, 40), ("r", "heel", 0.0)),
       (0.47, 4, (4, 4, 0), (-70, 100, 20), ("r", "heel", 0.0)),
       (0.60, 4, (11, 3, 10), (-28, 12, -3), ("r", "toe", 0.22))],
      0.72, H7)

# Figure 6c: an extra backward swing of the swing leg in the third keyframe: forward, back,
# forward again before foot strike.
build("backswing.keyframes.json", "sharon2005_human7",
      "Stylized walk of the 7-link human with an extra backward swing of the swing leg "
      "(Sharon & van de Panne 2005, Figure 6c), one step listed; the next step is its mirror image.",
      "6c",
      [(0.00, 4, (-19, 3, -5), (14, 14, 22), ("r", "heel", 0.0)),
       (0.17, 4, (-11, 10, 0), (-28, 55, 15), ("r", "heel", 0.0)),
       (0.35, 4, (-2, 5, 0), (6, 62, 42), ("r", "heel", 0.0)),
       (0.55, 4, (11, 3, 10), (-27, 12, -3), ("r", "toe", 0.22))],
      0.70, H7)

# Figure 7a: walking up a 10 degree slope: the trunk leans forward, hips flex more, the feet land
# parallel to the slope (world pitch -10 degrees: toe up).
build("uphill.keyframes.json", "sharon2005_human7",
      "Walk of the 7-link human up a 10 degree slope (Sharon & van de Panne 2005, Figure 7a), one "
      "step listed; the next step is its mirror image, one stride higher.", "7a",
      [(0.00, 10, (-38, 12, -14), (0, 12, 15), ("r", "heel", 0.0)),
       (0.15, 10, (-32, 25, -10), (-12, 60, 30), ("r", "heel", 0.0)),
       (0.30, 10, (-20, 18, -10), (-45, 75, 0), ("r", "heel", 0.0)),
       (0.45, 10, (-6, 8, -4), (-55, 35, -15), ("r", "toe", 0.22))],
      0.60, H7, slope=10.0)

# Figure 5c: the 16-link human walking with the normal walk's legs, arms swinging against the legs
# and a slightly flexed trunk. Only the legs are optimized; the upper body follows the nodes.
ARMS = [  # per keyframe: upper-body DOFs (degrees)
    {"back": 2, "chest": 0, "neck": 0, "rshoulder": 20, "relbow": -15, "rwrist": 0,
     "lshoulder": -20, "lelbow": -25, "lwrist": 0},
    {"back": 2, "chest": 0, "neck": 0, "rshoulder": 12, "relbow": -15, "rwrist": 0,
     "lshoulder": -12, "lelbow": -22, "lwrist": 0},
    {"back": 2, "chest": 0, "neck": 0, "rshoulder": 0, "relbow": -18, "rwrist": 0,
     "lshoulder": 0, "lelbow": -18, "lwrist": 0},
    {"back": 2, "chest": 0, "neck": 0, "rshoulder": -15, "relbow": -24, "rwrist": 0,
     "lshoulder": 15, "lelbow": -15, "lwrist": 0},
]
build("human16_walk.keyframes.json", "sharon2005_human16",
      "Walk of the 16-link human (Sharon & van de Panne 2005, Figure 5c), one step listed; the "
      "next step is its mirror image.", "5c",
      [(0.00, 2, (-19, 3, -5), (14, 20, 26), ("r", "heel", 0.0)),
       (0.13, 2, (-13, 12, 0), (0, 55, 45), ("r", "heel", 0.0)),
       (0.27, 2, (-1, 5, 0), (-24, 70, 18), ("r", "heel", 0.0)),
       (0.41, 2, (11, 3, 10), (-27, 15, -3), ("r", "toe", 0.262979))],
      0.55, H16, upper=ARMS)
