#!/usr/bin/env python3
"""Generate the synthetic first-generation SimMechanics bundles under tests/in/<case>/.

Every case is an input bundle: one PhysicalModelingXMLFile export (written the way SimMechanics
Link 3.1 / 4.0 and Simscape Multibody Link 4.8 / 5.0 write them: quoted strings, bare
comma-separated numbers, three-digit exponents, world-referenced 3x3 orientations whose nine
numbers are the frame's x, y and z axes in world coordinates), the STL meshes it names, an
`expect.json` with facts computed here independently of the converter, and for some cases an
`options.json`. `tests/in/README.md` is written too.

The mechanisms are built directly in world coordinates: every frame gets its world pose from
rotation matrices computed here, so joint frames coincide (or differ by exactly the encoded
initial joint value) to the last bit. Numbers that fix a pose are printed with repr (17
significant digits), so the XML round-trips exactly; the facts in expect.json are read back from
the printed text, so they are exactly what a parser of the XML sees, converted to SI. A frame
may be written relative to other frames (`Frame.rel`: position origin, position axes,
orientation reference, each WORLD, a frame of the same body or the frame at the other end of
its joint, ADJOINING); its numbers are then computed from its exact world pose and what a parser
sees of the frames it refers to, so the world pose is reproduced to ~1e-15. A primitive's axis
may be written in the axes of its joint's BASE or FOLLOWER frame (`Joint.axis_frames`).

Standard library only, deterministic: running it twice gives byte-identical files.

    python3 tests/tools/make_fixtures.py [OUT_DIR]     (default: tests/in next to this script)
"""

import json
import math
import re
import shutil
import struct
import sys
from pathlib import Path

# ---------------------------------------------------------------------------------------------
# Linear algebra on 3-vectors (tuples) and 3x3 matrices (tuples of rows).
# A frame orientation R has the frame's axes as columns: R[i][j] = component i of axis j.


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def mul(s, a):
    return tuple(s * x for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    n = norm(a)
    return tuple(x / n for x in a)


def mat_mul(A, B):
    return tuple(tuple(sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)) for i in range(3))


def mat_vec(A, v):
    return tuple(sum(A[i][k] * v[k] for k in range(3)) for i in range(3))


def transpose(A):
    return tuple(tuple(A[j][i] for j in range(3)) for i in range(3))


def col(A, j):
    return (A[0][j], A[1][j], A[2][j])


def from_cols(x, y, z):
    return tuple((x[i], y[i], z[i]) for i in range(3))


I3 = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


def rot(axis, deg):
    """Rotation by deg degrees about the unit vector axis (right-handed), Rodrigues' formula."""
    x, y, z = unit(axis)
    t = math.radians(deg)
    c, s = math.cos(t), math.sin(t)
    C = 1.0 - c
    return (
        (c + x * x * C, x * y * C - z * s, x * z * C + y * s),
        (y * x * C + z * s, c + y * y * C, y * z * C - x * s),
        (z * x * C - y * s, z * y * C + x * s, c + z * z * C),
    )


def Rx(deg):
    return rot((1, 0, 0), deg)


def Ry(deg):
    return rot((0, 1, 0), deg)


def Rz(deg):
    return rot((0, 0, 1), deg)


def chain(*Ms):
    out = I3
    for M in Ms:
        out = mat_mul(out, M)
    return out


def frame_xz(x, z):
    """Orientation whose z axis is z and whose x axis is x made orthogonal to it."""
    z = unit(z)
    x = unit(sub(x, mul(dot(x, z), z)))
    return from_cols(x, cross(z, x), z)


def perpendicular(a):
    """Some unit vector perpendicular to a."""
    helper = (1.0, 0.0, 0.0) if abs(a[0]) < 0.9 else (0.0, 1.0, 0.0)
    return unit(cross(a, helper))


# ---------------------------------------------------------------------------------------------
# Number formatting as real exports do it (MSVC printf: three-digit exponents).


def _exp3(s):
    return re.sub(r"e([+-])(\d+)$", lambda m: "e" + m.group(1) + m.group(2).rjust(3, "0"), s)


def num(x):
    """Exact: repr (round-trips), integers without '.0', three-digit exponents."""
    x = float(x)
    if x == 0.0:
        return "0"
    if x == int(x) and abs(x) < 1e15:
        return str(int(x))
    return _exp3(repr(x))


def g6(x):
    """Six significant digits, like the exports' mass, inertia, volume and area."""
    x = float(x)
    if x == 0.0:
        return "0"
    return _exp3("%.6g" % x)


def vec(xs, f=num):
    return ",".join(f(x) for x in xs)


def orient_text(R):
    return vec(col(R, 0) + col(R, 1) + col(R, 2))


def parse_vec(s):
    return tuple(float(t) for t in s.split(","))


# ---------------------------------------------------------------------------------------------
# Units.

DENSITY_AL = 2700.0  # kg/m^3
DENSITY_STEEL = 7850.0
LBM = 0.45359237
INCH = 0.0254

UNITS = {
    "mm": dict(length="mm", L=1e-3, mass="kg", M=1.0, inertia="kg*m^2", J=1.0,
               volume="mm^3", V=1e-9, area="mm^2", A=1e-6),
    "in": dict(length="in", L=INCH, mass="lbm", M=LBM, inertia="lbm*in^2", J=LBM * INCH * INCH,
               volume="in^3", V=INCH ** 3, area="in^2", A=INCH ** 2),
}

# ---------------------------------------------------------------------------------------------
# The model.


class Frame:
    def __init__(self, owner, pos, R, kind, ref=None, node_id="", display=""):
        self.owner = owner  # Body or Ground
        self.pos = tuple(float(v) for v in pos)  # world, file length unit
        self.R = R
        self.kind = kind  # "CG", "CS1", "user", "joint", "ground"
        self.ref = ref
        self.node_id = node_id
        self.display = display
        self.name = ""
        self.over = {}  # element name -> raw text (used by the broken cases)
        # Position origin, position axes, orientation reference: None (WORLD) or a Frame of the
        # same owner (written by name) or at the other end of this frame's joint (ADJOINING).
        self.rel = (None, None, None)


class Body:
    def __init__(self, asm, name, node_id):
        self.asm = asm
        self.name = name
        self.node_id = node_id
        self.frames = []
        self.mass = 0.0  # file units, exact values written with g6
        self.inertia = ((0.0,) * 3,) * 3
        self.volume = 0.0
        self.area = 0.0
        self.geometry = ""
        self.material = None
        self.mass_text = None  # overrides
        self.inertia_text = None
        self.volume_text = None
        self.mass_units = None


class Ground:
    def __init__(self, asm):
        self.asm = asm
        self.name = "RootGround"
        self.node_id = "RootGround"
        self.frame = None


class Joint:
    def __init__(self, name, node_id, base, follower, prims, initial):
        self.name = name
        self.node_id = node_id
        self.base = base
        self.follower = follower
        self.prims = prims  # [(kind, axis tuple or None for the dummy axis)]
        self.initial = initial  # per primitive: rad / file length / None
        self.follower_ref_text = None
        self.axis_frames = ["WORLD"] * len(self.prims)  # or "BASE" / "FOLLOWER"


class Asm:
    def __init__(self, name, node_id, parent=None):
        self.name = name
        self.node_id = node_id
        self.parent = parent
        self.bodies = []
        self.joints = []
        self.grounds = []
        self.subs = []
        if parent is not None:
            parent.subs.append(self)

    def chain_up(self):
        a, out = self, []
        while a is not None:
            out.append(a)
            a = a.parent
        return out


DUMMY_AXIS = "0.57735,0.57735,0.57735"


