#!/usr/bin/env python3
"""Verify the bundles under tests/in/ that make_fixtures.py writes, independently of it.

Re-reads every XML with xml.etree (sharing no code with the generator) and checks:
- bundle shape: one PhysicalModelingXMLFile XML (two in broken_two_xml), every named STL found
  exactly once by exact / case-insensitive / any-sub-folder lookup, no stray STL, 12 triangles;
- lexical and frame rules: "3x3 Transform", orientations orthonormal with determinant +1 to
  1e-12, refs unique across the file and all resolvable; frame references (positionOrigin,
  positionReferenceFrame, orientationReferenceFrame) WORLD, a frame of the same body or
  ADJOINING, resolved here to world poses (origin(X) + R(Y) p, R(Z) R); primitive axes in WORLD,
  BASE or FOLLOWER axes;
- joints: name "<base body>--<follower body>", unique nodeIDs, and the follower frame equal to
  the base frame moved by the primitives at the initial values expect.json declares (product of
  exponentials about world axes through the base origin), to 1e-12 m and 1e-12;
- bodies: inertia symmetric, positive definite, triangle inequality; density of aluminium or
  steel; the mesh box has the body's volume and contains its CG;
- expect.json: counts, loops, every frame pose, CGs, masses (and lumped properties) agree;
- broken cases: exactly the intended flaw is present, the rest is valid;
- determinism: a fresh run of make_fixtures.py into a temporary directory is byte-identical.

    python3 tests/tools/check_fixtures.py [IN_DIR]     (exit status 0 when everything holds)
"""

import json
import math
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path
import struct

LENGTH = {"mm": 1e-3, "cm": 1e-2, "m": 1.0, "in": 0.0254, "ft": 0.3048}
MASS = {"kg": 1.0, "g": 1e-3, "lbm": 0.45359237, "slug": 14.5939029}
INERTIA = {"kg*m^2": 1.0, "lbm*in^2": 0.45359237 * 0.0254 ** 2, "slug*in^2": 14.5939029 * 0.0254 ** 2}
VOLUME = {"mm^3": 1e-9, "m^3": 1.0, "in^3": 0.0254 ** 3}
AREA = {"mm^2": 1e-6, "m^2": 1.0, "in^2": 0.0254 ** 2}
DENSITIES = (2700.0, 7850.0)
TOL = 1e-12

ERROR_CASES = {
    "broken_dangling_ref": "dangling_ref",
    "broken_unknown_unit": "unknown_unit",
    "broken_truncated": "truncated",
    "broken_unsupported_ref": "unsupported_ref",
    "broken_nan": "nan",
    "broken_two_xml": "two_xml",
    "broken_ambiguous_mesh": "ambiguous",
    "broken_frame_cycle": "frame_cycle",
    "broken_frame_missing": "frame_missing",
    "broken_mass_overflow": "overflow",
    "broken_far_frame": "far",
    "broken_nan_stl": "nan_stl",
}
# Farthest a frame of a real machine lies from the origin, m.
FAR_M = 1e5
ALL_CASES = ["pendulum", "fourbar", "arm_subsystems", "inch_lbm", "rotated_frames", "composite_joint",
             "lump_welds", "warnings", "frames_relative", "slider_crank", "sixbar_6digit",
             "crank_rocker_noise", "spatial_rssr", "immobile_leg"] + list(ERROR_CASES)
# Written by make_vrml_fixtures.py, checked elsewhere.
OTHER_GENERATOR = ("vrml_", "broken_vrml_", "urdf_", "broken_urdf_", "xml2_", "broken_xml2_")
I3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]

failures = []

# Exports print rotation matrices and axes with 6 significant digits; numbers printed that way are
# exact only to about 1e-6 (orthonormality, unit length, where a joint puts its follower).
PRINTED_TOL = 1e-5


def significant_digits(token):
    mant = token.strip().lstrip("+-").lower().split("e")[0].replace(".", "").lstrip("0")
    return len(mant.rstrip("0")) if mant else 1


def tol_of(text_):
    """TOL for exact numbers, PRINTED_TOL when every number has at most 6 significant digits."""
    return PRINTED_TOL if all(significant_digits(t) <= 6 for t in text_.split(",")) else TOL


