#!/usr/bin/env python3
"""Generate graphs/skeletons/mannequin.ron: a ~180 cm humanoid with UE4-mannequin bone names.

Run from anywhere:  python3 scripts/gen_mannequin.py
The output is deterministic; re-running regenerates the file byte-for-byte.

Rig space: +Z up, +Y forward, +X is the character's LEFT (right-handed), centimetres.
A transform maps p -> t + r*(s*p); global(bone) = global(parent) * local(bone).
Quaternions are (x, y, z, w). Python 3.11, standard library only.

How the data is built
---------------------
Each bone gets a GLOBAL rest position and a GLOBAL rotation. Rotations are built as 3x3
frames whose columns are where the bone's local X, Y and Z axes point in rig space:

* root, pelvis, spine_01..03, neck_01, head: identity (axes = rig axes; +Z up the spine).
* Left limb bones (thigh/calf/foot, clavicle/upperarm/lowerarm/hand):
    local -X points from the bone to its child (foot_l -> ball_l; hand_l continues the
    forearm direction), local +Y points to the limb's bend side, Z = X x Y.
* Right limb bones: mirrored -- local +X points to the child and local +Y points the
    opposite way of the left side's +Y (so local -Y points to the bend side).
* ball_l / ball_r: the same global rotation as their foot (identity local rotation).

Bend side ("secondary" / pole axis), found by Gram-Schmidt of a reference direction
against the bone's X axis:
* legs: rig +Y (forward) -- the knee sits in front of the hip-ankle line. foot_l uses rig
  +Z (up) as reference, which gives a frame that is the calf's frame rotated about the
  knee-hinge axis, i.e. local +Y points up/forward.
* arms: rig -Y (backward) -- the elbow sits behind the shoulder-wrist line (the forearm
  is bent slightly forward), so local +Y of the left arm bones points backwards.
So two-bone IK axes are: left primary (-1,0,0), secondary (0,1,0); right primary (1,0,0),
secondary (0,-1,0), for both legs and arms.

Locals: local.r = parent.r^-1 * r, local.t = parent.r^-1 * (t - parent.t) (all scales 1).
Before writing, the script checks (asserts) that the rounded, written locals recompose to
the intended globals and that the axis rules hold.
"""

from __future__ import annotations

import math
import os

# ---------------------------------------------------------------------------------------
# Small vector / matrix / quaternion helpers (no numpy).
# ---------------------------------------------------------------------------------------


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    )


def length(a):
    return math.sqrt(dot(a, a))


def normalize(a):
    n = length(a)
    assert n > 1e-9, f"cannot normalise {a}"
    return scale(a, 1.0 / n)


def mirror(p):
    """Mirror a rig-space point/vector across the sagittal (YZ) plane."""
    return (-p[0], p[1], p[2])


def frame(x_axis, y_ref):
    """Right-handed orthonormal frame: columns (X, Y, Z) as a row-major 3x3 matrix.

    X is given; Y is y_ref made orthogonal to X; Z = X x Y.
    """
    x = normalize(x_axis)
    y = normalize(sub(y_ref, scale(x, dot(y_ref, x))))
    z = cross(x, y)
    return (
        (x[0], y[0], z[0]),
        (x[1], y[1], z[1]),
        (x[2], y[2], z[2]),
    )


def det3(m):
    return (
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    )


def quat_canonical(q):
    x, y, z, w = q
    n = math.sqrt(x * x + y * y + z * z + w * w)
    x, y, z, w = x / n, y / n, z / n, w / n
    if w < 0.0:
        x, y, z, w = -x, -y, -z, -w
    return (x, y, z, w)