class Model:
    def __init__(self, name, units="mm", container="SimscapeMultibody", link="4.8",
                 created_from="Pro/E Wildfire Creo 7.0 - 2020454", created_on="03/14/24||10:20:30",
                 created_by="cad2mo", top_node=None):
        self.name = name
        self.u = UNITS[units]
        self.container = container
        self.link = link
        self.created_from = created_from
        self.created_on = created_on
        self.created_by = created_by
        self.top = Asm(name, top_node or name)
        self.next_ref = 1
        self.meshes = {}  # bundle path -> bytes
        self.weld_groups = []
        self._seen = {}  # id(frame) -> world pose as a parser of the XML sees it

    @property
    def old_link(self):
        return self.link.startswith("3.")

    def root_part_id(self, asm):
        if asm is self.top and self.old_link:
            return "RootPart"
        return asm.node_id + "/RootPart"

    # -- bodies ------------------------------------------------------------------------------

    def root_part(self, asm, cg):
        b = Body(asm, "RootPart", self.root_part_id(asm))
        b.frames.append(Frame(b, cg, I3, "CG", node_id=b.node_id + "::CG(AUTOGEN)"))
        b.frames.append(Frame(b, (0, 0, 0), I3, "CS1", node_id=b.node_id + "::CS1(AUTOGEN)"))
        asm.bodies.append(b)
        return b

    def part(self, asm, name, node_id, cs1_pos, cs1_R, lo, hi, density=DENSITY_AL, cg_R=None,
             geometry=None, mesh_path=None, mesh_format="ascii", material=None, mesh_header=None):
        """A part whose solid is the box lo..hi (CS1 coordinates, file length unit).

        Mass, centre of gravity and inertia are the box's; the CG frame has orientation cg_R
        (default: CS1's) and the inertia is resolved in its axes."""
        u = self.u
        b = Body(asm, name, node_id)
        d = sub(hi, lo)
        center_local = mul(0.5, add(lo, hi))
        cg = add(cs1_pos, mat_vec(cs1_R, center_local))
        cg_R = cg_R or cs1_R
        vol = d[0] * d[1] * d[2]
        b.volume = vol
        b.area = 2.0 * (d[0] * d[1] + d[1] * d[2] + d[0] * d[2])
        mass_kg = density * vol * u["V"]
        b.mass = float(g6(mass_kg / u["M"]))
        # Box inertia in SI about its centre, box (= CS1) axes, then resolved in CG axes.
        m = b.mass * u["M"]
        L = [x * u["L"] for x in d]
        Ibox = ((m * (L[1] ** 2 + L[2] ** 2) / 12, 0.0, 0.0),
                (0.0, m * (L[0] ** 2 + L[2] ** 2) / 12, 0.0),
                (0.0, 0.0, m * (L[0] ** 2 + L[1] ** 2) / 12))
        C = mat_mul(transpose(cg_R), cs1_R)  # CG axes <- CS1 axes
        Icg = mat_mul(mat_mul(C, Ibox), transpose(C))
        Icg = tuple(tuple(0.5 * (Icg[i][j] + Icg[j][i]) / u["J"] for j in range(3)) for i in range(3))
        b.inertia = Icg
        b.frames.append(Frame(b, cg, cg_R, "CG", node_id=node_id + "::CG(AUTOGEN)"))
        b.frames.append(Frame(b, cs1_pos, cs1_R, "CS1", node_id=node_id + "::CS1(AUTOGEN)"))
        if geometry is None:
            geometry = name + "_prt.stl"
        b.geometry = geometry
        b.material = material
        if mesh_path is not None:
            self.meshes[mesh_path] = box_stl(name, lo, hi, mesh_format, mesh_header)
        asm.bodies.append(b)
        return b

    def user_frame(self, body, pos, R, node_id, display):
        f = Frame(body, pos, R, "user", node_id=node_id, display=display)
        body.frames.append(f)
        return f

    # -- joints ------------------------------------------------------------------------------

    def side_id(self, owner, asm):
        """How a joint's nodeID names one side, seen from the assembly holding the joint."""
        if isinstance(owner, Ground):
            return "RootGround"
        if owner.asm is asm:
            return owner.node_id
        for a in owner.asm.chain_up():
            if a.parent is asm:
                return a.node_id + ":" + owner.node_id
        raise ValueError("joint side %s is not below %s" % (owner.node_id, asm.node_id))

    def joint(self, asm, base, follower, base_pos, base_R, fol_pos=None, fol_R=None,
              prims=(("revolute", (0, 0, 1)),), initial=None):
        fol_pos = base_pos if fol_pos is None else fol_pos
        fol_R = base_R if fol_R is None else fol_R
        node = ":-:".join(sorted([self.side_id(base, asm), self.side_id(follower, asm)]))
        frames = []
        for owner, pos, R in ((base, base_pos, base_R), (follower, fol_pos, fol_R)):
            f = Frame(owner, pos, R, "ground" if isinstance(owner, Ground) else "joint",
                      ref=self.next_ref, node_id="%s::%s(AUTOGEN)" % (node, owner.node_id))
            self.next_ref += 1
            if isinstance(owner, Ground):
                owner.frame = f
            else:
                owner.frames.append(f)
            frames.append(f)
        if initial is None:
            initial = [0.0 if k in ("revolute", "prismatic") else None for k, _ in prims]
        j = Joint("%s--%s" % (base.name, follower.name), node, frames[0], frames[1], list(prims), initial)
        asm.joints.append(j)
        return j

    def weld(self, asm, base, follower, pos, R=I3):
        return self.joint(asm, base, follower, pos, R, prims=(("weld", None),))

    def ground(self, root_part, pos, R=I3):
        """RootGround (in the top assembly) welded to the top RootPart: created last, like the
        exports, which list this weld last and give it the highest refs."""
        g = Ground(self.top)
        self.top.grounds.append(g)
        self.weld(self.top, g, root_part, pos, R)
        return g

    # -- traversal ---------------------------------------------------------------------------

    def asms(self, a=None):
        a = a or self.top
        yield a
        for s in a.subs:
            yield from self.asms(s)

    def bodies(self):
        for a in self.asms():
            yield from a.bodies

    def joints(self):
        for a in self.asms():
            yield from a.joints

    def grounds(self):
        for a in self.asms():
            yield from a.grounds

    def all_frames(self):
        for b in self.bodies():
            yield from b.frames
        for g in self.grounds():
            yield g.frame

    # -- frames relative to other frames -----------------------------------------------------

    def rel_name(self, f, t):
        """How frame f writes its reference t: WORLD, a sibling's name or ADJOINING."""
        if t is None:
            return "WORLD"
        if t.owner is f.owner:
            return t.name
        users = [j for j in self.joints() if f in (j.base, j.follower)]
        assert len(users) == 1 and t in (users[0].base, users[0].follower), "ADJOINING: not joined"
        return "ADJOINING"

    def given(self, f):
        """The position and orientation written for f: its exact world pose expressed relative
        to what a parser sees of its references."""
        X, Y, Z = (None if t is None else self.seen(t) for t in f.rel)
        origin = X[0] if X else (0.0, 0.0, 0.0)
        RY = Y[1] if Y else I3
        RZ = Z[1] if Z else I3
        return mat_vec(transpose(RY), sub(f.pos, origin)), mat_mul(transpose(RZ), f.R)

    def seen(self, f):
        """World pose (position in the file's length unit, orientation) of f as a parser of the
        printed XML computes it."""
        key = id(f)
        if key not in self._seen:
            p, R = self.given(f)
            p = parse_vec(vec(p))
            o = parse_vec(orient_text(R))
            R = from_cols(o[0:3], o[3:6], o[6:9])
            X, Y, Z = (None if t is None else self.seen(t) for t in f.rel)
            if X or Y or Z:
                p = add(X[0] if X else (0.0, 0.0, 0.0), mat_vec(Y[1] if Y else I3, p))
                R = mat_mul(Z[1], R) if Z else R
            self._seen[key] = (p, R)
        return self._seen[key]

    def axis_text(self, j, k):
        """A primitive's axis as written: in world axes or its BASE / FOLLOWER frame's axes."""
        axis = j.prims[k][1]
        if axis is None:
            return DUMMY_AXIS
        frame = {"WORLD": None, "BASE": j.base, "FOLLOWER": j.follower}[j.axis_frames[k]]
        return vec(axis if frame is None else mat_vec(transpose(self.seen(frame)[1]), axis))

    def axis_seen(self, j, k):
        """A primitive's world axis as a parser of the printed XML computes it."""
        a = parse_vec(self.axis_text(j, k))
        frame = {"WORLD": None, "BASE": j.base, "FOLLOWER": j.follower}[j.axis_frames[k]]
        return a if frame is None else mat_vec(self.seen(frame)[1], a)

    def finish(self):
        """Name the frames like the exports: CG, CS1, then CS2.. in order (user frames first)."""
        for b in self.bodies():
            order = {"CG": 0, "CS1": 1, "user": 2, "joint": 3}
            b.frames.sort(key=lambda f: order[f.kind])  # stable: joint frames keep creation order
            k = 2
            for f in b.frames:
                if f.kind in ("CG", "CS1"):
                    f.name = f.kind
                else:
                    f.name = "CS%d" % k
                    k += 1
        for g in self.grounds():
            g.frame.name = "CS1"

    # -- XML ---------------------------------------------------------------------------------

    def xml(self):
        self.finish()
        out = []
        w = out.append
        w('<?xml version="1.0" encoding="UTF-8" standalone="no" ?>')
        w("<PhysicalModelingXMLFile>")
        w("")
        header = [
            ("formatVersion", '"1.0.4"'),
            ("internalVersion", "1"),
            ("createdUsing", '"%s Link Version %s"' % (
                "SimMechanics" if self.link in ("3.1", "4.0") else "Simscape Multibody", self.link)),
            ("createdFrom", '"%s"' % self.created_from),
            ("createdOn", '"%s"' % self.created_on),
            ("createdBy", '"%s"' % self.created_by),
            ("name", '"%s"' % self.name),
        ]
        for tag, val in header:
            w("  <%s>%s</%s>" % (tag, val, tag))
            w("")
        w("  <%s>" % self.container)
        self._asm_body(self.top, 4, w, top=True)
        w("  </%s>" % self.container)
        w("")
        w("</PhysicalModelingXMLFile>")
        return "\n".join(out) + "\n"

    def _asm_body(self, a, ind, w, top):
        p = " " * ind
        w('%s<name>"%s"</name>' % (p, a.name))
        w('%s<nodeID>"%s"</nodeID>' % (p, a.node_id))
        if not top:
            w('%s<status>""</status>' % p)
        self._list(p, "bodies", a.bodies, lambda b: self._body(b, ind + 2, w), w)
        self._list(p, "joints", a.joints, lambda j: self._joint(j, ind + 2, w), w)
        self._list(p, "grounds", a.grounds, lambda g: self._ground(g, ind + 2, w), w)

        def sub_(s):
            q = " " * (ind + 2)
            w("%s<Subsystem>" % q)
            self._asm_body(s, ind + 4, w, top=False)
            w("%s</Subsystem>" % q)

        self._list(p, "subsystems", a.subs, sub_, w)
        w("%s<connectionPorts></connectionPorts>" % p)
        w("%s<id>0</id>" % p)

    @staticmethod
    def _list(p, tag, items, each, w):
        if not items:
            w("%s<%s></%s>" % (p, tag, tag))
            return
        w("%s<%s>" % (p, tag))
        for it in items:
            each(it)
        w("%s</%s>" % (p, tag))

    def _body(self, b, ind, w):
        p = " " * ind
        q = p + "  "
        u = self.u
        w("%s<Body>" % p)
        w('%s<name>"%s"</name>' % (q, b.name))
        w('%s<nodeID>"%s"</nodeID>' % (q, b.node_id))
        w('%s<status>""</status>' % q)
        w("%s<mass>%s</mass>" % (q, b.mass_text or g6(b.mass)))
        w('%s<massUnits>"%s"</massUnits>' % (q, b.mass_units or u["mass"]))
        w("%s<inertia>%s</inertia>" % (q, b.inertia_text or vec([b.inertia[i][j] for i in range(3) for j in range(3)], g6)))
        w('%s<inertiaUnits>"%s"</inertiaUnits>' % (q, u["inertia"]))
        w("%s<volume>%s</volume>" % (q, b.volume_text or g6(b.volume)))
        w('%s<volumeUnits>"%s"</volumeUnits>' % (q, u["volume"]))
        w("%s<surfaceArea>%s</surfaceArea>" % (q, g6(b.area)))
        w('%s<surfaceAreaUnits>"%s"</surfaceAreaUnits>' % (q, u["area"]))
        w("%s<frames>" % q)
        for f in b.frames:
            self._frame(f, ind + 4, w)
        w("%s</frames>" % q)
        w('%s<geometryFileName>"%s"</geometryFileName>' % (q, b.geometry))
        if b.material:
            m = b.material
            w("%s<MaterialProp>" % q)
            w("%s  <color>%s</color>" % (q, vec(m["color"], g6)))
            for k in ("ambient", "diffuse", "specular", "shininess", "transparency", "emission"):
                w("%s  <%s>%s</%s>" % (q, k, g6(m[k]), k))
            w("%s</MaterialProp>" % q)
        w("%s</Body>" % p)

    def _frame(self, f, ind, w):
        p = " " * ind
        q = p + "  "
        o = f.over
        pos, R = self.given(f)
        origin, axes, orient_ref = (self.rel_name(f, t) for t in f.rel)
        w("%s<Frame%s>" % (p, ' ref="%d"' % f.ref if f.ref is not None else ""))
        w('%s<name>"%s"</name>' % (q, f.name))
        if not self.old_link:
            w('%s<displayName>"%s"</displayName>' % (q, f.display))
        w('%s<nodeID>"%s"</nodeID>' % (q, f.node_id))
        w("%s<position>%s</position>" % (q, o.get("position", vec(pos))))
        w('%s<positionOrigin>"%s"</positionOrigin>' % (q, o.get("positionOrigin", origin)))
        w('%s<positionReferenceFrame>"%s"</positionReferenceFrame>' % (q, o.get("positionReferenceFrame", axes)))
        w('%s<positionUnits>"%s"</positionUnits>' % (q, o.get("positionUnits", self.u["length"])))
        w("%s<orientation>%s</orientation>" % (q, o.get("orientation", orient_text(R))))
        w('%s<orientationType>"3x3 Transform"</orientationType>' % q)
        w('%s<orientationUnits>"rad"</orientationUnits>' % q)
        w('%s<orientationReferenceFrame>"%s"</orientationReferenceFrame>' % (q, o.get("orientationReferenceFrame", orient_ref)))
        w("%s</Frame>" % p)

    def _joint(self, j, ind, w):
        p = " " * ind
        q = p + "  "
        w("%s<SimpleJoint>" % p)
        w('%s<name>"%s"</name>' % (q, j.name))
        w('%s<nodeID>"%s"</nodeID>' % (q, j.node_id))
        w('%s<status>""</status>' % q)
        for side, f in (("base", j.base), ("follower", j.follower)):
            ref = str(f.ref)
            if side == "follower" and j.follower_ref_text is not None:
                ref = j.follower_ref_text
            w("%s<%s>" % (q, side))
            w("%s  <JointSide>" % q)
            w('%s    <name>""</name>' % q)
            w("%s    <connection>" % q)
            w('%s      <Frame ref="%s"></Frame>' % (q, ref))
            w("%s    </connection>" % q)
            w("%s  </JointSide>" % q)
            w("%s</%s>" % (q, side))
        w("%s<primitives>" % q)
        for k, (kind, axis) in enumerate(j.prims):
            w("%s  <Primitive>" % q)
            w('%s    <name>"%s"</name>' % (q, kind))
            w('%s    <nodeID>""</nodeID>' % q)
            w('%s    <referenceFrame>"%s"</referenceFrame>' % (q, j.axis_frames[k]))
            w("%s    <axis>%s</axis>" % (q, self.axis_text(j, k)))
            w("%s  </Primitive>" % q)
        w("%s</primitives>" % q)
        w("%s</SimpleJoint>" % p)

    def _ground(self, g, ind, w):
        p = " " * ind
        q = p + "  "
        w("%s<Ground>" % p)
        w('%s<name>"%s"</name>' % (q, g.name))
        w('%s<nodeID>"%s"</nodeID>' % (q, g.node_id))
        w('%s<status>""</status>' % q)
        w("%s<frame>" % q)
        self._frame(g.frame, ind + 4, w)
        w("%s</frame>" % q)
        w("%s</Ground>" % p)

    # -- facts -------------------------------------------------------------------------------

    def expect(self, xml_name):
        """Facts read back from the printed numbers, converted to SI."""
        u = self.u
        L = u["L"]
        frames = []
        cgs = {}
        masses = {}
        for f in self.all_frames():
            p, R = self.seen(f)
            owner = f.owner.node_id
            entry = {
                "node_id": f.node_id,
                "owner": owner,
                "name": f.name,
                "position_m": [v * L for v in p],
                "x_axis": list(col(R, 0)),
                "y_axis": list(col(R, 1)),
                "z_axis": list(col(R, 2)),
            }
            if f.rel != (None, None, None):
                entry["given_relative_to"] = [self.rel_name(f, t) for t in f.rel]
            if f.ref is not None:
                entry["ref"] = f.ref
            if f.display:
                entry["display_name"] = f.display
            frames.append(entry)
            if f.kind == "CG":
                cgs[owner] = entry["position_m"]
        for b in self.bodies():
            masses[b.node_id] = float(b.mass_text or g6(b.mass)) * u["M"]
        joints = []
        for j in self.joints():
            prims = []
            for k, ((kind, axis), init) in enumerate(zip(j.prims, j.initial)):
                pr = {"kind": kind, "axis_world": list(self.axis_seen(j, k))}
                if j.axis_frames[k] != "WORLD":
                    pr["axis_given_in"] = j.axis_frames[k]
                if kind == "revolute":
                    pr["initial_rad"] = init
                elif kind == "prismatic":
                    pr["initial_m"] = init * L
                prims.append(pr)
            joints.append({
                "node_id": j.node_id,
                "name": j.name,
                "base_frame": j.base.node_id,
                "follower_frame": j.follower.node_id,
                "primitives": prims,
            })
        nb, nj, loops = graph_counts(self)
        return {
            "xml": xml_name,
            "bodies": nb,
            "joints": nj,
            "loops": loops,
            "units": {k: u[k] for k in ("length", "mass", "inertia", "volume", "area")},
            "frames": frames,
            "cg_world_m": cgs,
            "mass_kg": masses,
            "joint_details": joints,
        }