class Flaw(Exception):
    """A deliberate flaw found while resolving frame references: args[0] is the flaw tuple."""


def fail(case, msg):
    failures.append("%s: %s" % (case, msg))


# --------------------------------------------------------------------------------------------
# Small linear algebra (row-major 3x3 lists).


def mm(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def mv(A, v):
    return [sum(A[i][k] * v[k] for k in range(3)) for i in range(3)]


def tr(A):
    return [[A[j][i] for j in range(3)] for i in range(3)]


def det(A):
    return (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1])
            - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
            + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]))


def maxdiff(A, B):
    return max(abs(A[i][j] - B[i][j]) for i in range(3) for j in range(3))


def vdiff(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def axis_angle(axis, angle):
    n = math.sqrt(sum(x * x for x in axis))
    if angle == 0.0:
        return [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]]
    x, y, z = (v / n for v in axis)
    c, s = math.cos(angle), math.sin(angle)
    C = 1 - c
    return [[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
            [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
            [z * x * C - y * s, z * y * C + x * s, c + z * z * C]]


def sym_eigenvalues(A):
    """Eigenvalues of a symmetric 3x3 matrix, ascending (trigonometric method)."""
    p1 = A[0][1] ** 2 + A[0][2] ** 2 + A[1][2] ** 2
    q = (A[0][0] + A[1][1] + A[2][2]) / 3
    if p1 == 0:
        return sorted([A[0][0], A[1][1], A[2][2]])
    p2 = (A[0][0] - q) ** 2 + (A[1][1] - q) ** 2 + (A[2][2] - q) ** 2 + 2 * p1
    p = math.sqrt(p2 / 6)
    B = [[(A[i][j] - (q if i == j else 0)) / p for j in range(3)] for i in range(3)]
    r = max(-1.0, min(1.0, det(B) / 2))
    phi = math.acos(r) / 3
    e1 = q + 2 * p * math.cos(phi)
    e3 = q + 2 * p * math.cos(phi + 2 * math.pi / 3)
    return sorted([e1, 3 * q - e1 - e3, e3])


# --------------------------------------------------------------------------------------------
# Reading an export.


def text(el, tag):
    c = el.find(tag)
    if c is None or c.text is None:
        return None
    return c.text.strip()


def string(el, tag):
    t = text(el, tag)
    if t is None:
        return None
    assert t.startswith('"') and t.endswith('"'), "%s not quoted: %r" % (tag, t)
    return t[1:-1]


def numbers(t):
    assert " " not in t, "spaces in a number list: %r" % t
    return [float(x) for x in t.split(",")]


class Export:
    def __init__(self, path, tolerate=()):
        self.path = path
        self.tree = ET.parse(path)
        root = self.tree.getroot()
        assert root.tag == "PhysicalModelingXMLFile", root.tag
        assert string(root, "formatVersion") == "1.0.4"
        tops = [c for c in root if c.tag in ("SimMechanics", "SimscapeMultibody")]
        assert len(tops) == 1
        self.top = tops[0]
        self.created_using = string(root, "createdUsing")
        self.tolerate = set(tolerate)
        self.bodies = []  # dicts
        self.frames = []  # dicts
        self.grounds = []
        self.joints = []
        self.by_ref = {}
        self.flaws = []
        self._walk(self.top, [])
        self._resolve()

    def _resolve(self):
        """World poses of all frames, then world primitive axes; flaws for bad references."""
        partners = {}
        for j in self.joints:
            for a, b in ((j["base_ref"], j["follower_ref"]), (j["follower_ref"], j["base_ref"])):
                partners.setdefault(a, []).append(b)

        def target(f, value):
            if value == "WORLD":
                return None
            if value == "ADJOINING":
                others = partners.get(f["ref"], [])
                if len(others) != 1 or others[0] not in self.by_ref:
                    raise Flaw(("adjoining", f["node_id"], len(others)))
                return self.by_ref[others[0]]
            if "CG" in f["owner"]:  # a body: its frames by name
                for g in f["owner"]["frames"]:
                    if g["name"] == value:
                        return g
                if re.fullmatch(r"CG|CS[0-9]+", value):
                    raise Flaw(("frame_missing", value))
            raise Flaw(("unsupported_ref", value))

        def place(f, path):
            if "p" in f:
                return f
            for i, g in enumerate(path):
                if g is f:
                    raise Flaw(("frame_cycle", " -> ".join(h["name"] for h in path[i:] + [f])))
            X, Y, Z = (target(f, v) for v in f["refs"])
            origin = place(X, path + [f])["p"] if X else [0.0, 0.0, 0.0]
            RY = place(Y, path + [f])["R"] if Y else I3
            RZ = place(Z, path + [f])["R"] if Z else I3
            v = mv(RY, f["p_given"])
            f["p"] = [origin[i] + v[i] for i in range(3)]
            f["R"] = mm(RZ, f["R_given"])
            return f

        for f in self.frames:
            try:
                place(f, [])
            except Flaw as e:
                self.flaws.append(e.args[0])
                for g in self.frames:  # keep going with the poses as given
                    g.setdefault("p", g["p_given"])
                    g.setdefault("R", g["R_given"])
        for j in self.joints:
            for k, (kind, axis) in enumerate(j["prims"]):
                side = {"WORLD": None, "BASE": "base_ref", "FOLLOWER": "follower_ref"}.get(j["axis_frames"][k], "?")
                if side == "?":
                    self.flaws.append(("unsupported_ref", j["axis_frames"][k]))
                elif side is not None and j[side] in self.by_ref:
                    j["prims"][k] = (kind, mv(self.by_ref[j[side]]["R"], axis))

    def _frame(self, el, owner):
        f = {"owner": owner, "ref": el.get("ref"), "name": string(el, "name"),
             "node_id": string(el, "nodeID"), "display": string(el, "displayName")}
        f["refs"] = [string(el, tag) or "WORLD"
                     for tag in ("positionOrigin", "positionReferenceFrame", "orientationReferenceFrame")]
        assert string(el, "orientationType") == "3x3 Transform"
        assert string(el, "orientationUnits") == "rad"
        unit = string(el, "positionUnits")
        if unit not in LENGTH:
            self.flaws.append(("unknown_unit", unit))
            unit = "mm"
        p = numbers(text(el, "position"))
        if not all(math.isfinite(x) for x in p):
            self.flaws.append(("nan", text(el, "position")))
        o = numbers(text(el, "orientation"))
        assert len(p) == 3 and len(o) == 9
        f["unit"] = unit
        # As given (relative to f["refs"]); _resolve sets the world pose p, R.
        f["p_given"] = [x * LENGTH[unit] for x in p]
        if max(abs(x) for x in f["p_given"]) > FAR_M:
            self.flaws.append(("far", text(el, "position")))
            owner["flawed"] = True
        f["R_given"] = [[o[0], o[3], o[6]], [o[1], o[4], o[7]], [o[2], o[5], o[8]]]  # columns = axes
        R = f["R_given"]
        RtR = mm(tr(R), R)
        err = maxdiff(RtR, [[1, 0, 0], [0, 1, 0], [0, 0, 1]])
        f["tol"] = tol_of(text(el, "orientation"))
        assert err < f["tol"], "frame %s not orthonormal (%g)" % (f["node_id"], err)
        assert abs(det(R) - 1) < f["tol"], "frame %s has det %r" % (f["node_id"], det(R))
        if f["ref"] is not None:
            assert f["ref"] not in self.by_ref, "ref %s twice" % f["ref"]
            self.by_ref[f["ref"]] = f
        self.frames.append(f)
        return f

    def _walk(self, asm, path):
        here = path + [string(asm, "nodeID")]
        for b in asm.find("bodies"):
            body = {"name": string(b, "name"), "node_id": string(b, "nodeID"), "path": here,
                    "mass_unit": string(b, "massUnits"), "geometry": string(b, "geometryFileName")}
            body["mass"] = float(text(b, "mass")) * MASS[body["mass_unit"]]
            if not math.isfinite(body["mass"]):
                self.flaws.append(("overflow", text(b, "mass") + " " + body["mass_unit"]))
                body["flawed"] = True
            body["volume"] = float(text(b, "volume")) * VOLUME[string(b, "volumeUnits")]
            body["volume_raw"] = float(text(b, "volume"))
            body["area"] = float(text(b, "surfaceArea")) * AREA[string(b, "surfaceAreaUnits")]
            i = numbers(text(b, "inertia"))
            J = INERTIA[string(b, "inertiaUnits")]
            body["I"] = [[i[3 * r + c] * J for c in range(3)] for r in range(3)]
            body["frames"] = [self._frame(f, body) for f in b.find("frames")]
            names = [f["name"] for f in body["frames"]]
            assert names[:2] == ["CG", "CS1"], names
            assert names[2:] == ["CS%d" % k for k in range(2, len(names))], names
            body["CG"], body["CS1"] = body["frames"][0], body["frames"][1]
            self.bodies.append(body)
        for g in asm.find("grounds"):
            ground = {"name": string(g, "name"), "node_id": string(g, "nodeID")}
            fr = g.find("frame").find("Frame")
            ground["frames"] = [self._frame(fr, ground)]
            self.grounds.append(ground)
        for j in asm.find("joints"):
            prims, axis_frames, axis_tols = [], [], []
            for p in j.find("primitives"):
                assert string(p, "nodeID") == ""
                axis_frames.append(string(p, "referenceFrame"))
                axis_tols.append(tol_of(text(p, "axis")))
                prims.append((string(p, "name"), numbers(text(p, "axis"))))
            self.joints.append({
                "name": string(j, "name"), "node_id": string(j, "nodeID"),
                "base_ref": j.find("base/JointSide/connection/Frame").get("ref"),
                "follower_ref": j.find("follower/JointSide/connection/Frame").get("ref"),
                "prims": prims, "axis_frames": axis_frames, "axis_tols": axis_tols, "path": here,
            })
        for s in asm.find("subsystems"):
            self._walk(s, here)


def find_mesh(bundle, name):
    """Exact path, then case-insensitive path, then the file name anywhere (case-insensitive)."""
    files = [p.relative_to(bundle).as_posix() for p in bundle.rglob("*") if p.is_file()]
    if name in files:
        return [name]
    low = [f for f in files if f.lower() == name.lower()]
    if low:
        return low
    base = name.replace("\\", "/").split("/")[-1].lower()
    return [f for f in files if f.split("/")[-1].lower() == base]


def read_stl(data):
    if len(data) >= 84:
        n = struct.unpack("<I", data[80:84])[0]
        if len(data) == 84 + 50 * n:
            tris = []
            for k in range(n):
                v = struct.unpack("<12f", data[84 + 50 * k: 84 + 50 * k + 48])
                tris.append((v[0:3], v[3:6], v[6:9], v[9:12]))
            return "binary", tris
    t = data.decode("ascii")
    assert t.startswith("solid"), "ASCII STL without 'solid'"
    assert t.rstrip().split("\n")[-1].startswith("endsolid")
    tris, cur = [], None
    for line in t.splitlines():
        w = line.split()
        if w[:2] == ["facet", "normal"]:
            cur = [tuple(float(x) for x in w[2:5])]
        elif w and w[0] == "vertex":
            cur.append(tuple(float(x) for x in w[1:4]))
        elif w and w[0] == "endfacet":
            tris.append(tuple(cur))
    return "ascii", tris


# --------------------------------------------------------------------------------------------


def check_export(case, bundle, ex, expect, tolerate=()):
    deliberate = expect.get("deliberate", {})
    flaws = [f[0] for f in ex.flaws]
    for f in ex.flaws:
        if f[0] not in tolerate:
            fail(case, "unexpected flaw %r" % (f,))
    # Joints.
    seen = set()
    for j in ex.joints:
        if j["node_id"] in seen:
            fail(case, "joint nodeID %s twice" % j["node_id"])
        seen.add(j["node_id"])
        fb, ff = ex.by_ref.get(j["base_ref"]), ex.by_ref.get(j["follower_ref"])
        if fb is None or ff is None:
            if "dangling_ref" in tolerate:
                flaws.append("dangling_ref")
                continue
            fail(case, "joint %s: unresolved ref" % j["node_id"])
            continue
        want = "%s--%s" % (fb["owner"]["name"], ff["owner"]["name"])
        if j["name"] != want:
            fail(case, "joint %s named %s, expected %s" % (j["node_id"], j["name"], want))
        if fb["owner"] is ff["owner"]:
            fail(case, "joint %s connects a body to itself" % j["node_id"])
        kinds = [k for k, _ in j["prims"]]
        for (k, axis), axis_tol in zip(j["prims"], j["axis_tols"]):
            if k in ("weld", "spherical"):
                if axis != [0.57735, 0.57735, 0.57735]:
                    fail(case, "joint %s: %s without the dummy axis" % (j["node_id"], k))
            elif k in ("revolute", "prismatic"):
                n = math.sqrt(sum(x * x for x in axis))
                if j["node_id"] in deliberate.get("zero_axis", []):
                    if n != 0:
                        fail(case, "joint %s should have a zero axis" % j["node_id"])
                elif abs(n - 1) > axis_tol:
                    fail(case, "joint %s: axis not unit (%r)" % (j["node_id"], n))
            else:
                fail(case, "unknown primitive %s" % k)
        if "weld" in kinds and len(kinds) != 1:
            fail(case, "weld mixed with other primitives")
        # Follower predicted from the base frame and the declared initial values.
        details = {d["node_id"]: d for d in expect.get("joint_details", [])}
        d = details.get(j["node_id"])
        init = []
        for idx, (k, axis) in enumerate(j["prims"]):
            v = 0.0
            if d is not None:
                pd = d["primitives"][idx]
                assert pd["kind"] == k and vdiff(pd["axis_world"], axis) <= 1e-15, (pd, axis)
                v = pd.get("initial_rad", pd.get("initial_m", 0.0))
            init.append(v)
        p = list(fb["p"])
        R = [row[:] for row in fb["R"]]
        c = fb["p"]  # all axes pass through the base origin at assembly
        for (k, axis), v in reversed(list(zip(j["prims"], init))):
            # Apply the last primitive first: T = E1 E2 ... En T_base.
            if k == "revolute" and v:
                Q = axis_angle(axis, v)
                p = [c[i] + x for i, x in enumerate(mv(Q, [p[0] - c[0], p[1] - c[1], p[2] - c[2]]))]
                R = mm(Q, R)
            elif k == "prismatic" and v:
                p = [p[i] + v * axis[i] for i in range(3)]
        gap = vdiff(p, ff["p"])
        rerr = maxdiff(R, ff["R"])
        # Frames and axes printed with 6 digits place the follower only to their precision.
        jtol = max([fb["tol"], ff["tol"]] + j["axis_tols"])
        if j["node_id"] in deliberate.get("joints_apart", []):
            if abs(gap - 0.002) > 1e-12:
                fail(case, "joint %s should be 2 mm apart, is %r m" % (j["node_id"], gap))
        elif gap > TOL:
            fail(case, "joint %s: follower frame %.3e m from where the joint puts it" % (j["node_id"], gap))
        if rerr > jtol:
            fail(case, "joint %s: follower orientation off by %.3e" % (j["node_id"], rerr))
        if "spherical" in kinds or len([k for k in kinds if k == "revolute"]) > 1:
            # Composite rotational joints: only zero initial rotation is declared (unambiguous).
            if maxdiff(fb["R"], ff["R"]) > TOL:
                fail(case, "joint %s: composite rotational joint with a rotated follower" % j["node_id"])
    # Bodies.
    for b in ex.bodies:
        nid = b["node_id"]
        I = b["I"]
        if b["name"] == "RootPart" and b["mass"] == 0:
            if b["geometry"] != "" or any(x != 0 for r in I for x in r):
                fail(case, "RootPart %s not empty" % nid)
            if b["CS1"]["p"] != [0, 0, 0] or maxdiff(b["CS1"]["R"], [[1, 0, 0], [0, 1, 0], [0, 0, 1]]) != 0:
                fail(case, "RootPart %s CS1 not at the world origin" % nid)
            continue
        scale = max(abs(x) for r in I for x in r)
        asym = maxdiff(I, tr(I)) / scale
        S = [[0.5 * (I[i][k] + I[k][i]) for k in range(3)] for i in range(3)]
        e = sym_eigenvalues(S)
        tri_ok = e[0] + e[1] >= e[2] * (1 + 1e-9) and e[0] > 0
        if nid in deliberate.get("invalid_inertia", []):
            if asym < 1e-3 and tri_ok:
                fail(case, "body %s should have an invalid inertia" % nid)
            if asym >= 1e-3 and not tri_ok:
                fail(case, "body %s breaks two inertia rules at once" % nid)
        else:
            if asym > 1e-12:
                fail(case, "body %s inertia not symmetric" % nid)
            if not tri_ok:
                fail(case, "body %s inertia invalid: %r" % (nid, e))
        if b.get("flawed"):  # the deliberate flaw is in this body's numbers
            b["mesh_file"] = find_mesh(bundle, b["geometry"])[0]
            continue
        rho = b["mass"] / b["volume"]
        if nid in deliberate.get("implausible_density", []):
            if b["mass"] / MASS[b["mass_unit"]] != b["volume_raw"]:
                fail(case, "body %s should have mass == volume" % nid)
        elif not any(abs(rho / d - 1) < 1e-5 for d in DENSITIES):
            fail(case, "body %s density %r kg/m^3" % (nid, rho))
        # Mesh.
        geo = b["geometry"]
        if geo == "":
            continue
        found = find_mesh(bundle, geo)
        if "ambiguous" in tolerate and len(found) > 1:
            flaws.append("ambiguous")
            continue
        if nid in deliberate.get("missing_mesh", []):
            if found:
                fail(case, "body %s mesh should be missing" % nid)
            continue
        if len(found) != 1:
            fail(case, "body %s: mesh %r resolves to %r" % (nid, geo, found))
            continue
        kind, tris = read_stl((bundle / found[0]).read_bytes())
        if any(not math.isfinite(x) for t in tris for v in t for x in v):
            if "nan_stl" in tolerate:
                flaws.append("nan_stl")
                b["mesh_file"] = found[0]
                continue
            fail(case, "%s has a non-finite coordinate" % found[0])
        if len(tris) != 12:
            fail(case, "%s: %d triangles" % (found[0], len(tris)))
        lo = [min(v[i] for t in tris for v in t[1:]) for i in range(3)]
        hi = [max(v[i] for t in tris for v in t[1:]) for i in range(3)]
        for n, a, bb, cc in tris:  # winding agrees with the normal (outward box faces)
            u = [bb[i] - a[i] for i in range(3)]
            w = [cc[i] - a[i] for i in range(3)]
            cr = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
            if sum(cr[i] * n[i] for i in range(3)) <= 0:
                fail(case, "%s: a facet's winding disagrees with its normal" % found[0])
                break
        L = LENGTH[b["CS1"]["unit"]]
        vol = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]) * L ** 3
        if nid not in deliberate.get("implausible_density", []) and abs(vol / b["volume"] - 1) > 1e-6:
            fail(case, "body %s: mesh box volume %r != volume %r" % (nid, vol, b["volume"]))
        # CG in CS1 coordinates (file units) inside the box, at its centre.
        cs1 = b["CS1"]
        d = [(b["CG"]["p"][i] - cs1["p"][i]) / L for i in range(3)]
        cg_local = mv(tr(cs1["R"]), d)
        centre = [(lo[i] + hi[i]) / 2 for i in range(3)]
        if vdiff(cg_local, centre) > 1e-6:
            fail(case, "body %s: CG %r not at the mesh box centre %r" % (nid, cg_local, centre))
        b["mesh_file"] = found[0]
    return flaws