def mat_to_quat(m):
    """Rotation matrix (row-major) -> unit quaternion (x, y, z, w), w >= 0."""
    tr = m[0][0] + m[1][1] + m[2][2]
    if tr > 0.0:
        s = math.sqrt(tr + 1.0) * 2.0
        w = 0.25 * s
        x = (m[2][1] - m[1][2]) / s
        y = (m[0][2] - m[2][0]) / s
        z = (m[1][0] - m[0][1]) / s
    elif m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2.0
        w = (m[2][1] - m[1][2]) / s
        x = 0.25 * s
        y = (m[0][1] + m[1][0]) / s
        z = (m[0][2] + m[2][0]) / s
    elif m[1][1] > m[2][2]:
        s = math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2.0
        w = (m[0][2] - m[2][0]) / s
        x = (m[0][1] + m[1][0]) / s
        y = 0.25 * s
        z = (m[1][2] + m[2][1]) / s
    else:
        s = math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2.0
        w = (m[1][0] - m[0][1]) / s
        x = (m[0][2] + m[2][0]) / s
        y = (m[1][2] + m[2][1]) / s
        z = 0.25 * s
    return quat_canonical((x, y, z, w))


def quat_mul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    )


def quat_conj(q):
    return (-q[0], -q[1], -q[2], q[3])


def quat_rotate(q, v):
    """Rotate vector v by quaternion q (q need not be exactly unit: uses q v q*/|q|^2)."""
    n2 = q[0] ** 2 + q[1] ** 2 + q[2] ** 2 + q[3] ** 2
    p = quat_mul(quat_mul(q, (v[0], v[1], v[2], 0.0)), quat_conj(q))
    return (p[0] / n2, p[1] / n2, p[2] / n2)


IDENTITY_Q = (0.0, 0.0, 0.0, 1.0)

# ---------------------------------------------------------------------------------------
# Rest pose: GLOBAL positions (cm). Left side is +X; the right side is mirrored.
# ---------------------------------------------------------------------------------------

GROUND_Z = 0.0
ANKLE_Z = 13.5          # foot bone (ankle) height above the sole
BALL_AHEAD = 14.0       # ball joint ahead of the ankle (+Y)
BALL_Z = 3.0            # ball joint height above the sole
SKULL_ABOVE_HEAD = 15.0  # top of the skull above the head bone
HEEL_BEHIND = 3.0       # heel contact point behind the ankle (-Y)

# Axial chain (identity rotations).
P_ROOT = (0.0, 0.0, 0.0)
P_PELVIS = (0.0, 0.0, 95.0)
P_SPINE_01 = (0.0, 0.0, 107.0)
P_SPINE_02 = (0.0, 0.0, 119.0)
P_SPINE_03 = (0.0, 0.0, 132.0)
P_NECK_01 = (0.0, 0.0, 152.0)
P_HEAD = (0.0, 0.0, 165.0)

# Left leg: hip 9.5 cm left of the pelvis centre, 3 cm below it; the leg hangs straight
# down in the X = 9.5 plane with the knee 1.5 cm in front of the hip-ankle line.
P_THIGH_L = (9.5, 0.0, 92.0)
P_CALF_L = (9.5, 1.5, 50.0)
P_FOOT_L = (9.5, 0.0, ANKLE_Z)
P_BALL_L = (9.5, BALL_AHEAD, BALL_Z)

# Left arm: relaxed A-pose. The upper arm points 45 deg down from horizontal in the XZ
# plane; the forearm is bent 15 deg forward (towards +Y), so the elbow sits behind the
# shoulder-wrist line (the elbow "points" backwards, rig -Y).
P_CLAVICLE_L = (3.0, 2.0, 146.0)
P_UPPERARM_L = (17.5, 0.0, 145.0)
UPPERARM_LEN = 29.0
LOWERARM_LEN = 25.0
ELBOW_BEND_DEG = 15.0
_d_upper = normalize((1.0, 0.0, -1.0))
_bend = math.radians(ELBOW_BEND_DEG)
_d_lower = add(scale(_d_upper, math.cos(_bend)), scale((0.0, 1.0, 0.0), math.sin(_bend)))
P_LOWERARM_L = add(P_UPPERARM_L, scale(_d_upper, UPPERARM_LEN))
P_HAND_L = add(P_LOWERARM_L, scale(_d_lower, LOWERARM_LEN))

FORWARD = (0.0, 1.0, 0.0)
BACKWARD = (0.0, -1.0, 0.0)
UP = (0.0, 0.0, 1.0)