def graph_counts(model):
    """Bodies (RootParts included), joints (ground welds included), independent loops
    (cyclomatic number of the graph whose nodes are bodies and grounds)."""
    nodes = {}
    for b in model.bodies():
        nodes[id(b)] = id(b)
    for g in model.grounds():
        nodes[id(g)] = id(g)

    def find(x):
        while nodes[x] != x:
            nodes[x] = nodes[nodes[x]]
            x = nodes[x]
        return x

    edges = 0
    for j in model.joints():
        edges += 1
        a, b = find(id(j.base.owner)), find(id(j.follower.owner))
        if a != b:
            nodes[a] = b
    comps = len({find(x) for x in list(nodes)})
    nb = sum(1 for _ in model.bodies())
    return nb, edges, edges - len(nodes) + comps


# ---------------------------------------------------------------------------------------------
# STL: a box lo..hi (12 triangles), outward normals, counter-clockwise seen from outside.


def box_triangles(lo, hi):
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    faces = [
        ((0, 0, -1), (0, 3, 2, 1)),
        ((0, 0, 1), (4, 5, 6, 7)),
        ((0, -1, 0), (0, 1, 5, 4)),
        ((0, 1, 0), (3, 7, 6, 2)),
        ((-1, 0, 0), (0, 4, 7, 3)),
        ((1, 0, 0), (1, 2, 6, 5)),
    ]
    tris = []
    for n, (a, b, c, d) in faces:
        tris.append((n, v[a], v[b], v[c]))
        tris.append((n, v[a], v[c], v[d]))
    return tris


def box_stl(name, lo, hi, fmt, header=None):
    tris = box_triangles(lo, hi)
    if fmt == "ascii":
        lines = ["solid %s" % name.upper()]
        for n, a, b, c in tris:
            lines.append("  facet normal %e %e %e" % n)
            lines.append("    outer loop")
            for p in (a, b, c):
                lines.append("      vertex %e %e %e" % p)
            lines.append("    endloop")
            lines.append("  endfacet")
        lines.append("endsolid %s" % name.upper())
        return ("\n".join(lines) + "\n").encode("ascii")
    if header is None:
        header = "binary STL of %s, written by cad2mo tests/tools/make_fixtures.py" % name
    head = header.encode("ascii")
    out = bytearray(head[:80].ljust(80, b"\0"))
    out += struct.pack("<I", len(tris))
    for n, a, b, c in tris:
        out += struct.pack("<12fH", *(n + a + b + c), 0)
    return bytes(out)


def bounds(points, pad, step):
    """Axis-aligned box around points, padded, rounded outward to multiples of step."""
    lo = tuple(math.floor((min(p[i] for p in points) - pad) / step) * step for i in range(3))
    hi = tuple(math.ceil((max(p[i] for p in points) + pad) / step) * step for i in range(3))
    return lo, hi


def local(cs1_pos, cs1_R, p):
    return mat_vec(transpose(cs1_R), sub(p, cs1_pos))


def link_box(cs1_pos, cs1_R, pts, pad, half_w, half_t, step):
    """Box around the points in CS1 coordinates: pad beyond them along x, half_w beyond them
    along y, half_t along z, rounded outward to multiples of step."""
    loc = [local(cs1_pos, cs1_R, p) for p in pts]
    margin = (pad, half_w, half_t)
    lo = tuple(math.floor((min(p[i] for p in loc) - margin[i]) / step) * step for i in range(3))
    hi = tuple(math.ceil((max(p[i] for p in loc) + margin[i]) / step) * step for i in range(3))
    return lo, hi


GREY = dict(color=(0.666667, 0.666667, 0.666667), ambient=0.4, diffuse=0.85, specular=0.9,
            shininess=0.3, transparency=0, emission=0.35)
BLUE = dict(color=(0.2, 0.35, 0.8), ambient=0.4, diffuse=0.8, specular=0.6, shininess=0.25,
            transparency=0, emission=0.2)
ORANGE = dict(color=(0.95, 0.55, 0.1), ambient=0.35, diffuse=0.9, specular=0.5, shininess=0.4,
              transparency=0.2, emission=0.1)

# ---------------------------------------------------------------------------------------------
# The cases. Each returns (model, extra facts for expect.json, options or None, xml file name).


def case_pendulum():
    m = Model("PENDULUM", container="SimscapeMultibody", link="4.8")
    top = m.top
    ground_p = (0.0, 500.0, 0.0)
    pivot = (0.0, 450.0, 0.0)
    rp = m.root_part(top, ground_p)
    R1 = Rz(-60.0)  # the link hangs 30 degrees off the vertical; CS1 x along the link
    lo, hi = (-15.0, -15.0, -5.0), (315.0, 15.0, 5.0)
    link = m.part(top, "LINK", "23", pivot, R1, lo, hi, geometry="LINK_PRT.STL",
                  mesh_path="meshes/LINK_prt.stl", material=GREY)
    m.joint(top, rp, link, pivot, I3, prims=(("revolute", (0, 0, 1)),))
    m.ground(rp, ground_p)
    return m, {}, None, "PENDULUM.xml"


def case_fourbar():
    m = Model("FOURBAR", container="SimMechanics", link="4.0",
              created_from="Pro/E Wildfire Creo 2.0 - 2012360")
    top = m.top
    A = (20.0, 10.0, 0.0)
    D = (220.0, 10.0, 0.0)
    crank, coupler, rocker = 60.0, 180.0, 150.0
    B = add(A, mul(crank, (math.cos(math.radians(70)), math.sin(math.radians(70)), 0.0)))
    # C: circle(B, coupler) meets circle(D, rocker), the upper solution.
    dBD = sub(D, B)
    dist = norm(dBD)
    a = (coupler ** 2 - rocker ** 2 + dist ** 2) / (2 * dist)
    h = math.sqrt(coupler ** 2 - a ** 2)
    ex = unit(dBD)
    ey = (-ex[1], ex[0], 0.0)
    C = add(add(B, mul(a, ex)), mul(h, ey))
    if C[1] < B[1]:
        C = sub(add(B, mul(a, ex)), mul(h, ey))
    rp = m.root_part(top, (0.0, 0.0, 0.0))

    def bar(name, node, P, Q, fmt, header=None, mat=None):
        x = unit(sub(Q, P))
        R = from_cols(x, cross((0, 0, 1), x), (0.0, 0.0, 1.0))
        lo, hi = link_box(P, R, [P, Q], 10.0, 10.0, 4.0, 1.0)
        return m.part(top, name, node, P, R, lo, hi, density=DENSITY_STEEL,
                      mesh_path=name + "_prt.stl", mesh_format=fmt, mesh_header=header, material=mat)

    # One binary header starts with "solid": the classic detection trap.
    b_crank = bar("CRANK", "40", A, B, "binary", "solid CRANK exported as binary STL", BLUE)
    b_coupler = bar("COUPLER", "41", B, C, "binary", None, GREY)
    b_rocker = bar("ROCKER", "45", D, C, "binary", None, ORANGE)
    m.joint(top, rp, b_crank, A, I3, prims=(("revolute", (0, 0, 1)),))
    m.joint(top, b_crank, b_coupler, B, I3, prims=(("revolute", (0, 0, 1)),))
    m.joint(top, b_coupler, b_rocker, C, I3, prims=(("revolute", (0, 0, 1)),))
    m.joint(top, rp, b_rocker, D, I3, prims=(("revolute", (0, 0, -1)),))
    m.ground(rp, (0.0, 0.0, 0.0))
    extra = {"pivots_m": {k: [v * 1e-3 for v in p] for k, p in (("A", A), ("B", B), ("C", C), ("D", D))}}
    return m, extra, None, "FOURBAR.xml"


