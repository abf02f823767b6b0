#!/usr/bin/env python3
"""MuJoCo's reading of a URDF cad2mo wrote, for the cross-check in tests/urdf_out.rs.

Usage: urdf_mujoco.py IN.json OUT.json
IN: {"urdf": "<path>", "samples": [{joint: u}]}   (u = URDF coordinate; joints not named stay at 0)
OUT: {"mujoco": "<version>", "total_mass": m, "nq": n,
      "xpos": [{body: [x, y, z]}], "xquat": [{body: [w, x, y, z]}]}  (world poses, mj_kinematics)
MuJoCo reads URDF directly; a <mujoco><compiler fusestatic="false"/></mujoco> element is added so
that bodies joined by fixed joints keep their names (MuJoCo would merge them), with a mass floor of
1e-12 kg and 1e-14 kg m2 (MuJoCo refuses moving bodies without mass, and a joint of several
elements runs through massless links in URDF; the floor adds < 1e-9 kg to any model we test).
Inertias that break the triangle inequality (a golden case has one on purpose) are balanced
(positions and masses do not depend on them); an inertia that is not positive definite (the
validator warns about those) is replaced by 1e-9 I and its link listed in "inertia_replaced".
Mesh elements are dropped. Exit code 3 when mujoco cannot be imported.
"""
import json
import sys

import numpy
import xml.etree.ElementTree as ET

try:
    import mujoco
except ImportError as e:  # pragma: no cover
    print(f"NOTICE: mujoco not importable: {e}")
    sys.exit(3)


def load(path, replaced):
    root = ET.parse(path).getroot()
    for link in root.findall("link"):
        inertia = link.find("inertial/inertia")
        if inertia is not None:
            g = lambda k: float(inertia.get(k))
            m = numpy.array([[g("ixx"), g("ixy"), g("ixz")], [g("ixy"), g("iyy"), g("iyz")], [g("ixz"), g("iyz"), g("izz")]])
            if m.any() and numpy.linalg.eigvalsh(m).min() <= 0.0:
                for k in ("ixy", "ixz", "iyz"):
                    inertia.set(k, "0")
                for k in ("ixx", "iyy", "izz"):
                    inertia.set(k, "1e-9")
                replaced.append(link.get("name"))
        for tag in ("visual", "collision"):
            for el in link.findall(tag):
                link.remove(el)
    ext = ET.SubElement(root, "mujoco")
    ET.SubElement(ext, "compiler", {"fusestatic": "false", "discardvisual": "true", "boundmass": "1e-12", "boundinertia": "1e-14", "balanceinertia": "true"})
    return mujoco.MjModel.from_xml_string(ET.tostring(root, encoding="unicode"))


def main():
    spec = json.load(open(sys.argv[1]))
    replaced = []
    model = load(spec["urdf"], replaced)
    data = mujoco.MjData(model)
    names = [mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, b) for b in range(model.nbody)]
    xpos, xquat = [], []
    for s in spec["samples"]:
        data.qpos[:] = model.qpos0
        for name, u in s.items():
            j = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
            if j < 0:
                raise SystemExit(f"joint {name} not in MuJoCo's model of the URDF")
            data.qpos[model.jnt_qposadr[j]] = u
        mujoco.mj_kinematics(model, data)
        xpos.append({names[b]: [float(x) for x in data.xpos[b]] for b in range(1, model.nbody)})
        xquat.append({names[b]: [float(x) for x in data.xquat[b]] for b in range(1, model.nbody)})
    out = {
        "mujoco": mujoco.__version__,
        "nq": int(model.nq),
        "total_mass": float(sum(model.body_mass)),
        "inertia_replaced": replaced,
        "xpos": xpos,
        "xquat": xquat,
    }
    json.dump(out, open(sys.argv[2], "w"))


if __name__ == "__main__":
    main()
