#!/usr/bin/env python3
"""Forward dynamics by MuJoCo and Pinocchio for the cad2mo cross-check (tests/simulation.rs).

Usage: forward_check.py IN.json OUT.json
IN: {"urdf": "<URDF text>", "gravity": [x, y, z],
     "samples": [{"q": {joint: value}, "qd": {...}, "tau": {...}}],          (accelerations)
     "passive": {"q": {joint: value}, "dt": s, "steps": n, "every": k}}      (optional)
OUT: {"mujoco": version or null, "mujoco_skip": reason or null, "pinocchio": version,
      "qacc_mujoco": [{joint: qacc}], "qacc_pin": [{joint: aba}],
      "tau_pin_of_ours": [{joint: rnea(q, qd, qdd_ours)}] (samples may carry "qdd_ours"),
      "passive_mujoco": [{joint: q}] (every k-th RK4 step, from t = 0), "passive_pin": [...]}
Joint values are the URDF's (continuous joints as angles). Both tools read the URDF themselves:
root link fixed, mimic couplings ignored (mimic=False, equality constraints disabled), joint
damping, friction and armature zero, limits and contacts off. MuJoCo is skipped (with the
reason) when it cannot read the model as written: a non positive-definite inertia or one
breaking the triangle inequality would have to be altered. Exit code 3 when neither imports.
"""
import json
import sys
import xml.etree.ElementTree as ET

try:
    import numpy as np
except ImportError as e:  # pragma: no cover
    print(f"NOTICE: numpy not importable: {e}")
    sys.exit(3)
try:
    import pinocchio as pin
except ImportError as e:  # pragma: no cover
    print(f"NOTICE: pinocchio not importable: {e}")
    sys.exit(3)
try:
    import mujoco
except ImportError:  # pragma: no cover
    mujoco = None


def stripped(text):
    root = ET.fromstring(text)
    for parent in list(root.iter()):
        for child in list(parent):
            tag = child.tag.split("}")[-1]
            if tag in ("visual", "collision", "gazebo", "transmission", "sensor", "loop_joint", "collision_checking") or "}" in child.tag:
                parent.remove(child)
    return root


def mujoco_model(text, gravity):
    root = stripped(text)
    ext = ET.SubElement(root, "mujoco")
    ET.SubElement(ext, "compiler", fusestatic="false", discardvisual="true", balanceinertia="false",
                  boundmass="0", boundinertia="0")
    model = mujoco.MjModel.from_xml_string(ET.tostring(root, encoding="unicode"))
    model.opt.gravity[:] = gravity
    model.opt.disableflags |= mujoco.mjtDisableBit.mjDSBL_CONTACT | mujoco.mjtDisableBit.mjDSBL_CONSTRAINT
    model.dof_damping[:] = 0.0
    model.dof_frictionloss[:] = 0.0
    model.dof_armature[:] = 0.0
    model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    return model


class Pin:
    def __init__(self, text, gravity):
        self.model = pin.buildModelFromXML(ET.tostring(stripped(text), encoding="unicode"))
        self.model.gravity.linear[:] = gravity
        self.data = self.model.createData()

    def state(self, qd_by_name, q_by_name):
        m = self.model
        q = pin.neutral(m)
        v = np.zeros(m.nv)
        for name, val in q_by_name.items():
            if not m.existJointName(name):
                raise SystemExit(f"joint {name} not in Pinocchio's model")
            j = m.joints[m.getJointId(name)]
            if j.nq == 2 and j.nv == 1:  # continuous: (cos, sin)
                q[j.idx_q] = np.cos(val)
                q[j.idx_q + 1] = np.sin(val)
            else:
                q[j.idx_q] = val
            if qd_by_name is not None:
                v[j.idx_v] = qd_by_name[name]
        return q, v

    def angles(self, q, names):
        out = {}
        for name in names:
            j = self.model.joints[self.model.getJointId(name)]
            out[name] = float(np.arctan2(q[j.idx_q + 1], q[j.idx_q])) if j.nq == 2 and j.nv == 1 else float(q[j.idx_q])
        return out