def case_arm_subsystems():
    m = Model("ARM", container="SimMechanics", link="4.0",
              created_from="Pro/E Wildfire Creo 2.0 - 2012360")
    top = m.top
    upper = Asm("UPPER", "12", top)
    fore = Asm("FORE", "12/20", upper)
    rp = m.root_part(top, (0.0, 0.0, 0.0))
    base = m.part(top, "BASE", "7", (0.0, 0.0, 0.0), I3, (-60.0, 0.0, -60.0), (60.0, 90.0, 60.0),
                  mesh_path="meshes/BASE_prt.stl", mesh_format="binary", material=GREY)
    # Shoulder: revolute about normalised (1,1,0) at P1; upper link along u1, perpendicular to it.
    a1 = unit((1.0, 1.0, 0.0))
    P1 = (0.0, 100.0, 0.0)
    u1 = unit(add(mul(math.cos(math.radians(40)), unit((-1.0, 1.0, 0.0))), mul(math.sin(math.radians(40)), (0, 0, 1.0))))
    R_u = frame_xz(u1, a1)
    P2 = add(P1, mul(250.0, u1))
    lo, hi = link_box(P1, R_u, [P1, P2], 15.0, 15.0, 12.0, 1.0)
    up_link = m.part(upper, "LINK", "12/13", P1, R_u, lo, hi,
                     mesh_path="meshes/upper/LINK_prt.stl", mesh_format="ascii", material=BLUE)
    # Elbow: revolute about normalised (1,-1,1) at P2, initial angle -20 degrees.
    a2 = unit((1.0, -1.0, 1.0))
    u2 = unit(cross(a2, (0.0, 0.0, 1.0)))
    R_f = frame_xz(u2, a2)
    P3 = add(P2, mul(200.0, u2))
    lo, hi = link_box(P2, R_f, [P2, P3], 12.0, 12.0, 10.0, 1.0)
    # Two bodies called LINK: the geometry file names differ, like exports of two part instances.
    fore_link = m.part(fore, "LINK", "12/20/21", P2, R_f, lo, hi, geometry="LINK-1_prt.stl",
                       mesh_path="meshes/fore/LINK-1_prt.stl", mesh_format="binary", material=ORANGE)
    # Subsystem RootParts: welded to their subsystem's part at its CG (as iCub exports do).
    up_rp = m.root_part(upper, up_link.frames[0].pos)
    fore_rp = m.root_part(fore, fore_link.frames[0].pos)
    m.weld(fore, fore_rp, fore_link, fore_link.frames[0].pos)
    m.weld(upper, up_rp, up_link, up_link.frames[0].pos)
    Rj1 = frame_xz(perpendicular(a1), a1)
    Rj2 = frame_xz(perpendicular(a2), a2)
    m.joint(upper, up_link, fore_link, P2, Rj2, P2, mat_mul(rot(a2, -20.0), Rj2),
            prims=(("revolute", a2),), initial=[math.radians(-20.0)])
    m.weld(top, rp, base, (0.0, 0.0, 0.0))
    m.joint(top, base, up_link, P1, Rj1, prims=(("revolute", a1),))
    m.ground(rp, (0.0, 0.0, 0.0))
    extra = {"subsystems": {"12": "UPPER", "12/20": "FORE"}}
    return m, extra, None, "ARM_SIM_MODEL.xml"


def case_inch_lbm():
    m = Model("CHAIN_IN", units="in", container="SimMechanics", link="3.1",
              created_from="Pro/E Wildfire Wildfire 4.0 - 2008230", created_on="11/10/09||14:08:16")
    top = m.top
    rho = DENSITY_AL  # kg/m^3; the part helper converts
    ground_p = (0.0, 20.0, 0.0)
    P1 = (2.0, 18.0, 0.0)
    rp = m.root_part(top, ground_p)
    R1 = Rz(-70.0)
    P2 = add(P1, mul(12.0, col(R1, 0)))
    lo, hi = link_box(P1, R1, [P1, P2], 0.5, 0.5, 0.25, 0.25)
    l1 = m.part(top, "LINK1", "39", P1, R1, lo, hi, density=rho, geometry="LINK1.stl",
                mesh_path="LINK1.stl", mesh_format="ascii")
    R2 = Rz(-120.0)
    P3 = add(P2, mul(8.0, col(R2, 0)))
    lo, hi = link_box(P2, R2, [P2, P3], 0.5, 0.5, 0.25, 0.25)
    l2 = m.part(top, "LINK2", "40", P2, R2, lo, hi, density=rho, geometry="LINK2.stl",
                mesh_path="LINK2.stl", mesh_format="binary", mesh_header="")
    m.joint(top, rp, l1, P1, I3, prims=(("revolute", (0, 0, 1)),))
    m.joint(top, l1, l2, P2, I3, prims=(("revolute", (0, 0, 1)),))
    m.ground(rp, ground_p)
    return m, {}, None, "CHAIN_IN.xml"


def case_rotated_frames():
    m = Model("ROT", container="SimscapeMultibody", link="5.0",
              created_from="Pro/E Wildfire Creo 9.0 - 2022073")
    top = m.top
    Rg = Rx(-90.0)
    ground_p = (100.0, -50.0, 30.0)
    rp = m.root_part(top, ground_p)
    # Joint 1: revolute about the z axis of a frame oriented Rz(37) Ry(-20) Rx(65); the follower
    # frame is turned 30 degrees about it (initial angle).
    Ra = chain(Rz(37.0), Ry(-20.0), Rx(65.0))
    J1 = (150.0, 20.0, -40.0)
    a1 = col(Ra, 2)
    # Joint 2: prismatic along a generic axis; follower frame 25 mm along it, same orientation.
    Rc = chain(Rx(-35.0), Rz(110.0), Ry(15.0))
    J2 = add(J1, mat_vec(Ra, (120.0, 30.0, -10.0)))
    a2 = unit((0.6, -0.3, 0.74))
    J2f = add(J2, mul(25.0, a2))
    # Joint 3: revolute about a generic world axis at J3; frames coincide, rotated Rz(-70) Ry(33) Rx(12).
    Rd = chain(Rz(-70.0), Ry(33.0), Rx(12.0))
    J3 = add(J2f, (-40.0, 85.0, 60.0))
    a3 = unit((0.3, -0.5, 0.8))
    tip = add(J3, mul(90.0, perpendicular(a3)))
    Rtip = chain(rot(a3, 45.0), Rx(180.0))

    R_b1 = chain(Rz(-15.0), Rx(40.0), Ry(25.0))
    cs1_1 = add(J1, mat_vec(Ra, (-20.0, 5.0, 10.0)))
    lo, hi = bounds([local(cs1_1, R_b1, p) for p in (J1, J2)], 15.0, 1.0)
    b1 = m.part(top, "BRACKET", "101", cs1_1, R_b1, lo, hi, cg_R=chain(Ry(50.0), Rz(-30.0), Rx(10.0)),
                mesh_path="BRACKET_prt.stl", mesh_format="ascii", material=GREY)
    R_b2 = chain(Rx(20.0), Ry(-55.0), Rz(80.0))
    cs1_2 = add(J2f, (5.0, -5.0, 5.0))
    lo, hi = bounds([local(cs1_2, R_b2, p) for p in (J2f, J3)], 12.0, 1.0)
    b2 = m.part(top, "SLIDER", "102", cs1_2, R_b2, lo, hi, density=DENSITY_STEEL,
                cg_R=chain(Rz(120.0), Rx(-25.0)), mesh_path="SLIDER_prt.stl", mesh_format="binary",
                material=BLUE)
    R_b3 = chain(Ry(70.0), Rz(15.0), Rx(-5.0))
    lo, hi = bounds([local(J3, R_b3, p) for p in (J3, tip)], 10.0, 1.0)
    b3 = m.part(top, "TOOL", "103", J3, R_b3, lo, hi, cg_R=chain(Rx(33.0), Ry(-12.0), Rz(64.0)),
                mesh_path="TOOL_prt.stl", mesh_format="ascii", material=ORANGE)
    m.user_frame(b3, tip, Rtip, "126(USERADDED)", "TOOL_TIP")

    m.joint(top, rp, b1, J1, Ra, J1, mat_mul(Ra, Rz(30.0)), prims=(("revolute", a1),),
            initial=[math.radians(30.0)])
    m.joint(top, b1, b2, J2, Rc, J2f, Rc, prims=(("prismatic", a2),), initial=[25.0])
    m.joint(top, b2, b3, J3, Rd, prims=(("revolute", a3),))
    m.ground(rp, ground_p, Rg)
    extra = {"user_frames": [{"node_id": "126(USERADDED)", "display_name": "TOOL_TIP", "owner": "103"}]}
    return m, extra, None, "ROT.xml"


def case_composite_joint():
    m = Model("UJ", container="SimscapeMultibody", link="5.0",
              created_from="Pro/E Wildfire Creo 9.0 - 2022073")
    top = m.top
    rp = m.root_part(top, (0.0, 0.0, 0.0))
    base = m.part(top, "BASE", "201", (0.0, 0.0, 0.0), I3, (-50.0, 0.0, -50.0), (50.0, 180.0, 50.0),
                  mesh_path="BASE_prt.stl", mesh_format="binary", material=GREY)
    U = (0.0, 200.0, 0.0)
    cross_ = m.part(top, "CROSS", "202", U, I3, (-20.0, -20.0, -20.0), (20.0, 80.0, 60.0),
                    mesh_path="CROSS_prt.stl", mesh_format="ascii", material=BLUE)
    F = (0.0, 260.0, 40.0)
    off = (10.0, -20.0, 30.0)
    Ff = add(F, off)
    floater = m.part(top, "FLOAT", "203", Ff, Rz(25.0), (-30.0, -15.0, -10.0), (30.0, 15.0, 10.0),
                     mesh_path="meshes/FLOAT_prt.stl", mesh_format="binary", material=ORANGE)
    m.weld(top, rp, base, (0.0, 0.0, 0.0))
    m.joint(top, base, cross_, U, I3, prims=(("revolute", (0, 0, 1)), ("revolute", (0, 1, 0))))
    m.joint(top, cross_, floater, F, I3, Ff, I3,
            prims=(("prismatic", (1, 0, 0)), ("prismatic", (0, 1, 0)), ("prismatic", (0, 0, 1)),
                   ("spherical", None)),
            initial=[off[0], off[1], off[2], None])
    m.ground(rp, (0.0, 0.0, 0.0))
    return m, {}, None, "UJ.xml"


