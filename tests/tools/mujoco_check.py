#!/usr/bin/env python3
"""Inverse dynamics by MuJoCo for the cad2mo cross-check (tests/mujoco.rs).

Usage: mujoco_check.py IN.json OUT.json
IN: {"model": "<path to .mjcf.xml>", "samples": [{"q": {joint: value}, "qd": {...}, "qdd": {...}}],
     "keep_damping": false}
OUT: {"mujoco": "<version>", "nv": n, "tau": [{joint: qfrc_inverse}],
      "xpos": [{body: [x, y, z]}], "xquat": [{body: [w, x, y, z]}]}  (world poses after mj_inverse)
Mesh geoms and assets are dropped (inertiafromgeom is false: they only draw); contacts are
disabled; armature is zero; damping is zero unless "keep_damping" (then the MJCF's joint
`damping` stays: qfrc_inverse includes damping * qvel); equality constraints (mimic) and
frictionloss are disabled (the tree's own inverse dynamics; MuJoCo's frictionloss is a soft
constraint, not a Coulomb sign law). Exit code 3 when mujoco cannot be imported.
"""
import json
import sys
import xml.etree.ElementTree as ET

try:
    import mujoco
except ImportError as e:  # pragma: no cover
    print(f"NOTICE: mujoco not importable: {e}")
    sys.exit(3)


def load(path, keep_damping=False):
    tree = ET.parse(path)
    root = tree.getroot()
    for asset in root.findall("asset"):
        root.remove(asset)
    for parent in root.iter():
        for geom in list(parent.findall("geom")):
            if geom.get("type") == "mesh":
                parent.remove(geom)
    model = mujoco.MjModel.from_xml_string(ET.tostring(root, encoding="unicode"))
    model.opt.disableflags |= mujoco.mjtDisableBit.mjDSBL_CONTACT
    model.opt.disableflags |= mujoco.mjtDisableBit.mjDSBL_EQUALITY
    model.opt.disableflags |= mujoco.mjtDisableBit.mjDSBL_FRICTIONLOSS
    if not keep_damping:
        model.dof_damping[:] = 0.0
    model.dof_armature[:] = 0.0
    return model


def main():
    spec = json.load(open(sys.argv[1]))
    model = load(spec["model"], spec.get("keep_damping", False))
    data = mujoco.MjData(model)
    out, xpos, xquat = [], [], []
    for s in spec["samples"]:
        data.qpos[:] = model.qpos0
        data.qvel[:] = 0.0
        data.qacc[:] = 0.0
        for name in s["q"]:
            j = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
            if j < 0:
                raise SystemExit(f"joint {name} not in the MJCF model")
            data.qpos[model.jnt_qposadr[j]] = s["q"][name]
            data.qvel[model.jnt_dofadr[j]] = s["qd"][name]
            data.qacc[model.jnt_dofadr[j]] = s["qdd"][name]
        mujoco.mj_inverse(model, data)
        tau = {}
        for name in s["q"]:
            j = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
            tau[name] = float(data.qfrc_inverse[model.jnt_dofadr[j]])
        out.append(tau)
        names = [mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, b) for b in range(1, model.nbody)]
        xpos.append({n: [float(x) for x in data.xpos[b + 1]] for b, n in enumerate(names)})
        xquat.append({n: [float(x) for x in data.xquat[b + 1]] for b, n in enumerate(names)})
    names = spec["samples"][0]["q"] if spec["samples"] else {}
    dof = {n: model.jnt_dofadr[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, n)] for n in names}
    json.dump({"mujoco": mujoco.__version__, "nv": int(model.nv),
               "damping": {n: float(model.dof_damping[d]) for n, d in dof.items()},
               "frictionloss": {n: float(model.dof_frictionloss[d]) for n, d in dof.items()},
               "tau": out, "xpos": xpos, "xquat": xquat}, open(sys.argv[2], "w"))


if __name__ == "__main__":
    main()
