#!/usr/bin/env python3
"""Passive motion of a closed-loop mechanism by Lagrange multipliers in Pinocchio, for the
cad2mo cross-check of loops (tests/simulation.rs).

Usage: loop_check.py IN.json OUT.json
IN: {"urdf": "<URDF text with Drake <loop_joint>s>", "gravity": [x, y, z],
     "fixed": {joint: u} (the independent joints at the start, at rest), "guess": {joint: u}
     (a guess of the others; assembled here), "times": [s],
     "rtol": r, "atol": a,
     "states": [{"u": {joint: u}, "v": {joint: speed}}] (optional: states of another simulation)}
OUT: {"pinocchio": version, "cut": [loop joint names], "u": [{tree joint: u}] per time,
      "loop_q": [{loop joint: q}] per time, "closure": largest residual (m or rad) at the times,
      "closure0": the residual of the start, "nfev": right-hand side evaluations,
      "qdd": [{tree joint: constrained acceleration}] per state,
      "energy_drift": the largest change of kinetic plus potential energy at the times (J)}

The tree is the URDF's (root link fixed, joint damping and friction ignored), read by
Pinocchio. Each <loop_joint> (type revolute/continuous or prismatic, link1/link2 frames,
axis in the link1 frame; follower = base * motion(axis, q)) adds constraints e(q) = 0:
  revolute:  p2 - p1 = 0 (3), b1 . a2 = 0 and c1 . a2 = 0 with a = axis, b, c normal to it;
  prismatic: R1 = R2 (3, as w2 - w1 = 0), b1 . (p2 - p1) = 0 and c1 . (p2 - p1) = 0
             (not exercised yet: the four-bar's and the slider-crank's URDFs cut a revolute).
Their Jacobians from Pinocchio's frame Jacobians, their bias J'v exactly from its classical
frame accelerations at zero joint acceleration. The accelerations solve
  M qdd + h = J^T lambda,  J qdd = -J'v - 2 w e' - w^2 e    (Baumgarte, w = 10 rad/s)
as qdd = a + M^-1 J^T (J M^-1 J^T)^+ (gamma - J a), a = M^-1 (-h) (aba): the pseudo-inverse
takes the redundant rows a planar loop has (a plane's point coincidence is 2 conditions of 3).
Integrated by scipy's solve_ivp (DOP853) at the given tolerances on (joint angles, speeds),
continuous joints as unbounded angles. Exit code 3 when numpy/scipy/pinocchio do not import.
"""
import json
import sys
import xml.etree.ElementTree as ET

try:
    import numpy as np
    from scipy.integrate import solve_ivp
except ImportError as e:  # pragma: no cover
    print(f"NOTICE: numpy/scipy not importable: {e}")
    sys.exit(3)
try:
    import pinocchio as pin
except ImportError as e:  # pragma: no cover
    print(f"NOTICE: pinocchio not importable: {e}")
    sys.exit(3)

LWA = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
BAUMGARTE = 10.0


def placement(node):
    xyz = [float(x) for x in node.get("xyz", "0 0 0").split()]
    r, p, y = [float(x) for x in node.get("rpy", "0 0 0").split()]
    return pin.SE3(pin.rpy.rpyToMatrix(r, p, y), np.array(xyz))