def case_lump_welds():
    m = Model("LUMP", container="SimMechanics", link="4.0",
              created_from="Pro/E Wildfire Creo 3.0 - 2014140")
    top = m.top
    rp = m.root_part(top, (0.0, 0.0, 0.0))
    # An arm in the y-z plane, revolutes about world x; gravity -z (options.json) swings it.
    J1 = (0.0, 0.0, 300.0)
    u = unit((0.0, 1.0, -0.4))
    Ra = frame_xz(u, (1.0, 0.0, 0.0))  # x along the arm, z along the joint axis
    W = add(J1, mul(140.0, u))
    J2 = add(J1, mul(260.0, u))
    lo, hi = link_box(J1, Ra, [J1, W], 12.0, 12.0, 10.0, 1.0)
    a = m.part(top, "UPPER_A", "302", J1, Ra, lo, hi, mesh_path="UPPER_A_prt.stl",
               mesh_format="ascii", material=GREY)
    Rb = mat_mul(Ra, Rx(90.0))  # a differently oriented CS1 at another origin
    cs1_b = add(W, mul(-5.0, u))
    lo, hi = link_box(cs1_b, Rb, [W, J2], 12.0, 12.0, 10.0, 1.0)
    b = m.part(top, "UPPER_B", "303", cs1_b, Rb, lo, hi, density=DENSITY_STEEL,
               mesh_path="UPPER_B_prt.stl", mesh_format="binary", material=BLUE)
    v = unit((0.0, 0.3, -1.0))
    Rc = frame_xz(v, (1.0, 0.0, 0.0))
    J3 = add(J2, mul(200.0, v))
    lo, hi = link_box(J2, Rc, [J2, J3], 10.0, 10.0, 8.0, 1.0)
    c = m.part(top, "FORE", "304", J2, Rc, lo, hi, mesh_path="FORE_prt.stl", mesh_format="ascii",
               material=ORANGE)
    m.joint(top, rp, a, J1, I3, prims=(("revolute", (1, 0, 0)),))
    m.weld(top, a, b, W, I3)
    m.joint(top, b, c, J2, I3, prims=(("revolute", (1, 0, 0)),))
    m.ground(rp, (0.0, 0.0, 0.0))
    m.weld_groups.append([a, b])
    opts = {"lump_welds": True, "package_name": "LumpedArm", "gravity": [0, 0, -9.81]}
    return m, {}, opts, "LUMP.xml"


def case_warnings():
    m = Model("WARN", container="SimMechanics", link="4.0",
              created_from="Pro/E Wildfire Creo 2.0 - 2012360")
    top = m.top
    rp = m.root_part(top, (0.0, 0.0, 0.0))
    lo, hi = (-10.0, -10.0, -5.0), (110.0, 10.0, 5.0)
    P = [(100.0 * k, 0.0, 0.0) for k in range(6)]
    gap = (0.0, 2.0, 0.0)  # joint 2: follower frame 2 mm from the base frame
    asym = m.part(top, "ASYM", "501", P[0], I3, lo, hi, mesh_path="ASYM_prt.stl", mesh_format="ascii")
    # Not symmetric: I_xy != I_yx.
    I = [list(r) for r in asym.inertia]
    I[1][0] += 2e-6
    asym.inertia_text = vec([I[i][j] for i in range(3) for j in range(3)], g6)
    tri = m.part(top, "TRI", "502", add(P[1], gap), I3, lo, hi, mesh_path="TRI_prt.stl", mesh_format="binary")
    # Principal moments violating I1 + I2 >= I3 (positive definite and symmetric otherwise).
    I = [list(r) for r in tri.inertia]
    I[0][0] *= 0.2
    tri.inertia_text = vec([I[i][j] for i in range(3) for j in range(3)], g6)
    ghost = m.part(top, "GHOST", "503", add(P[2], gap), I3, lo, hi, geometry="GHOST_prt.stl")
    bare = m.part(top, "BARE", "504", add(P[3], gap), I3, lo, hi, geometry="")
    # No material: mass == volume numerically (12.5 kg, 12.5 mm^3: 1e9 kg/m^3). A 5x5x0.5 mm pin.
    nomat = m.part(top, "NOMAT", "505", add(P[4], gap), I3, (-0.5, -2.5, -0.25), (4.5, 2.5, 0.25),
                   mesh_path="NOMAT_prt.stl", mesh_format="ascii")
    s = 12.5 / nomat.mass
    nomat.mass = 12.5
    nomat.volume = 12.5
    nomat.inertia = tuple(tuple(v * s for v in r) for r in nomat.inertia)
    m.joint(top, rp, asym, P[0], I3)
    m.joint(top, asym, tri, P[1], I3, add(P[1], gap), I3)
    m.joint(top, tri, ghost, add(P[2], gap), I3, prims=(("revolute", (0, 0, 0)),))
    m.joint(top, ghost, bare, add(P[3], gap), I3)
    m.joint(top, bare, nomat, add(P[4], gap), I3)
    m.ground(rp, (0.0, 0.0, 0.0))
    extra = {
        "expected_warnings": [
            {"check": "no-material", "node_id": "505", "why": "mass 12.5 kg == volume 12.5 mm^3 (1e9 kg/m^3)"},
            {"check": "inertia-not-symmetric", "node_id": "501", "why": "I_yx = I_xy + 2e-6 kg*m^2"},
            {"check": "inertia-triangle-inequality", "node_id": "502", "why": "I_xx scaled by 0.2"},
            {"check": "joint-frames-apart", "node_id": "501:-:502", "why": "revolute frames 2 mm apart"},
            {"check": "zero-axis", "node_id": "502:-:503", "why": "revolute axis 0,0,0"},
            {"check": "missing-geometry-file", "node_id": "503", "why": "GHOST_prt.stl is not in the bundle"},
            {"check": "no-geometry", "node_id": "504", "why": "geometryFileName is empty"},
        ],
        "deliberate": {
            "joints_apart": ["501:-:502"],
            "zero_axis": ["502:-:503"],
            "invalid_inertia": ["501", "502"],
            "implausible_density": ["505"],
            "missing_mesh": ["503"],
        },
    }
    return m, extra, None, "WARN.xml"


# -- broken inputs: a small valid model, then one flaw each -----------------------------------


# -- Closed loops: cut forms chosen by rank ------------------------------------------------------


def link(m, asm, name, node, P, Q, up=(0.0, 0.0, 1.0), density=DENSITY_AL, mat=GREY):
    """A bar from P to Q: CS1 at P with x along the bar and z as close to `up` as it can be."""
    x = unit(sub(Q, P))
    up = up if abs(dot(unit(up), x)) < 0.99 else perpendicular(x)
    z = unit(sub(up, mul(dot(up, x), x)))
    R = from_cols(x, cross(z, x), z)
    lo, hi = link_box(P, R, [P, Q], 8.0, 8.0, 4.0, 1.0)
    return m.part(asm, name, node, P, R, lo, hi, density=density, mesh_path=name + "_prt.stl", material=mat)


def circles(P, r1, Q, r2, upper=True):
    """The intersection of circle(P, r1) and circle(Q, r2) in the z = 0 plane."""
    d = sub(Q, P)
    dist = norm(d)
    a = (r1 ** 2 - r2 ** 2 + dist ** 2) / (2 * dist)
    h = math.sqrt(r1 ** 2 - a ** 2)
    ex = unit(d)
    ey = (-ex[1], ex[0], 0.0)
    c1 = add(add(P, mul(a, ex)), mul(h, ey))
    c2 = sub(add(P, mul(a, ex)), mul(h, ey))
    return c1 if (c1[1] >= c2[1]) == upper else c2


def rounded(R):
    """R with every entry printed to 6 significant digits, as the exports print them."""
    return tuple(tuple(float(g6(v)) for v in row) for row in R)


def case_slider_crank():
    m = Model("SLIDERCRANK", container="SimMechanics", link="4.0",
              created_from="Pro/E Wildfire Creo 2.0 - 2012360")
    top = m.top
    A = (0.0, 0.0, 0.0)
    B = (40.0 * math.cos(math.radians(50)), 40.0 * math.sin(math.radians(50)), 0.0)
    # C on the x axis at distance 120 from B.
    C = (B[0] + math.sqrt(120.0 ** 2 - B[1] ** 2), 0.0, 0.0)
    rp = m.root_part(top, (0.0, 0.0, 0.0))
    crank = link(m, top, "CRANK", "40", A, B, mat=BLUE)
    rod = link(m, top, "ROD", "41", B, C)
    piston = m.part(top, "PISTON", "42", C, I3, (-15.0, -10.0, -10.0), (15.0, 10.0, 10.0),
                    density=DENSITY_STEEL, mesh_path="PISTON_prt.stl", material=ORANGE)
    m.joint(top, rp, crank, A, I3, prims=(("revolute", (0, 0, 1)),))
    m.joint(top, crank, rod, B, I3, prims=(("revolute", (0, 0, 1)),))
    m.joint(top, rod, piston, C, I3, prims=(("revolute", (0, 0, 1)),))
    # The cylinder: the piston slides along world x; this joint's nodeID sorts last, so the
    # spanning tree would close the loop at the prismatic.
    j = m.joint(top, piston, rp, C, I3, fol_pos=(0.0, 0.0, 0.0), prims=(("prismatic", (1, 0, 0)),))
    j.initial = [-C[0]]
    m.ground(rp, (0.0, 0.0, 0.0))
    return m, {"expected_cut": {"cut": "revolute-planar-loop-constraint", "kind": "planar"}}, None, "SLIDERCRANK.xml"