# ---------------------------------------------------------------------------------------
# Bone table: name, parent, global position, global rotation matrix.
# ---------------------------------------------------------------------------------------

IDENTITY_M = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


def left_frame(pos, toward, y_ref):
    """Left limb: local -X from pos towards `toward`, local +Y towards y_ref."""
    return frame(scale(sub(toward, pos), -1.0), y_ref)


def right_frame(pos, toward, y_ref_left):
    """Right limb: local +X from pos towards `toward`, local +Y opposite the left's +Y.

    y_ref_left is the reference the left side uses (a Y/Z direction, unchanged by the
    X-mirror); the right side's +Y is its negation.
    """
    return frame(sub(toward, pos), scale(y_ref_left, -1.0))


def build_bones():
    bones = []  # (name, parent, pos, matrix), depth-first pre-order, left before right

    def bone(name, parent, pos, m):
        bones.append((name, parent, pos, m))

    bone("root", None, P_ROOT, IDENTITY_M)
    bone("pelvis", "root", P_PELVIS, IDENTITY_M)

    for side in ("l", "r"):
        mir = (lambda p: p) if side == "l" else mirror
        fr = left_frame if side == "l" else right_frame
        thigh, calf, foot, ball = (mir(P_THIGH_L), mir(P_CALF_L), mir(P_FOOT_L), mir(P_BALL_L))
        foot_m = fr(foot, ball, UP)
        bone(f"thigh_{side}", "pelvis", thigh, fr(thigh, calf, FORWARD))
        bone(f"calf_{side}", f"thigh_{side}", calf, fr(calf, foot, FORWARD))
        bone(f"foot_{side}", f"calf_{side}", foot, foot_m)
        bone(f"ball_{side}", f"foot_{side}", ball, foot_m)

    bone("spine_01", "pelvis", P_SPINE_01, IDENTITY_M)
    bone("spine_02", "spine_01", P_SPINE_02, IDENTITY_M)
    bone("spine_03", "spine_02", P_SPINE_03, IDENTITY_M)

    for side in ("l", "r"):
        mir = (lambda p: p) if side == "l" else mirror
        fr = left_frame if side == "l" else right_frame
        clav, upper, lower, hand = (
            mir(P_CLAVICLE_L), mir(P_UPPERARM_L), mir(P_LOWERARM_L), mir(P_HAND_L))
        lower_m = fr(lower, hand, BACKWARD)
        bone(f"clavicle_{side}", "spine_03", clav, fr(clav, upper, BACKWARD))
        bone(f"upperarm_{side}", f"clavicle_{side}", upper, fr(upper, lower, BACKWARD))
        bone(f"lowerarm_{side}", f"upperarm_{side}", lower, lower_m)
        # The hand continues the forearm direction: same global rotation as lowerarm.
        bone(f"hand_{side}", f"lowerarm_{side}", hand, lower_m)

    bone("neck_01", "spine_03", P_NECK_01, IDENTITY_M)
    bone("head", "neck_01", P_HEAD, IDENTITY_M)
    return bones


# ---------------------------------------------------------------------------------------
# Rounding / formatting.
# ---------------------------------------------------------------------------------------

T_DECIMALS = 4  # translations: 0.1 micrometre is plenty
Q_DECIMALS = 7  # quaternion components: ~7 significant digits


def rnd(v, d):
    r = round(v, d)
    return 0.0 if r == 0.0 else r  # no "-0.0"


def fmt_num(v):
    s = repr(float(v))
    assert "e" not in s and "E" not in s, s
    return s


def fmt_vec(v):
    return "(" + ", ".join(fmt_num(c) for c in v) + ")"


# ---------------------------------------------------------------------------------------
# Main.
# ---------------------------------------------------------------------------------------

LEFT_LIMB = {"thigh_l", "calf_l", "foot_l", "ball_l", "clavicle_l", "upperarm_l",
             "lowerarm_l", "hand_l"}
RIGHT_LIMB = {n[:-1] + "r" for n in LEFT_LIMB}