def main():
    spec = json.load(open(sys.argv[1]))
    gravity = spec["gravity"]
    out = {"mujoco": None, "mujoco_skip": None, "pinocchio": pin.__version__}
    p = Pin(spec["urdf"], gravity)
    mj = None
    if mujoco is None:
        out["mujoco_skip"] = "mujoco not importable"
    else:
        try:
            mj = mujoco_model(spec["urdf"], gravity)
            out["mujoco"] = mujoco.__version__
        except Exception as e:  # MuJoCo refuses the inertias as written
            out["mujoco_skip"] = str(e).strip().splitlines()[0]
    qacc_pin, qacc_mj, tau_back = [], [], []
    for s in spec.get("samples", []):
        q, v = p.state(s["qd"], s["q"])
        tau = np.zeros(p.model.nv)
        for name, t in s["tau"].items():
            tau[p.model.joints[p.model.getJointId(name)].idx_v] = t
        a = pin.aba(p.model, p.data, q, v, tau)
        qacc_pin.append({n: float(a[p.model.joints[p.model.getJointId(n)].idx_v]) for n in s["q"]})
        if "qdd_ours" in s:
            ours = np.zeros(p.model.nv)
            for name, x in s["qdd_ours"].items():
                ours[p.model.joints[p.model.getJointId(name)].idx_v] = x
            back = pin.rnea(p.model, p.data, q, v, ours)
            tau_back.append({n: float(back[p.model.joints[p.model.getJointId(n)].idx_v]) for n in s["q"]})
        if mj is not None:
            d = mujoco.MjData(mj)
            for name in s["q"]:
                j = mujoco.mj_name2id(mj, mujoco.mjtObj.mjOBJ_JOINT, name)
                if j < 0:
                    raise SystemExit(f"joint {name} not in MuJoCo's model")
                d.qpos[mj.jnt_qposadr[j]] = s["q"][name]
                d.qvel[mj.jnt_dofadr[j]] = s["qd"][name]
                d.qfrc_applied[mj.jnt_dofadr[j]] = s["tau"][name]
            mujoco.mj_forward(mj, d)
            qacc_mj.append({n: float(d.qacc[mj.jnt_dofadr[mujoco.mj_name2id(mj, mujoco.mjtObj.mjOBJ_JOINT, n)]]) for n in s["q"]})
    out["qacc_pin"] = qacc_pin
    out["qacc_mujoco"] = qacc_mj
    out["tau_pin_of_ours"] = tau_back
    ps = spec.get("passive")
    if ps:
        names = list(ps["q"].keys())
        dt, steps, every = ps["dt"], ps["steps"], ps["every"]
        if mj is not None:
            mj.opt.timestep = dt
            d = mujoco.MjData(mj)
            ids = [mujoco.mj_name2id(mj, mujoco.mjtObj.mjOBJ_JOINT, n) for n in names]
            for n, j in zip(names, ids):
                d.qpos[mj.jnt_qposadr[j]] = ps["q"][n]
            traj = []
            for k in range(steps + 1):
                if k % every == 0:
                    traj.append({n: float(d.qpos[mj.jnt_qposadr[j]]) for n, j in zip(names, ids)})
                if k < steps:
                    mujoco.mj_step(mj, d)
            out["passive_mujoco"] = traj
        # Pinocchio: classical RK4 on (q, v) with aba, same step.
        q, v = p.state(None, ps["q"])
        zero = np.zeros(p.model.nv)

        def f(q, v):
            return pin.aba(p.model, p.data, q, v, zero)

        traj = []
        for k in range(steps + 1):
            if k % every == 0:
                traj.append(p.angles(q, names))
            if k < steps:
                k1v, k1a = v, f(q, v)
                q2 = pin.integrate(p.model, q, k1v * dt / 2); v2 = v + k1a * dt / 2
                k2v, k2a = v2, f(q2, v2)
                q3 = pin.integrate(p.model, q, k2v * dt / 2); v3 = v + k2a * dt / 2
                k3v, k3a = v3, f(q3, v3)
                q4 = pin.integrate(p.model, q, k3v * dt); v4 = v + k3a * dt
                k4v, k4a = v4, f(q4, v4)
                q = pin.integrate(p.model, q, (k1v + 2 * k2v + 2 * k3v + k4v) * dt / 6)
                v = v + (k1a + 2 * k2a + 2 * k3a + k4a) * dt / 6
        out["passive_pin"] = traj
    json.dump(out, open(sys.argv[2], "w"))


if __name__ == "__main__":
    main()