def normals(a):
    """Two unit vectors normal to unit `a` and to each other."""
    t = np.array([1.0, 0.0, 0.0]) if abs(a[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    b = np.cross(a, t)
    b /= np.linalg.norm(b)
    return b, np.cross(a, b)


class Loops:
    def __init__(self, text, gravity):
        root = ET.fromstring(text)
        loops = []
        for parent in list(root.iter()):
            for child in list(parent):
                tag = child.tag.split("}")[-1]
                if tag == "loop_joint":
                    loops.append(child)
                if tag in ("visual", "collision", "gazebo", "transmission", "loop_joint") or "}" in child.tag:
                    parent.remove(child)
        self.model = pin.buildModelFromXML(ET.tostring(root, encoding="unicode"))
        self.model.gravity.linear[:] = gravity
        self.cuts = []
        for lj in loops:
            kind = lj.get("type")
            if kind not in ("revolute", "continuous", "prismatic"):
                raise SystemExit(f"loop joint {lj.get('name')}: type {kind} not handled")
            axis_node = lj.find("axis")
            a = np.array([float(x) for x in (axis_node.get("xyz") if axis_node is not None else "1 0 0").split()])
            a /= np.linalg.norm(a)
            ids = []
            for side in ("link1", "link2"):
                node = lj.find(side)
                body = self.model.frames[self.model.getFrameId(node.get("link"), pin.FrameType.BODY)]
                frame = pin.Frame(f"{lj.get('name')}_{side}", body.parentJoint, body.placement * placement(node), pin.FrameType.OP_FRAME)
                ids.append(self.model.addFrame(frame, False))
            self.cuts.append({"name": lj.get("name"), "prismatic": kind == "prismatic", "axis": a, "normals": normals(a), "frames": ids})
        self.data = self.model.createData()
        m = self.model
        self.names = [m.names[j] for j in range(1, m.njoints) if m.joints[j].nv == 1]
        if len(self.names) != m.njoints - 1:
            raise SystemExit("only 1-DoF tree joints are handled")
        self.continuous = [m.joints[m.getJointId(n)].nq == 2 for n in self.names]

    def config(self, theta):
        q = np.zeros(self.model.nq)
        for k, n in enumerate(self.names):
            j = self.model.joints[self.model.getJointId(n)]
            if self.continuous[k]:
                q[j.idx_q], q[j.idx_q + 1] = np.cos(theta[k]), np.sin(theta[k])
            else:
                q[j.idx_q] = theta[k]
        return q

    def constraints(self, q, v):
        """Residual e, Jacobian J and bias J'v of every loop's constraints at (q, v)."""
        m, d = self.model, self.data
        nv = m.nv
        pin.forwardKinematics(m, d, q, v, np.zeros(nv))
        pin.computeJointJacobians(m, d, q)
        pin.updateFramePlacements(m, d)
        es, js, bs = [], [], []
        for c in self.cuts:
            f1, f2 = c["frames"]
            X1, X2 = d.oMf[f1], d.oMf[f2]
            J1, J2 = pin.getFrameJacobian(m, d, f1, LWA), pin.getFrameJacobian(m, d, f2, LWA)
            A1, A2 = pin.getFrameClassicalAcceleration(m, d, f1, LWA), pin.getFrameClassicalAcceleration(m, d, f2, LWA)
            V1, V2 = pin.getFrameVelocity(m, d, f1, LWA), pin.getFrameVelocity(m, d, f2, LWA)
            w1, w2 = V1.angular, V2.angular
            dp, dv = X2.translation - X1.translation, V2.linear - V1.linear
            if not c["prismatic"]:
                es.append(dp)
                js.append(J2[:3] - J1[:3])
                bs.append(A2.linear - A1.linear)
                a2 = X2.rotation @ c["axis"]
                for n in c["normals"]:
                    b1 = X1.rotation @ n
                    g = np.cross(a2, b1)
                    es.append([b1 @ a2])
                    js.append((g @ (J2[3:] - J1[3:]))[None, :])
                    dg = np.cross(np.cross(w2, a2), b1) + np.cross(a2, np.cross(w1, b1))
                    bs.append([g @ (A2.angular - A1.angular) + (w2 - w1) @ dg])
            else:
                R = X1.rotation.T @ X2.rotation
                es.append(X1.rotation @ pin.log3(R))
                js.append(J2[3:] - J1[3:])
                bs.append(A2.angular - A1.angular)
                for n in c["normals"]:
                    b1 = X1.rotation @ n
                    es.append([b1 @ dp])
                    bd = np.cross(b1, dp)
                    js.append((b1 @ (J2[:3] - J1[:3]) + bd @ J1[3:])[None, :])
                    wb = np.cross(w1, b1)
                    bs.append([b1 @ (A2.linear - A1.linear) + 2 * wb @ dv + np.cross(w1, wb) @ dp + bd @ A1.angular])
        return np.concatenate([np.atleast_1d(e) for e in es]), np.vstack(js), np.concatenate([np.atleast_1d(b) for b in bs])

    def loop_q(self, q):
        """Each loop joint's own coordinate: the follower frame's motion from the base frame."""
        m, d = self.model, self.data
        pin.framesForwardKinematics(m, d, q)
        out = {}
        for c in self.cuts:
            rel = d.oMf[c["frames"][0]].actInv(d.oMf[c["frames"][1]])
            if c["prismatic"]:
                out[c["name"]] = float(rel.translation @ c["axis"])
            else:
                b, n = c["normals"]
                out[c["name"]] = float(np.arctan2(n @ rel.rotation @ b, b @ rel.rotation @ b))
        return out

    def rhs(self, _t, y):
        nv = self.model.nv
        theta, v = y[:nv], y[nv:]
        q = self.config(theta)
        m, d = self.model, self.data
        a = pin.aba(m, d, q, v, np.zeros(nv))
        M = pin.crba(m, d, q)
        M = np.triu(M) + np.triu(M, 1).T
        e, J, bias = self.constraints(q, v)
        gamma = -bias - 2 * BAUMGARTE * (J @ v) - BAUMGARTE**2 * e
        MiJt = np.linalg.solve(M, J.T)
        lam = np.linalg.pinv(J @ MiJt, rcond=1e-10, hermitian=True) @ (gamma - J @ a)
        return np.concatenate([v, a + MiJt @ lam])


def main():
    spec = json.load(open(sys.argv[1]))
    p = Loops(spec["urdf"], spec["gravity"])
    nv = p.model.nv
    # Assembly: the fixed (independent) joints at their values, the others by Gauss-Newton on
    # the loops' constraints from the guess (the CAD pose where none is given).
    theta0 = np.array([spec["fixed"].get(n, spec["guess"].get(n, 0.0)) for n in p.names])
    free = [k for k, n in enumerate(p.names) if n not in spec["fixed"]]
    for _ in range(50):
        e, J, _ = p.constraints(p.config(theta0), np.zeros(nv))
        if np.abs(e).max() < 1e-14:
            break
        theta0[free] -= np.linalg.lstsq(J[:, free], e, rcond=1e-10)[0]
    e0, _, _ = p.constraints(p.config(theta0), np.zeros(nv))
    times = spec["times"]
    sol = solve_ivp(p.rhs, (times[0], times[-1]), np.concatenate([theta0, np.zeros(nv)]), method="DOP853",
                    t_eval=times, rtol=spec["rtol"], atol=spec["atol"])
    if not sol.success:
        raise SystemExit(f"solve_ivp: {sol.message}")
    us, loop_qs, closure, energy = [], [], 0.0, []
    for s in range(len(times)):
        theta, v = sol.y[:nv, s], sol.y[nv:, s]
        q = p.config(theta)
        us.append({n: float(theta[k]) for k, n in enumerate(p.names)})
        loop_qs.append(p.loop_q(q))
        e, _, _ = p.constraints(q, v)
        closure = max(closure, float(np.abs(e).max()))
        energy.append(pin.computeKineticEnergy(p.model, p.data, q, v) + pin.computePotentialEnergy(p.model, p.data, q))
    # Accelerations at given states: the joints given fixed, the others completed (positions by
    # Gauss-Newton from this run's own sample, speeds from J v = 0).
    qdds = []
    for k, st in enumerate(spec.get("states", [])):
        theta = np.array([st["u"].get(n, us[min(k, len(us) - 1)][n]) for n in p.names])
        v = np.array([st["v"].get(n, 0.0) for n in p.names])
        free = [i for i, n in enumerate(p.names) if n not in st["u"]]
        fixed = [i for i in range(nv) if i not in free]
        for _ in range(50):
            e, J, _ = p.constraints(p.config(theta), np.zeros(nv))
            if np.abs(e).max() < 1e-14 or not free:
                break
            theta[free] -= np.linalg.lstsq(J[:, free], e, rcond=1e-10)[0]
        if free:
            v[free] = np.linalg.lstsq(J[:, free], -J[:, fixed] @ v[fixed], rcond=1e-10)[0]
        qdd = p.rhs(0.0, np.concatenate([theta, v]))[nv:]
        qdds.append({n: float(qdd[i]) for i, n in enumerate(p.names)})
    out = {"pinocchio": pin.__version__, "qdd": qdds, "cut": [c["name"] for c in p.cuts], "u": us, "loop_q": loop_qs,
           "closure": closure, "closure0": float(np.abs(e0).max()), "nfev": int(sol.nfev),
           "energy_drift": float(max(abs(x - energy[0]) for x in energy))}
    json.dump(out, open(sys.argv[2], "w"))


if __name__ == "__main__":
    main()