def case_sixbar_6digit():
    m = Model("SIXBAR", container="SimMechanics", link="4.0",
              created_from="Pro/E Wildfire Creo 2.0 - 2012360")
    top = m.top
    A, D, G = (0.0, 0.0, 0.0), (200.0, 0.0, 0.0), (380.0, 40.0, 0.0)
    B = (60.0 * math.cos(math.radians(75)), 60.0 * math.sin(math.radians(75)), 0.0)
    C = circles(B, 190.0, D, 140.0)
    # E on the ternary coupler, beyond C.
    E = add(C, mul(60.0, unit(sub(C, B))))
    F = circles(E, 150.0, G, 120.0)
    rp = m.root_part(top, (0.0, 0.0, 0.0))
    crank = link(m, top, "CRANK", "50", A, B, mat=BLUE)
    coupler = link(m, top, "COUPLER", "51", B, E)
    rocker = link(m, top, "ROCKER", "52", D, C, mat=ORANGE)
    link5 = link(m, top, "LINK5", "53", E, F)
    link6 = link(m, top, "LINK6", "54", G, F, mat=ORANGE)
    # Axes printed with 6 significant digits: parallel to about 4e-6 rad, not to 1e-6.
    noise = [(0.0, 0.0), (3e-06, -1e-06), (-2e-06, 2.5e-06), (1.5e-06, 3e-06), (-3.5e-06, 0.0),
             (2e-06, -2e-06), (0.0, 4e-06)]
    axes = [tuple(float(g6(v)) for v in unit((nx, ny, 1.0))) for nx, ny in noise]
    pairs = [(rp, crank, A), (crank, coupler, B), (coupler, rocker, C), (rocker, rp, D),
             (coupler, link5, E), (link5, link6, F), (link6, rp, G)]
    for (a, b, P), axis in zip(pairs, axes):
        m.joint(top, a, b, P, I3, prims=(("revolute", axis),))
    m.ground(rp, (0.0, 0.0, 0.0))
    return m, {"expected_cut": {"cut": "revolute-planar-loop-constraint", "kind": "planar"}}, None, "SIXBAR.xml"


def case_crank_rocker_noise():
    m = Model("CRANKROCKER", container="SimscapeMultibody", link="5.0")
    top = m.top
    A, D = (0.0, 0.0, 0.0), (250.0, 30.0, 0.0)
    B = (50.0 * math.cos(math.radians(110)), 50.0 * math.sin(math.radians(110)), 0.0)
    C = circles(B, 220.0, D, 160.0)
    rp = m.root_part(top, (0.0, 0.0, 0.0))
    crank = link(m, top, "CRANK", "60", A, B, mat=BLUE)
    coupler = link(m, top, "COUPLER", "61", B, C)
    rocker = link(m, top, "ROCKER", "62", D, C, mat=ORANGE)
    # Joint frames turned with their links and printed to 6 digits (off orthonormal by ~1e-6),
    # axes with 1e-10 noise: the emitted axes must still be parallel to well below 1e-10.
    def fr(P, Q):
        return rounded(Rz(math.degrees(math.atan2(Q[1] - P[1], Q[0] - P[0]))))
    axes = [(1e-10, 0.0, 1.0), (0.0, -1e-10, 1.0), (1e-10, 1e-10, 1.0), (0.0, 0.0, -1.0)]
    ang = lambda P, Q: math.atan2(Q[1] - P[1], Q[0] - P[0])  # noqa: E731
    t1, t2, t3 = ang(A, B), ang(B, C), ang(D, C)
    m.joint(top, rp, crank, A, fr(A, B), prims=(("revolute", axes[0]),))
    m.joint(top, crank, coupler, B, fr(A, B), fol_R=fr(B, C), prims=(("revolute", axes[1]),), initial=[t2 - t1])
    m.joint(top, coupler, rocker, C, fr(B, C), fol_R=fr(D, C), prims=(("revolute", axes[2]),), initial=[t3 - t2])
    m.joint(top, rocker, rp, D, fr(D, C), fol_R=I3, prims=(("revolute", axes[3]),), initial=[t3])
    m.ground(rp, (0.0, 0.0, 0.0))
    return m, {"expected_cut": {"cut": "revolute-planar-loop-constraint", "kind": "planar"}}, None, "CRANKROCKER.xml"


def case_spatial_rssr():
    m = Model("RSSR", container="SimscapeMultibody", link="5.0")
    top = m.top
    A = (0.0, 0.0, 0.0)
    B = (50.0 * math.cos(math.radians(30)), 50.0 * math.sin(math.radians(30)), 0.0)
    D = (200.0, 0.0, 80.0)
    phi = math.radians(200)
    C = add(D, (0.0, 100.0 * math.cos(phi), 100.0 * math.sin(phi)))
    rp = m.root_part(top, (0.0, 0.0, 0.0))
    crank = link(m, top, "CRANK", "70", A, B, mat=BLUE)
    coupler = link(m, top, "COUPLER", "71", B, C, up=(0.0, 1.0, 0.0))
    rocker = link(m, top, "ROCKER", "72", D, C, up=(1.0, 0.0, 0.0), mat=ORANGE)
    m.joint(top, rp, crank, A, I3, prims=(("revolute", (0, 0, 1)),))
    m.joint(top, crank, coupler, B, I3, prims=(("spherical", None),))
    m.joint(top, coupler, rocker, C, I3, prims=(("spherical", None),))
    m.joint(top, rp, rocker, D, I3, prims=(("revolute", (1, 0, 0)),))
    m.ground(rp, (0.0, 0.0, 0.0))
    return m, {"expected_cut": {"kind": "spatial", "mobility": 2}}, None, "RSSR.xml"


def case_immobile_leg():
    m = Model("LEG", container="SimMechanics", link="4.0",
              created_from="Pro/E Wildfire Creo 2.0 - 2012360")
    top = m.top
    P = [(0.0, 0.0, 0.0), (0.0, 0.0, -100.0), (20.0, 10.0, -300.0), (30.0, 40.0, -500.0)]
    rp = m.root_part(top, (0.0, 0.0, -250.0))
    hip = link(m, top, "HIP", "80", P[0], P[1], up=(1.0, 0.0, 0.0), mat=BLUE)
    thigh = link(m, top, "THIGH", "81", P[1], P[2], up=(1.0, 0.0, 0.0))
    shank = link(m, top, "SHANK", "82", P[2], P[3], up=(1.0, 0.0, 0.0), mat=ORANGE)
    # Welded to its root at hip and ankle, like LEGS_MECHANISM's left leg: four revolutes on
    # generic axes form a loop that cannot move (rank 4 of 4), so 2 of a plain revolute's 5
    # equations are redundant.
    axes = [(0.0, 0.0, 1.0), (1.0, 0.0, 0.0), unit((0.0, 1.0, 0.2)), unit((1.0, 1.0, 1.0))]
    m.joint(top, rp, hip, P[0], I3, prims=(("revolute", axes[0]),))
    m.joint(top, hip, thigh, P[1], I3, prims=(("revolute", axes[1]),))
    m.joint(top, thigh, shank, P[2], I3, prims=(("revolute", axes[2]),))
    m.joint(top, shank, rp, P[3], I3, prims=(("revolute", axes[3]),))
    m.ground(rp, (0.0, 0.0, 0.0))
    return m, {"expected_cut": {"cut": "constraint-spherical", "kind": "spatial", "mobility": 0}}, None, "LEG.xml"


def small_model(name="BROKEN", mesh_name="ARM_prt.stl"):
    m = Model(name, container="SimscapeMultibody", link="4.8")
    top = m.top
    rp = m.root_part(top, (0.0, 0.0, 0.0))
    pivot = (0.0, 200.0, 0.0)
    arm = m.part(top, "ARM", "31", pivot, Rz(-90.0), (-10.0, -10.0, -5.0), (160.0, 10.0, 5.0),
                 geometry=mesh_name, mesh_path=mesh_name, mesh_format="ascii")
    j = m.joint(top, rp, arm, pivot, I3)
    m.ground(rp, (0.0, 0.0, 0.0))
    return m, arm, j


def case_broken_dangling_ref():
    m, arm, j = small_model()
    j.follower_ref_text = "9999"
    return m, {"error_contains": "9999", "flaw": 'joint follower <Frame ref="9999"> names no frame'}, None, "BROKEN.xml"


def case_broken_unknown_unit():
    m, arm, j = small_model()
    m.finish()
    arm.frames[0].over["positionUnits"] = "furlong"
    return m, {"error_contains": "furlong", "flaw": 'CG frame of ARM has positionUnits "furlong"'}, None, "BROKEN.xml"


def case_broken_nan():
    m, arm, j = small_model()
    m.finish()
    f = arm.frames[0]
    f.over["position"] = "%s,nan,%s" % (num(f.pos[0]), num(f.pos[2]))
    return m, {"error_contains": "nan", "flaw": "CG frame of ARM has position x,nan,z"}, None, "BROKEN.xml"


def truncate(text):
    """Cut the XML in the middle of the ARM body's CG <position> element."""
    i = text.index('<nodeID>"31::CG(AUTOGEN)"</nodeID>')
    i = text.index("<position>", i) + len("<position>") + 3
    return text[:i]


def case_broken_truncated():
    m, arm, j = small_model()
    return m, {"error_contains": "truncated", "flaw": "file ends inside <position> of ARM's CG frame",
               "truncate": True}, None, "BROKEN.xml"


def case_broken_two_xml():
    m, arm, j = small_model("FIRST")
    m2, _, _ = small_model("SECOND")
    return m, {"error_contains": "two model sources in one bundle", "flaw": "FIRST.xml and SECOND.xml are both exports",
               "second": (m2, "SECOND.xml")}, None, "FIRST.xml"


def case_broken_ambiguous_mesh():
    m, arm, j = small_model(mesh_name="part.stl")
    data = m.meshes.pop("part.stl")
    m.meshes["a/PART.stl"] = data
    m.meshes["b/part.STL"] = data
    return m, {"error_contains": "more than one file",
               "flaw": '"part.stl" matches a/PART.stl and b/part.STL'}, None, "BROKEN.xml"


def case_broken_mass_overflow():
    m, arm, j = small_model()
    arm.mass_text = "1.7e308"
    arm.mass_units = "slug"
    return m, {"error_contains": "not a finite number",
               "flaw": "ARM's mass is 1.7e308 slug, which overflows to infinity in kg"}, None, "BROKEN.xml"


def case_broken_far_frame():
    m, arm, j = small_model()
    m.finish()
    arm.frames[1].over["position"] = "0,2000000000,0"
    return m, {"error_contains": "beyond any real machine",
               "flaw": "ARM's CS1 frame is 2e9 mm (2000 km) from the origin"}, None, "BROKEN.xml"


def case_broken_nan_stl():
    m, arm, j = small_model(mesh_name="ARM_prt.stl")
    data = bytearray(box_stl("ARM", (-10.0, -10.0, -5.0), (160.0, 10.0, 5.0), "binary"))
    # The first triangle's second vertex x becomes NaN (offset: header 80 + count 4 + normal 12).
    data[96:100] = struct.pack("<f", float("nan"))
    m.meshes["ARM_prt.stl"] = bytes(data)
    return m, {"error_contains": "not finite",
               "flaw": "ARM_prt.stl (binary) has a NaN vertex coordinate"}, None, "BROKEN.xml"


