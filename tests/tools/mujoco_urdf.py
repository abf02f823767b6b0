#!/usr/bin/env python3
"""MuJoCo's own reading of a URDF, for the cad2mo cross-check (tests/urdf.rs).

Usage: mujoco_urdf.py IN.json OUT.json
IN: {"urdf": "<URDF text>", "samples": [{"q": {urdf_joint_name: value}}]}
OUT: {"mujoco": version, "total_mass": kg, "joints": [names],
      "xpos": [{link: [x, y, z]}], "xquat": [{link: [w, x, y, z]}], "gravity": [{joint: qfrc_bias}]}
Geometry, Gazebo, transmission, sensor and Drake elements are dropped (only kinematics and
inertia are compared); static bodies are not fused, so every link keeps its name. The root link
is fixed to the world, as in cad2mo. `gravity` is qfrc_bias at zero velocity: the generalized
gravity force. Exit code 3 when mujoco cannot be imported.
"""
import json
import sys
import xml.etree.ElementTree as ET

try:
    import mujoco
except ImportError as e:  # pragma: no cover
    print(f"NOTICE: mujoco not importable: {e}")
    sys.exit(3)


def positive_definite(i):
    import numpy as np
    g = lambda k: float(i.get(k, "0"))
    m = np.array([[g("ixx"), g("ixy"), g("ixz")], [g("ixy"), g("iyy"), g("iyz")], [g("ixz"), g("iyz"), g("izz")]])
    return bool(np.all(np.linalg.eigvalsh(m) > 1e-10))


def load(text):
    root = ET.fromstring(text)
    # MuJoCo refuses inertias that are not positive definite (some real URDFs have them). The
    # compared quantities (mass, poses, gravity forces) do not depend on inertia, so such a link
    # gets a small valid one; balanceinertia likewise only touches inertias.
    for i in root.iter("inertia"):
        if not positive_definite(i):
            for k, v in (("ixx", "1e-6"), ("iyy", "1e-6"), ("izz", "1e-6"), ("ixy", "0"), ("ixz", "0"), ("iyz", "0")):
                i.set(k, v)
    for parent in list(root.iter()):
        for child in list(parent):
            tag = child.tag.split("}")[-1]
            if tag in ("visual", "collision", "gazebo", "transmission", "sensor", "loop_joint", "collision_checking") or "}" in child.tag:
                parent.remove(child)
    ext = ET.SubElement(root, "mujoco")
    ET.SubElement(ext, "compiler", fusestatic="false", discardvisual="true", balanceinertia="true",
                  boundmass="0", boundinertia="0")
    return mujoco.MjModel.from_xml_string(ET.tostring(root, encoding="unicode"))


def main():
    spec = json.load(open(sys.argv[1]))
    model = load(spec["urdf"])
    model.opt.gravity[:] = [0.0, 0.0, -9.81]
    data = mujoco.MjData(model)
    joints = [mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, j) for j in range(model.njnt)]
    out = {"mujoco": mujoco.__version__, "total_mass": float(sum(model.body_mass)), "joints": joints,
           "xpos": [], "xquat": [], "gravity": []}
    for s in spec["samples"]:
        data.qpos[:] = model.qpos0
        data.qvel[:] = 0.0
        for name, v in s["q"].items():
            j = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
            if j < 0:
                raise SystemExit(f"joint {name} not in MuJoCo's model")
            data.qpos[model.jnt_qposadr[j]] = v
        mujoco.mj_forward(model, data)
        names = [mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, b) for b in range(1, model.nbody)]
        out["xpos"].append({n: [float(x) for x in data.xpos[b + 1]] for b, n in enumerate(names)})
        out["xquat"].append({n: [float(x) for x in data.xquat[b + 1]] for b, n in enumerate(names)})
        out["gravity"].append({n: float(data.qfrc_bias[model.jnt_dofadr[j]]) for j, n in enumerate(joints)
                               if int(model.jnt_type[j]) in (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))})
    json.dump(out, open(sys.argv[2], "w"))


if __name__ == "__main__":
    main()