def graph_counts(ex):
    nodes = {}
    for b in ex.bodies:
        nodes[id(b)] = id(b)
    for g in ex.grounds:
        nodes[id(g)] = id(g)

    def find(x):
        while nodes[x] != x:
            x = nodes[x]
        return x

    edges = 0
    for j in ex.joints:
        fb, ff = ex.by_ref.get(j["base_ref"]), ex.by_ref.get(j["follower_ref"])
        if fb is None or ff is None:
            continue
        edges += 1
        a, b = find(id(fb["owner"])), find(id(ff["owner"]))
        if a != b:
            nodes[a] = b
    comps = len({find(x) for x in list(nodes)})
    return len(ex.bodies), len(ex.joints), edges - len(nodes) + comps


def check_expect(case, ex, expect):
    nb, nj, loops = graph_counts(ex)
    if (nb, nj, loops) != (expect["bodies"], expect["joints"], expect["loops"]):
        fail(case, "counts %r != expect %r" % ((nb, nj, loops), (expect["bodies"], expect["joints"], expect["loops"])))
    if "frames" not in expect:
        return
    want = {f["node_id"]: f for f in expect["frames"]}
    got = {f["node_id"]: f for f in ex.frames}
    if len(got) != len(ex.frames):
        fail(case, "frame nodeIDs not unique")
    if set(want) != set(got):
        fail(case, "frame sets differ: %r" % (set(want) ^ set(got)))
    for k, f in got.items():
        w = want.get(k)
        if w is None:
            continue
        if vdiff(f["p"], w["position_m"]) > 1e-15:
            fail(case, "frame %s position differs" % k)
        # Exact for frames in WORLD; frames given relative to others are composed here and by
        # the generator independently: equal to rounding.
        tol = 0 if f["refs"] == ["WORLD"] * 3 else 1e-15
        if (f["refs"] != ["WORLD"] * 3) != ("given_relative_to" in w) or f["refs"] != w.get("given_relative_to", f["refs"]):
            fail(case, "frame %s references %r differ from expect.json" % (k, f["refs"]))
        for j, key in enumerate(("x_axis", "y_axis", "z_axis")):
            if vdiff([f["R"][i][j] for i in range(3)], w[key]) > tol:
                fail(case, "frame %s %s differs" % (k, key))
        if (f["ref"] and int(f["ref"])) != w.get("ref"):
            fail(case, "frame %s ref differs" % k)
        if w["owner"] != f["owner"]["node_id"]:
            fail(case, "frame %s owner differs" % k)
    for b in ex.bodies:
        if vdiff(b["CG"]["p"], expect["cg_world_m"][b["node_id"]]) > 1e-15:
            fail(case, "CG of %s differs" % b["node_id"])
        if abs(b["mass"] - expect["mass_kg"][b["node_id"]]) > 1e-15 * max(1, b["mass"]):
            fail(case, "mass of %s differs" % b["node_id"])
    for grp in expect.get("lumped", []):
        parts = [b for b in ex.bodies if b["node_id"] in grp["bodies"]]
        M = sum(b["mass"] for b in parts)
        C = [sum(b["mass"] * b["CG"]["p"][i] for b in parts) / M for i in range(3)]
        It = [[0.0] * 3 for _ in range(3)]
        for b in parts:
            R = b["CG"]["R"]
            Iw = mm(mm(R, b["I"]), tr(R))
            dv = [b["CG"]["p"][i] - C[i] for i in range(3)]
            dd = sum(x * x for x in dv)
            for i in range(3):
                for k in range(3):
                    It[i][k] += Iw[i][k] + b["mass"] * ((dd if i == k else 0) - dv[i] * dv[k])
        if abs(M - grp["mass_kg"]) > 1e-12 or vdiff(C, grp["cg_world_m"]) > 1e-12 \
                or maxdiff(It, grp["inertia_world_kgm2"]) > 1e-12:
            fail(case, "lumped properties differ")
        # The weld joining the group: frames coincide, CS1 frames do not.
        if vdiff(parts[0]["CS1"]["p"], parts[1]["CS1"]["p"]) < 1e-6 or \
                maxdiff(parts[0]["CS1"]["R"], parts[1]["CS1"]["R"]) < 1e-6:
            fail(case, "lumped parts' CS1 frames should differ")