def case_frames_relative():
    """Frames written relative to other frames (see README_TEXT)."""
    m = Model("RELFRAMES", container="SimscapeMultibody", link="5.0",
              created_from="Pro/E Wildfire Creo 9.0 - 2022073")
    top = m.top
    rp = m.root_part(top, (0.0, 0.0, 0.0))
    # Joint 1: revolute about world z at J1, frames rotated Rz(15) (WORLD axis).
    J1 = (40.0, -20.0, 120.0)
    R1 = chain(Rz(37.0), Rx(25.0), Ry(-10.0))
    J2 = add(J1, mat_vec(R1, (180.0, 0.0, 0.0)))
    lo, hi = link_box(J1, R1, [J1, J2], 15.0, 15.0, 10.0, 1.0)
    crank = m.part(top, "CRANK", "601", add(J1, mat_vec(R1, (-5.0, 3.0, 0.0))), R1, lo, hi,
                   cg_R=chain(R1, Rz(-20.0)), mesh_path="CRANK_prt.stl", mesh_format="ascii",
                   material=GREY)
    # Joint 2: revolute about the z axis of its base frame (axis written in BASE), follower
    # turned 25 degrees about it (initial angle) and written ADJOINING.
    Rb = chain(Ry(30.0), Rx(-50.0), Rz(12.0))
    a2 = col(Rb, 2)
    R2 = chain(rot(a2, 70.0), R1)
    J3 = add(J2, mat_vec(R2, (150.0, 0.0, 0.0)))
    lo, hi = link_box(J2, R2, [J2, J3], 12.0, 12.0, 10.0, 1.0)
    rod = m.part(top, "ROD", "602", J2, R2, lo, hi, density=DENSITY_STEEL,
                 cg_R=chain(R2, Rx(40.0), Ry(15.0)), mesh_path="ROD_prt.stl", mesh_format="binary",
                 material=BLUE)
    # Joint 3: prismatic along a generic world axis, follower 15 mm along it.
    a3 = unit((0.2, 0.7, -0.4))
    Rp = frame_xz(perpendicular(a3), a3)
    J3f = add(J3, mul(15.0, a3))
    R3 = chain(Rz(-40.0), Ry(20.0))
    lo, hi = bounds([local(J3f, R3, p) for p in (J3f, add(J3f, mul(60.0, a3)))], 10.0, 1.0)
    slider = m.part(top, "SLIDER", "603", J3f, R3, lo, hi, mesh_path="SLIDER_prt.stl",
                    mesh_format="ascii", material=ORANGE)
    m.joint(top, rp, crank, J1, Rz(15.0), prims=(("revolute", (0, 0, 1)),))
    j2 = m.joint(top, crank, rod, J2, Rb, J2, mat_mul(rot(a2, 25.0), Rb),
                 prims=(("revolute", a2),), initial=[math.radians(25.0)])
    m.joint(top, rod, slider, J3, Rp, J3f, Rp, prims=(("prismatic", a3),), initial=[15.0])
    m.ground(rp, (0.0, 0.0, 0.0))
    m.finish()
    cg, cs1, cs2 = crank.frames[0], crank.frames[1], crank.frames[2]
    assert (cg.name, cs1.name, cs2.name) == ("CG", "CS1", "CS2")
    cs1.rel = (cs2, cs2, cs2)  # CG -> CS1 -> CS2 -> WORLD
    cg.rel = (cs1, cs1, cs1)
    rod_cg, rod_cs1, rod_cs2, rod_cs3 = rod.frames
    rod_cs2.rel = (j2.base, j2.base, j2.base)  # the follower of joint 2: ADJOINING
    rod_cs3.rel = (rod_cs1, rod_cg, rod_cs2)  # origin, axes and orientation: three frames
    j2.axis_frames = ["BASE"]
    return m, {}, None, "RELFRAMES.xml"


def case_broken_frame_cycle():
    m, arm, j = small_model()
    m.finish()
    arm.frames[0].over["positionOrigin"] = "CS1"
    arm.frames[1].over["orientationReferenceFrame"] = "CG"
    return m, {"error_contains": "frame references form a cycle: CG -> CS1 -> CG",
               "flaw": 'CG frame of ARM has positionOrigin "CS1", whose orientationReferenceFrame is "CG"'}, \
        None, "BROKEN.xml"


def case_broken_frame_missing():
    m, arm, j = small_model()
    m.finish()
    arm.frames[0].over["positionReferenceFrame"] = "CS9"
    return m, {"error_contains": 'refers to frame "CS9", which its body does not have',
               "flaw": 'CG frame of ARM has positionReferenceFrame "CS9"; ARM has no CS9'}, None, "BROKEN.xml"


def case_broken_unsupported_ref():
    m, arm, j = small_model()
    m.finish()
    arm.frames[0].over["positionReferenceFrame"] = "BASE"
    return m, {"error_contains": 'reference frame "BASE" is not supported',
               "flaw": 'CG frame of ARM has positionReferenceFrame "BASE" (allowed only for a primitive axis)'}, \
        None, "BROKEN.xml"


CASES = [
    ("pendulum", case_pendulum),
    ("fourbar", case_fourbar),
    ("arm_subsystems", case_arm_subsystems),
    ("inch_lbm", case_inch_lbm),
    ("rotated_frames", case_rotated_frames),
    ("composite_joint", case_composite_joint),
    ("lump_welds", case_lump_welds),
    ("warnings", case_warnings),
    ("slider_crank", case_slider_crank),
    ("sixbar_6digit", case_sixbar_6digit),
    ("crank_rocker_noise", case_crank_rocker_noise),
    ("spatial_rssr", case_spatial_rssr),
    ("immobile_leg", case_immobile_leg),
    ("frames_relative", case_frames_relative),
    ("broken_dangling_ref", case_broken_dangling_ref),
    ("broken_unknown_unit", case_broken_unknown_unit),
    ("broken_truncated", case_broken_truncated),
    ("broken_unsupported_ref", case_broken_unsupported_ref),
    ("broken_nan", case_broken_nan),
    ("broken_two_xml", case_broken_two_xml),
    ("broken_ambiguous_mesh", case_broken_ambiguous_mesh),
    ("broken_mass_overflow", case_broken_mass_overflow),
    ("broken_far_frame", case_broken_far_frame),
    ("broken_nan_stl", case_broken_nan_stl),
    ("broken_frame_cycle", case_broken_frame_cycle),
    ("broken_frame_missing", case_broken_frame_missing),
]

