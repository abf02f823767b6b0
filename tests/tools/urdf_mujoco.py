#!/usr/bin/env python3
"""MuJoCo's reading of a URDF cad2mo wrote, for the cross-check in tests/urdf_out.rs.

Usage: urdf_mujoco.py IN.json OUT.json
IN: {"urdf": "<path>", "samples": [{joint: u}]}   (u = URDF coordinate; joints not named stay at 0)
OUT: {"mujoco": "<version>", "total_mass": m, "nq": n,
      "xpos": [{body: [x, y, z]}], "xquat": [{body: [w, x, y, z]}]}  (world poses, mj_kinematics)
MuJoCo reads URDF directly; a <mujoco><compiler fusestatic="false"/></mujoco> element is added so
that bodies joined by fixed joints keep their names (MuJoCo would merge them). Mesh elements are
dropped. Exit code 3 when mujoco cannot be imported.
"""
import json
import sys
import xml.etree.ElementTree as ET

try:
    import mujoco
except ImportError as e:  # pragma: no cover
    print(f"NOTICE: mujoco not importable: {e}")
    sys.exit(3)


def load(path):
    root = ET.parse(path).getroot()
    for link in root.findall("link"):
        for tag in ("visual", "collision"):
            for el in link.findall(tag):
                link.remove(el)
    ext = ET.SubElement(root, "mujoco")
    ET.SubElement(ext, "compiler", {"fusestatic": "false", "discardvisual": "true"})
    return mujoco.MjModel.from_xml_string(ET.tostring(root, encoding="unicode"))


def main():
    spec = json.load(open(sys.argv[1]))
    model = load(spec["urdf"])
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
        "xpos": xpos,
        "xquat": xquat,
    }
    json.dump(out, open(sys.argv[2], "w"))


if __name__ == "__main__":
    main()