def check_case(root, case):
    bundle = root / case
    if not bundle.is_dir():
        fail(case, "missing")
        return None
    expect = json.loads((bundle / "expect.json").read_text())
    xmls = sorted(p for p in bundle.rglob("*") if p.suffix.lower() == ".xml")
    flaw = ERROR_CASES.get(case)
    stls = {p.relative_to(bundle).as_posix() for p in bundle.rglob("*") if p.suffix.lower() == ".stl"}
    others = {p.relative_to(bundle).as_posix() for p in bundle.rglob("*") if p.is_file()} \
        - stls - {x.relative_to(bundle).as_posix() for x in xmls} - {"expect.json", "options.json"}
    if others:
        fail(case, "unexpected files %r" % others)
    if (bundle / "options.json").exists() != (case == "lump_welds"):
        fail(case, "options.json only belongs to lump_welds")
    if case == "lump_welds":
        o = json.loads((bundle / "options.json").read_text())
        if o != {"lump_welds": True, "package_name": "LumpedArm", "gravity": [0, 0, -9.81]}:
            fail(case, "options.json %r" % o)
    if flaw is None and "error_contains" in expect:
        fail(case, "error_contains on a valid case")
    if flaw is not None and not expect.get("error_contains"):
        fail(case, "no error_contains")
    if flaw == "two_xml":
        if len(xmls) != 2:
            fail(case, "expected two XML files")
    elif len(xmls) != 1:
        fail(case, "expected one XML file, found %r" % xmls)
    if flaw == "truncated":
        try:
            ET.parse(xmls[0])
            fail(case, "truncated XML parses")
        except ET.ParseError:
            pass
        t = xmls[0].read_text()
        if t.rstrip().endswith(">"):
            fail(case, "truncated XML ends at a tag")
        return expect
    tolerate = {flaw} if flaw else set()
    used = set()
    for x in xmls:
        try:
            ex = Export(x)
        except Exception as e:  # noqa: BLE001
            fail(case, "%s does not read: %r" % (x.name, e))
            continue
        found = check_export(case, bundle, ex, expect, tolerate)
        if flaw and flaw != "two_xml" and flaw not in found:
            fail(case, "intended flaw %s not present" % flaw)
        if flaw and len(set(found)) > 1:
            fail(case, "more than one flaw: %r" % sorted(set(found)))
        if flaw == "dangling_ref":
            if not any(j["follower_ref"] == expect["error_contains"] for j in ex.joints):
                fail(case, "dangling ref is not %s" % expect["error_contains"])
        if flaw in ("unknown_unit", "nan"):
            if not any(expect["error_contains"] in str(f) for f in ex.flaws):
                fail(case, "error_contains does not name the flaw")
        if flaw in ("unsupported_ref", "frame_missing", "frame_cycle"):
            named = ['"%s"' % f[1] if flaw != "frame_cycle" else f[1] for f in ex.flaws if f[0] == flaw]
            if not any(n in expect["error_contains"] for n in named):
                fail(case, "error_contains does not name the flaw %r" % named)
        if flaw is None:
            if expect.get("xml") != x.name:
                fail(case, "expect.xml is %r" % expect.get("xml"))
            check_expect(case, ex, expect)
        else:
            nb, nj, loops = graph_counts(ex)
            if flaw != "dangling_ref" and (nb, nj, loops) != (expect["bodies"], expect["joints"], expect["loops"]):
                fail(case, "counts differ")
        used |= {b["mesh_file"] for b in ex.bodies if "mesh_file" in b}
    if flaw != "ambiguous" and used != stls:
        fail(case, "STL files not named by the XML: %r" % (stls - used))
    return expect