README_TEXT = {
    "pendulum": "One aluminium link (`LINK`, nodeID 23) hanging from `PENDULUM/RootPart` by a revolute about world z, in mm/kg under a `<SimscapeMultibody>` container (Simscape Multibody Link 4.8). The ground frame sits at (0, 500, 0) mm, not at the world origin, and the pivot at (0, 450, 0) mm, so the RootGround weld needs a fixed translation. The link's CS1 is rotated -60 deg about z (it hangs 30 deg off the vertical) and its CG lies 150 mm along the link. The XML names `LINK_PRT.STL` while the ASCII mesh is `meshes/LINK_prt.stl`: lookup must be case-insensitive and search sub-folders. The link carries a `MaterialProp`.",
    "fourbar": "A real planar four-bar in mm/kg under a `<SimMechanics>` container (Link 4.0): `FOURBAR/RootPart` is the fixed link with the two ground pivots A and D, plus `CRANK`, `COUPLER` and `ROCKER` (steel). Four revolutes about world z form one closed loop with no cut marked; three axes are `0,0,1` and the RootPart--ROCKER one is `0,0,-1`, so a planar-loop test must accept antiparallel axes. Joint frames are world-aligned and coincide at each pivot (C is the computed intersection of the coupler and rocker circles). Binary STLs; the crank's 80-byte header starts with `solid` (binary detection must go by size).",
    "arm_subsystems": "Top assembly `ARM` (mm/kg, `<SimMechanics>`, Link 4.0) with `ARM/RootPart`, a `BASE` part and the subsystem `UPPER` (nodeID `12`), which nests `FORE` (nodeID `12/20`). Each subsystem has its own zero-mass RootPart (`12/RootPart`, `12/20/RootPart`) welded at the CG of its subsystem's part, as iCub exports do, and a part named `LINK` (`12/13` and `12/20/21`): duplicate body names, and the joint between them is called `LINK--LINK`. The top-level revolute `BASE--LINK` (nodeID `12:12/13:-:7`) has its follower frame on a body inside `UPPER`, and `UPPER`'s revolute `LINK--LINK` points into `FORE`: frame refs are unique across the file and must be resolved globally. Axes are normalised (1,1,0) and (1,-1,1), with joint frames whose z axis is the joint axis; the elbow's follower frame is turned -20 deg about its axis (initial angle). Meshes in `meshes/upper/` (ASCII) and `meshes/fore/`, `meshes/` (binary).",
    "inch_lbm": "The pendulum chain plus one more link, in imperial units: `in`, `lbm`, `lbm*in^2`, `in^3`, `in^2`, a `<SimMechanics>` container with the SimMechanics Link 3.1 header (Pro/E Wildfire 4.0), which writes no `displayName` elements and calls the top RootPart just `RootPart`. Ground frame at (0, 20, 0) in, pivots at (2, 18, 0) in and 12 in further down the first link; both revolutes about world z. Aluminium densities expressed in lbm/in^3. `LINK1.stl` is ASCII and `LINK2.stl` binary with an all-zero header, both in inches.",
    "rotated_frames": "Three bodies (`BRACKET`, `SLIDER`, `TOOL`) whose CS1, CG and joint frames all carry composite rotations such as Rz(37) Ry(-20) Rx(65); each CG frame is rotated away from CS1, so the inertia (a box's, distinct principal moments) arrives as a full tensor in rotated axes and must be rotated into the body frame. The ground frame is rotated Rx(-90) and off the origin. RootPart--BRACKET is a revolute about the z axis of its base frame with the follower frame turned 30 deg about that axis (initial angle 30 deg); BRACKET--SLIDER is a prismatic along a generic world axis with the follower frame 25 mm along it and the same orientation (initial displacement 25 mm); SLIDER--TOOL is a revolute about a generic world axis not aligned with any frame axis. `TOOL` has a user-added frame, nodeID `126(USERADDED)`, displayName `TOOL_TIP`, no ref. Simscape Multibody Link 5.0.",
    "composite_joint": "Joints with several primitives. `BASE--CROSS` is a universal joint: two revolute primitives, world z then world y, with coincident frames. `CROSS--FLOAT` is a 6-DoF free joint written the way ergoCub exports do it: prismatic x, y, z then a spherical (dummy axis), with the follower frame (10, -20, 30) mm from the base frame and the same orientation, so the initial prismatic values are 10, -20 and 30 mm. `BASE` is welded to `UJ/RootPart`. Mixed ASCII and binary meshes, one in a sub-folder.",
    "lump_welds": "An arm `UPPER_A` -weld- `UPPER_B` between two revolutes about world x (RootPart--UPPER_A and UPPER_B--FORE). The weld frames coincide but the two parts' CS1 frames differ in origin and orientation (UPPER_B's is turned 90 deg about its x axis), and the parts differ in material (aluminium, steel), so lumping must combine mass, CG and inertia with the parallel-axis theorem. `options.json` asks for `lump_welds`, the package name `LumpedArm` and gravity (0, 0, -9.81). `expect.json` has the lumped body's mass, CG and inertia (about the combined CG, world axes) under `lumped`.",
    "warnings": "Converts, but trips every check once, each on its own body or joint (listed in `expect.json` under `expected_warnings`): `NOMAT` has mass 12.5 kg and volume 12.5 mm^3 (mass == volume numerically, density 1e9 kg/m^3); `ASYM`'s inertia is not symmetric; `TRI`'s principal moments violate the triangle inequality; the revolute `ASYM--TRI` has its base and follower frames 2 mm apart; the revolute `TRI--GHOST` has axis `0,0,0`; `GHOST` names `GHOST_prt.stl`, which is not in the bundle; `BARE` has no geometry (`geometryFileName \"\"`).",
    "slider_crank": "A planar slider-crank (engine cylinder, the case MSL's `PlanarLoops` tutorial names): crank, connecting rod and piston joined by three revolutes about world z, the piston sliding along world x in the plane of motion. The prismatic joint's nodeID sorts last, so a spanning tree by node ID closes the loop at the prismatic; the loop is planar (rank 3), so a plain closing joint would repeat 3 of its equations: the cut must move to a revolute and become `RevolutePlanarLoopConstraint`.",
    "sixbar_6digit": "A planar Watt six-bar (two independent loops sharing the ternary coupler) whose seven revolute axes are written with 6 significant digits, parallel only to about 4e-6 rad: still planar at the data's precision, so both loops take `RevolutePlanarLoopConstraint` and every emitted axis is the loops' common normal.",
    "crank_rocker_noise": "A crank-rocker four-bar whose joint frames turn with their links and are printed to 6 significant digits (orthonormal only to ~1e-6), with 1e-10 noise in the axes and one axis antiparallel: the emitted revolute axes must be parallel to well within MSL's 1e-10.",
    "spatial_rssr": "A spatial RSSR four-bar: crank revolute about world z, coupler with a spherical joint at each end, rocker revolute about world x on a pivot off the crank's plane. Genuinely spatial and mobile: 8 coordinates, rank 6, mobility 2 (the output and the coupler's spin about its own line); no equation of the closing joint is redundant.",
    "immobile_leg": "A leg welded to its root at hip and ankle, like the real `LEGS_MECHANISM.xml`: four revolutes on generic axes form a loop that cannot move (rank 4 of 4 coordinates, mobility 0). A plain closing revolute would impose 5 equations of which 3 are independent; the cut is `Joints.Constraints.Spherical`.",
    "frames_relative": "Frames written relative to other frames, in mm/kg (Simscape Multibody Link 5.0): `RELFRAMES/RootPart` -revolute (world z)- `CRANK` -revolute- `ROD` (steel) -prismatic (generic world axis, follower 15 mm along it)- `SLIDER`. `CRANK`'s CG is given relative to its CS1 and CS1 relative to the joint frame CS2 (origin, axes and orientation; CS2 itself in WORLD): the chain CG -> CS1 -> CS2 -> WORLD. The revolute `CRANK--ROD` has its axis written in the axes of its base frame (`referenceFrame \"BASE\"`, `0,0,1` up to rounding) and its follower frame (`ROD`'s CS2, turned 25 deg about the axis: initial angle) written `ADJOINING` (relative to the base frame on `CRANK`). `ROD`'s CS3 (the prismatic's base frame) has `positionOrigin` CS1, `positionReferenceFrame` CG and `orientationReferenceFrame` CS2 (itself ADJOINING). Everything else is in WORLD. The relative numbers are computed from the exact world poses, so `expect.json` (world poses; `given_relative_to` lists each relative frame's three references) is reproduced to ~1e-15.",
    "broken_dangling_ref": "The revolute's follower `<Frame ref=\"9999\">` names a ref that no frame has. Conversion must fail and say which ref.",
    "broken_unknown_unit": "A frame with `positionUnits \"furlong\"`. Conversion must fail naming the unknown unit.",
    "broken_truncated": "The XML is cut off in the middle of a `<position>` element (no closing tags). Conversion must fail; the message is expected to say the file is truncated.",
    "broken_unsupported_ref": "The CG frame of `ARM` has `positionReferenceFrame \"BASE\"`: `BASE` and `FOLLOWER` name a joint frame only in a primitive's `referenceFrame`; a frame's references are `WORLD`, `ADJOINING` or a frame of the same body. An explicit unsupported error, not a silent misreading.",
    "broken_nan": "The CG frame of `ARM` has position `x,nan,z`. Non-finite numbers must be rejected.",
    "broken_two_xml": "Two valid PhysicalModelingXMLFile exports (`FIRST.xml`, `SECOND.xml`) in one bundle: the converter must refuse to guess.",
    "broken_mass_overflow": "`ARM` has mass `1.7e308` in `slug`: finite as written, infinite in kg. Conversion must fail naming the body, not write `m=inf`.",
    "broken_far_frame": "`ARM`'s CS1 frame lies 2e9 mm (2,000 km) from the origin: beyond any real machine (a unit error or a corrupt export). Conversion must fail naming the frame.",
    "broken_nan_stl": "`ARM_prt.stl` is a binary STL whose first triangle has a NaN coordinate. Conversion must fail naming the mesh, not write NaN into the DXF and STL.",
    "broken_ambiguous_mesh": "The XML names `part.stl`; the bundle holds `a/PART.stl` and `b/part.STL`, both matches of the case-insensitive sub-folder lookup. Conversion must fail naming the ambiguity rather than pick one.",
    "broken_frame_cycle": "`ARM`'s CG has `positionOrigin \"CS1\"` and CS1 has `orientationReferenceFrame \"CG\"`: a reference cycle. Conversion must fail naming the frames of the cycle.",
    "broken_frame_missing": "`ARM`'s CG has `positionReferenceFrame \"CS9\"`, a frame `ARM` does not have. Conversion must fail naming the missing frame.",
}


def lumped_facts(m, group):
    u = m.u
    L = u["L"]
    parts = []
    for b in group:
        mass = float(g6(b.mass)) * u["M"]
        cg = b.frames[0]
        c = tuple(v * L for v in parse_vec(vec(cg.pos)))
        R = cg.R
        I = tuple(tuple(float(g6(b.inertia[i][j])) * u["J"] for j in range(3)) for i in range(3))
        Iw = mat_mul(mat_mul(R, I), transpose(R))
        parts.append((mass, c, Iw))
    M = sum(p[0] for p in parts)
    C = mul(1.0 / M, tuple(sum(p[0] * p[1][i] for p in parts) for i in range(3)))
    Itot = [[0.0] * 3 for _ in range(3)]
    for mass, c, Iw in parts:
        d = sub(c, C)
        dd = dot(d, d)
        for i in range(3):
            for j in range(3):
                Itot[i][j] += Iw[i][j] + mass * ((dd if i == j else 0.0) - d[i] * d[j])
    return {
        "bodies": [b.node_id for b in group],
        "mass_kg": M,
        "cg_world_m": list(C),
        "inertia_world_kgm2": Itot,
    }


def write_case(out_root, name, fn):
    d = out_root / name
    if d.exists():
        shutil.rmtree(d)
    d.mkdir(parents=True)
    m, extra, opts, xml_name = fn()
    text = m.xml()
    facts = m.expect(xml_name)
    second = extra.pop("second", None)
    if extra.pop("truncate", False):
        text = truncate(text)
    if "error_contains" in extra:
        facts = {k: facts[k] for k in ("xml", "bodies", "joints", "loops")}
        facts["note"] = "counts describe the model before it was broken"
    if m.weld_groups:
        facts["lumped"] = [lumped_facts(m, g) for g in m.weld_groups]
    facts.update(extra)
    facts = {"case": name, **facts}
    (d / xml_name).write_text(text, encoding="utf-8", newline="\n")
    if second is not None:
        m2, name2 = second
        (d / name2).write_text(m2.xml(), encoding="utf-8", newline="\n")
    for path, data in sorted(m.meshes.items()):
        p = d / path
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_bytes(data)
    (d / "expect.json").write_text(json.dumps(facts, indent=1) + "\n", encoding="utf-8", newline="\n")
    if opts is not None:
        (d / "options.json").write_text(json.dumps(opts) + "\n", encoding="utf-8", newline="\n")
    return facts


def main(argv):
    out_root = Path(argv[1]) if len(argv) > 1 else Path(__file__).resolve().parent.parent / "in"
    out_root.mkdir(parents=True, exist_ok=True)
    summary = []
    for name, fn in CASES:
        f = write_case(out_root, name, fn)
        summary.append((name, f))
    lines = [
        "# tests/in: synthetic SimMechanics bundles",
        "",
        "Generated by `tests/tools/make_fixtures.py` (Python 3, standard library, deterministic) and",
        "checked by `tests/tools/check_fixtures.py`; edit the generator, not these files. Every",
        "directory is one input bundle: one first-generation SimMechanics `PhysicalModelingXMLFile`",
        "export plus the STL meshes it names (in the XML's length unit, in the body's CS1 frame, 12",
        "triangles each), `expect.json` with facts computed by the generator (counts; every frame's",
        "world pose in metres with its x, y and z axes; each body's CG in metres and mass in kg; each",
        "joint's primitives with their initial values; `error_contains` for the broken cases) and",
        "sometimes `options.json`. Counts: `bodies` includes every RootPart, `joints` every",
        "SimpleJoint including the RootGround weld, `loops` is the number of independent cycles of",
        "the graph of bodies and grounds. All poses are built with exact rotation matrices and",
        "printed with 17 significant digits, so joint frames coincide (or differ by exactly the",
        "declared initial joint value) to rounding. Masses and inertias are those of the box each",
        "mesh shows, at the density of aluminium (2700 kg/m^3) or steel (7850 kg/m^3), unless a case",
        "says otherwise. For the broken cases, `error_contains` is a substring the conversion error",
        "must contain, and the counts describe the model before it was broken.",
        "",
    ]
    for name, f in summary:
        head = "## `%s`" % name
        if "error_contains" in f:
            stat = "error containing `%s`" % f["error_contains"]
        else:
            stat = "%d bodies, %d joints, %d %s" % (f["bodies"], f["joints"], f["loops"],
                                                   "loop" if f["loops"] == 1 else "loops")
        lines.append("%s (%s)" % (head, stat))
        lines.append("")
        lines.append(README_TEXT[name])
        lines.append("")
    (out_root / "README.md").write_text("\n".join(lines), encoding="utf-8", newline="\n")
    for name, f in summary:
        if "error_contains" in f:
            print("%-22s error: %s" % (name, f["error_contains"]))
        else:
            print("%-22s bodies %d, joints %d, loops %d" % (name, f["bodies"], f["joints"], f["loops"]))


if __name__ == "__main__":
    main(sys.argv)