def main():
    bones = build_bones()
    names = [b[0] for b in bones]
    assert len(set(names)) == len(names)
    index = {n: i for i, n in enumerate(names)}

    glob_q = {}
    glob_t = {}
    for name, parent, pos, m in bones:
        if parent is not None:
            assert index[parent] < index[name], f"{parent} must precede {name}"
        d = det3(m)
        assert abs(d - 1.0) < 1e-9, f"{name}: frame not right-handed (det {d})"
        for i in range(3):
            for j in range(3):
                e = sum(m[k][i] * m[k][j] for k in range(3))
                assert abs(e - (1.0 if i == j else 0.0)) < 1e-9, f"{name}: not orthonormal"
        q = mat_to_quat(m)
        # quaternion must reproduce the matrix columns
        for c in range(3):
            axis = tuple(1.0 if k == c else 0.0 for k in range(3))
            col = (m[0][c], m[1][c], m[2][c])
            assert length(sub(quat_rotate(q, axis), col)) < 1e-9, f"{name}: quat mismatch"
        glob_q[name] = q
        glob_t[name] = pos

    # Locals (exact), then rounded as written.
    locals_written = []  # (name, parent, t_rounded, q_rounded)
    for name, parent, pos, _m in bones:
        if parent is None:
            lt, lq = pos, glob_q[name]
        else:
            pinv = quat_conj(glob_q[parent])
            lq = quat_canonical(quat_mul(pinv, glob_q[name]))
            lt = quat_rotate(pinv, sub(pos, glob_t[parent]))
        t_r = tuple(rnd(c, T_DECIMALS) for c in lt)
        q_r = tuple(rnd(c, Q_DECIMALS) for c in lq)
        n = math.sqrt(sum(c * c for c in q_r))
        assert abs(n - 1.0) < 1e-6, f"{name}: |q| = {n!r}"
        locals_written.append((name, parent, t_r, q_r))

    # Self-check 1: recompose globals from the rounded locals.
    rq = {}
    rt = {}
    for name, parent, t_r, q_r in locals_written:
        if parent is None:
            rq[name], rt[name] = q_r, t_r
        else:
            rq[name] = quat_mul(rq[parent], q_r)
            rt[name] = add(rt[parent], quat_rotate(rq[parent], t_r))
        err = length(sub(rt[name], glob_t[name]))
        assert err < 1e-3, f"{name}: recomposed position off by {err} cm"
        # rotation too: compare axes
        for axis in ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)):
            e = length(sub(quat_rotate(rq[name], axis), quat_rotate(glob_q[name], axis)))
            assert e < 1e-5, f"{name}: recomposed rotation off by {e}"

    # Self-check 2: limb axes point at the child.
    children = {}
    for name, parent, _p, _m in bones:
        if parent is not None:
            children.setdefault(parent, []).append(name)
    for name in LEFT_LIMB | RIGHT_LIMB:
        kids = children.get(name, [])
        assert len(kids) <= 1, name
        sign = -1.0 if name in LEFT_LIMB else 1.0
        x_axis = quat_rotate(rq[name], (sign, 0.0, 0.0))
        if kids:
            d = normalize(sub(rt[kids[0]], rt[name]))
            assert dot(x_axis, d) > 0.999, f"{name}: primary axis not towards {kids[0]}"
        if name.startswith("hand_"):
            fore = normalize(sub(rt[name], rt["lowerarm_" + name[-1]]))
            assert dot(x_axis, fore) > 0.999, f"{name}: does not continue the forearm"
        if name.startswith("ball_"):
            foot = "foot_" + name[-1]
            for axis in ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)):
                e = length(sub(quat_rotate(rq[name], axis), quat_rotate(rq[foot], axis)))
                assert e < 1e-6, f"{name}: rotation differs from {foot}"

    # Self-check 3: bend directions (secondary axis).
    def check_pole(bone_name, sign, off):
        """The mid joint's offset from the root-end line lies in the bone's local XY plane
        (Z is the hinge axis) on the secondary-axis side."""
        y = quat_rotate(rq[bone_name], (0.0, sign, 0.0))
        zax = quat_rotate(rq[bone_name], (0.0, 0.0, 1.0))
        o = normalize(off)
        assert abs(dot(zax, o)) < 1e-3, f"{bone_name}: mid joint off the bend plane"
        assert dot(y, o) > 0.9, f"{bone_name}: secondary axis not towards the mid joint"

    for side, sign in (("l", 1.0), ("r", -1.0)):
        for b in ("thigh", "calf"):
            y = quat_rotate(rq[f"{b}_{side}"], (0.0, sign, 0.0))
            assert y[1] > 0.0, f"{b}_{side}: knee bend axis does not point forward"
        # The knee is in front of the hip-ankle line, the elbow behind the shoulder-wrist line.
        thigh, calf, foot = rt[f"thigh_{side}"], rt[f"calf_{side}"], rt[f"foot_{side}"]
        line = normalize(sub(foot, thigh))
        off = sub(sub(calf, thigh), scale(line, dot(sub(calf, thigh), line)))
        assert 1.0 <= off[1] <= 2.0, f"knee {side} offset {off}"
        check_pole(f"thigh_{side}", sign, off)
        up, lo, ha = rt[f"upperarm_{side}"], rt[f"lowerarm_{side}"], rt[f"hand_{side}"]
        line = normalize(sub(ha, up))
        off = sub(sub(lo, up), scale(line, dot(sub(lo, up), line)))
        assert off[1] < 0.0, f"elbow {side} not behind the shoulder-wrist line"
        check_pole(f"upperarm_{side}", sign, off)
        for b in ("upperarm", "lowerarm"):
            y = quat_rotate(rq[f"{b}_{side}"], (0.0, sign, 0.0))
            assert y[1] < 0.0, f"{b}_{side}: elbow bend axis does not point backward"

    # Self-check 4: proportions.
    for side in ("l", "r"):
        ankle, ball = rt[f"foot_{side}"], rt[f"ball_{side}"]
        assert abs(ankle[2] - ANKLE_Z) < 1e-3, f"ankle {side} z = {ankle[2]}"
        assert abs((ball[1] - ankle[1]) - BALL_AHEAD) < 1e-3, f"ball {side} not 14 cm ahead"
        assert abs(ball[2] - BALL_Z) < 1e-3, f"ball {side} z = {ball[2]}"
    assert 178.0 <= rt["head"][2] + SKULL_ABOVE_HEAD <= 182.0
    assert abs(rt["pelvis"][2] - 95.0) < 1e-3
    assert rt["root"] == (0.0, 0.0, 0.0) and locals_written[0][3] == IDENTITY_Q
    for name in ("root", "pelvis", "spine_01", "spine_02", "spine_03", "neck_01", "head"):
        assert rq[name] == IDENTITY_Q or all(
            abs(a - b) < 1e-9 for a, b in zip(rq[name], IDENTITY_Q)), name

    # Contacts: heel under (slightly behind) the ankle, ball under the ball joint, on the
    # sole (z = 0), expressed in the foot bone's local frame.
    contacts = []
    for side in ("l", "r"):
        foot = f"foot_{side}"
        ankle = glob_t[foot]
        ball = glob_t[f"ball_{side}"]
        for cname, target in ((f"heel_{side}", (ankle[0], ankle[1] - HEEL_BEHIND, GROUND_Z)),
                              (f"ball_{side}", (ball[0], ball[1], GROUND_Z))):
            off = quat_rotate(quat_conj(glob_q[foot]), sub(target, ankle))
            off_r = tuple(rnd(c, T_DECIMALS) for c in off)
            back = add(rt[foot], quat_rotate(rq[foot], off_r))
            assert length(sub(back, target)) < 1e-3, f"contact {cname}: {back} vs {target}"
            assert abs(back[2] - GROUND_Z) < 1e-3
            contacts.append((cname, foot, off_r))

    # Write.
    lines = [
        "// graphs/skeletons/mannequin.ron — generated by scripts/gen_mannequin.py; "
        "edit the script, not this file.",
        "// Humanoid rest skeleton with UE4-mannequin bone names, ~180 cm tall (head bone at",
        f"// z = {fmt_num(P_HEAD[2])}, top of the skull ~{fmt_num(SKULL_ABOVE_HEAD)} cm above it), "
        "pelvis at z = 95, ankles 13.5 cm above the sole (z = 0).",
        "// Neutral pose facing +Y: legs straight down, knees 1.5 cm forward; arms in a relaxed "
        "A-pose 45 deg down, elbows bent 15 deg.",
        "// Rig space: +Z up, +Y forward, +X = character's left; cm; quaternions (x, y, z, w); "
        "translation/rotation are LOCAL.",
        "// root/pelvis/spine_*/neck_01/head: identity global rotation (axes = rig axes).",
        "// Left limbs: local -X points to the child bone, local +Y to the bend side "
        "(legs: forward, knee; arms: backward, elbow).",
        "// Right limbs (mirrored): local +X points to the child, local -Y to the bend side. "
        "ball_*: same global rotation as foot_*.",
        "// Two-bone IK axes: left primary (-1,0,0) secondary (0,1,0); right primary (1,0,0) "
        "secondary (0,-1,0).",
        "Skeleton(",
        "    version: 1,",
        '    name: "mannequin",',
        "    bones: [",
    ]
    for name, parent, t_r, q_r in locals_written:
        fields = [f'name: "{name}"', "parent: None" if parent is None else f'parent: "{parent}"']
        if any(c != 0.0 for c in t_r):
            fields.append(f"translation: {fmt_vec(t_r)}")
        if q_r != IDENTITY_Q:
            fields.append(f"rotation: {fmt_vec(q_r)}")
        lines.append("        (" + ", ".join(fields) + "),")
    lines += [
        "    ],",
        "    // Sole contact points for ground-contact metrics: heel under the ankle "
        f"({fmt_num(HEEL_BEHIND)} cm behind), ball under the ball joint.",
        "    // Offsets are in the foot bone's LOCAL frame, cm; in the rest pose they lie on "
        "the sole (z = 0).",
        "    contacts: [",
    ]
    for cname, bone_name, off_r in contacts:
        lines.append(f'        (name: "{cname}", bone: "{bone_name}", offset: {fmt_vec(off_r)}),')
    lines += ["    ],", ")"]
    text = "\n".join(lines) + "\n"

    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = os.path.join(repo, "graphs", "skeletons", "mannequin.ron")
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w", encoding="utf-8", newline="\n") as f:
        f.write(text)

    def z(n):
        return rt[n][2]

    print(f"wrote {os.path.relpath(out, repo)}: {len(locals_written)} bones, "
          f"{len(contacts)} contacts")
    print(f"  head bone z = {z('head'):.2f} cm, top of skull ~{z('head') + SKULL_ABOVE_HEAD:.2f} cm")
    print(f"  neck_01 {z('neck_01'):.2f}, spine_03 {z('spine_03'):.2f}, "
          f"spine_02 {z('spine_02'):.2f}, spine_01 {z('spine_01'):.2f}, pelvis {z('pelvis'):.2f}")
    print(f"  shoulder (upperarm_l) z = {z('upperarm_l'):.2f}, elbow {z('lowerarm_l'):.2f}, "
          f"wrist {z('hand_l'):.2f} (x = {rt['hand_l'][0]:.2f}, y = {rt['hand_l'][1]:.2f})")
    print(f"  hip (thigh_l) z = {z('thigh_l'):.2f}, knee {z('calf_l'):.2f} "
          f"(y = {rt['calf_l'][1]:.2f}), ankle {z('foot_l'):.2f}, ball {z('ball_l'):.2f} "
          f"(y = {rt['ball_l'][1]:.2f})")
    print(f"  thigh {length(sub(rt['calf_l'], rt['thigh_l'])):.2f} cm, "
          f"shin {length(sub(rt['foot_l'], rt['calf_l'])):.2f} cm, "
          f"upper arm {UPPERARM_LEN:.2f} cm, forearm {LOWERARM_LEN:.2f} cm")
    print("  arm axes: left -X to child, +Y backward (elbow side); right +X to child, -Y backward")
    print("  all self-checks passed")


if __name__ == "__main__":
    main()