def main(argv):
    here = Path(__file__).resolve().parent
    root = Path(argv[1]) if len(argv) > 1 else here.parent / "in"
    present = sorted(p.name for p in root.iterdir() if p.is_dir() and not p.name.startswith(OTHER_GENERATOR))
    if present != sorted(ALL_CASES):
        fail("tests/in", "case directories %r" % present)
    rows = []
    for case in ALL_CASES:
        try:
            e = check_case(root, case)
        except Exception as exc:  # noqa: BLE001
            fail(case, "check crashed: %r" % exc)
            continue
        size = sum(p.stat().st_size for p in (root / case).rglob("*") if p.is_file())
        if e is not None:
            rows.append((case, e, size))
    # Determinism: regenerate and compare byte for byte.
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([sys.executable, str(here / "make_fixtures.py"), tmp], check=True,
                       stdout=subprocess.DEVNULL)
        a = {p.relative_to(tmp).as_posix(): p.read_bytes() for p in Path(tmp).rglob("*") if p.is_file()}
        b = {p.relative_to(root).as_posix(): p.read_bytes() for p in root.rglob("*")
             if p.is_file() and not p.relative_to(root).as_posix().startswith(OTHER_GENERATOR)}
        if a != b:
            diff = sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
            fail("determinism", "regenerated files differ: %r" % diff[:10])
    for case, e, size in rows:
        if "error_contains" in e:
            print("%-22s %6d bytes  error containing %r" % (case, size, e["error_contains"]))
        else:
            print("%-22s %6d bytes  bodies %d, joints %d, loops %d, frames %d" % (
                case, size, e["bodies"], e["joints"], e["loops"], len(e["frames"])))
    if failures:
        print("\n%d problems:" % len(failures))
        for f in failures:
            print("  " + f)
        return 1
    print("\nall %d cases verified" % len(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
