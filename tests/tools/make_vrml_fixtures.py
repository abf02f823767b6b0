#!/usr/bin/env python3
"""Generates the VRML test bundles under tests/in/vrml_* (and broken_vrml_*): first-generation
SimMechanics XML without meshes (geometryFileName ""), plus a VRML export that places each part
at its CS1 pose, the way Pro/E's "Save as VRML" does: a main hierarchy file that Inlines one
file per part, auto-generated names that do not match the XML (Obj01, Obj02, ...), nested shapes.

expect.json gains `vrml_bbox_m`: per body nodeID, the world-space bounding box (metres) of the
geometry placed for it, computed here from the VRML transforms, for the mesh-placement test.
Python 3 standard library only; deterministic."""
import gzip, json, math, shutil, sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import make_fixtures as mf  # noqa: E402

OUT = Path(__file__).resolve().parent.parent / "in"


def axis_angle(R):
    """VRML rotation (axis x y z, angle) of a rotation matrix."""
    tr = R[0][0] + R[1][1] + R[2][2]
    c = max(-1.0, min(1.0, (tr - 1.0) / 2.0))
    a = math.acos(c)
    if a < 1e-12:
        return (0.0, 0.0, 1.0, 0.0)
    if math.pi - a < 1e-6:
        # Near pi: axis from the diagonal.
        x = math.sqrt(max(0.0, (R[0][0] + 1) / 2))
        y = math.copysign(math.sqrt(max(0.0, (R[1][1] + 1) / 2)), R[0][1] if x > 1e-9 else 1.0)
        z = math.copysign(math.sqrt(max(0.0, (R[2][2] + 1) / 2)), R[0][2] if x > 1e-9 else R[1][2])
        n = math.sqrt(x * x + y * y + z * z)
        return (x / n, y / n, z / n, a)
    s = 2 * math.sin(a)
    return ((R[2][1] - R[1][2]) / s, (R[0][2] - R[2][0]) / s, (R[1][0] - R[0][1]) / s, a)


def r17(x):
    return "%.17g" % x


def box_ifs(lo, hi, color):
    """Two Shapes (upper and lower halves of the box, split in z) in a nested Group: VRML 97."""
    zm = 0.5 * (lo[2] + hi[2])
    out = []
    for (z0, z1) in ((lo[2], zm), (zm, hi[2])):
        pts = [(x, y, z) for z in (z0, z1) for y in (lo[1], hi[1]) for x in (lo[0], hi[0])]
        faces = "0 2 3 1 -1 4 5 7 6 -1 0 1 5 4 -1 2 6 7 3 -1 0 4 6 2 -1 1 3 7 5 -1"
        out.append(
            "      Shape {\n        appearance Appearance { material Material { diffuseColor %s %s %s } }\n"
            "        geometry IndexedFaceSet {\n          coord Coordinate { point [ %s ] }\n"
            "          coordIndex [ %s ]\n        }\n      }" % (r17(color[0]), r17(color[1]), r17(color[2]),
                                                            ", ".join("%s %s %s" % tuple(map(r17, p)) for p in pts), faces))
    return "Group {\n  children [\n    Group {\n      children [\n" + ",\n".join(out) + "\n      ]\n    }\n  ]\n}\n"


def box_corners_world(cs1_pos, cs1_R, lo, hi, scale):
    pts = [(x, y, z) for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
    w = [mf.add(cs1_pos, mf.mat_vec(cs1_R, p)) for p in pts]
    return [[min(p[k] for p in w) * scale for k in range(3)], [max(p[k] for p in w) * scale for k in range(3)]]


def transform_line(name, pos, R, inner, indent="    "):
    ax = axis_angle(R)
    return ("%sDEF %s Transform {\n%s  translation %s %s %s\n%s  rotation %s %s %s %s\n%s  children [\n%s\n%s  ]\n%s}" %
            (indent, name, indent, r17(pos[0]), r17(pos[1]), r17(pos[2]), indent, *map(r17, ax), indent, inner, indent, indent))


def assembly_model(twins=False):
    m = mf.Model("VASM", container="SimMechanics", link="4.0", created_from="Pro/E Wildfire Creo 2.0 - 2012360")
    top = m.top
    rp = m.root_part(top, (0.0, 0.0, 0.0))
    parts = []
    if twins:
        R = mf.chain(mf.Rz(25.0), mf.Rx(40.0))
        p = (120.0, 40.0, -30.0)
        for name, node, lo, hi in (("BOLT", "201", (-5.0, -5.0, 0.0), (5.0, 5.0, 60.0)), ("NUT", "202", (-12.0, -12.0, 0.0), (12.0, 12.0, 10.0))):
            b = m.part(top, name, node, p, R, lo, hi, geometry="")
            m.joint(top, rp, b, p, R, prims=(("revolute", mf.col(R, 2)),))
            parts.append((b, p, R, lo, hi))
    else:
        specs = (("BRACKET", "101", (150.0, 20.0, -40.0), mf.chain(mf.Rz(-15.0), mf.Rx(40.0), mf.Ry(25.0)), (-20.0, -15.0, -5.0), (140.0, 15.0, 5.0)),
                 ("SLIDER", "102", (290.0, 70.0, -55.0), mf.chain(mf.Rx(20.0), mf.Ry(-55.0), mf.Rz(80.0)), (-10.0, -10.0, -10.0), (60.0, 10.0, 10.0)),
                 ("TOOL", "103", (250.0, 160.0, 10.0), mf.chain(mf.Ry(70.0), mf.Rz(15.0), mf.Rx(-5.0)), (-8.0, -8.0, -8.0), (90.0, 8.0, 8.0)))
        prev = rp
        for name, node, p, R, lo, hi in specs:
            b = m.part(top, name, node, p, R, lo, hi, geometry="")
            m.joint(top, prev, b, p, R, prims=(("revolute", mf.col(R, 2)),))
            parts.append((b, p, R, lo, hi))
            prev = b
    m.ground(rp, (0.0, 0.0, 0.0))
    return m, parts


COLORS = [(0.8, 0.2, 0.2), (0.2, 0.6, 0.9), (0.3, 0.8, 0.3)]


def write(name, m, files, extra):
    d = OUT / name
    if d.exists():
        shutil.rmtree(d)
    d.mkdir(parents=True)
    (d / "VASM.xml").write_text(m.xml(), encoding="utf-8", newline="\n")
    for path, data in files.items():
        p = d / path
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_bytes(data if isinstance(data, bytes) else data.encode())
    facts = m.expect("VASM.xml")
    facts.update(extra)
    (d / "expect.json").write_text(json.dumps({"case": name, **facts}, indent=1) + "\n", encoding="utf-8", newline="\n")


def vrml97_assembly(parts, names, stray=False, gz=False):
    """Main file with one Inline per part (in shuffled order), parts in parts/."""
    files, items = {}, []
    order = list(range(len(parts)))[::-1]
    for k in order:
        b, p, R, lo, hi = parts[k]
        fname = "parts/%s.wrl" % names[k].lower()
        body = box_ifs(lo, hi, COLORS[k % 3])
        files[fname] = ("#VRML V2.0 utf8\n# part %s\n" % names[k]) + body
        items.append(transform_line(names[k], p, R, '      Inline { url "%s" }' % fname))
    if stray:
        items.append('    DEF STRAY Transform { translation 5000 0 0 children [ Shape { geometry Box { size 10 10 10 } } ] }')
    main = "#VRML V2.0 utf8\n# assembly hierarchy\nDEF ASM Group {\n  children [\n" + ",\n".join(items) + "\n  ]\n}\n"
    if gz:
        files["asm.wrz"] = gzip.compress(main.encode(), mtime=0)
    else:
        files["asm.wrl"] = main
    return files


def bboxes(parts):
    return {b.node_id: box_corners_world(p, R, lo, hi, 1e-3) for (b, p, R, lo, hi) in parts}


def vrml1(parts, names):
    seps = []
    for k, (b, p, R, lo, hi) in enumerate(parts):
        ax = axis_angle(R)
        pts = [(x, y, z) for z in (lo[2], hi[2]) for y in (lo[1], hi[1]) for x in (lo[0], hi[0])]
        c = COLORS[k % 3]
        seps.append(
            "DEF %s Separator {\n  Translation { translation %s %s %s }\n  Rotation { rotation %s %s %s %s }\n"
            "  Material { diffuseColor %s %s %s }\n  Coordinate3 { point [ %s ] }\n"
            "  IndexedFaceSet { coordIndex [ 0, 2, 3, 1, -1, 4, 5, 7, 6, -1, 0, 1, 5, 4, -1, 2, 6, 7, 3, -1, 0, 4, 6, 2, -1, 1, 3, 7, 5, -1 ] }\n}"
            % (names[k], *map(r17, p), *map(r17, ax), *map(r17, c), ", ".join("%s %s %s" % tuple(map(r17, q)) for q in pts)))
    return {"asm.wrl": "#VRML V1.0 ascii\nSeparator {\n" + "\n".join(seps) + "\n}\n"}


def main():
    m, parts = assembly_model()
    names = ["Obj01", "Obj02", "Obj03"][::-1]  # mangled, and not in XML order
    write("vrml_assembly", m, vrml97_assembly(parts, names), {"vrml_bbox_m": bboxes(parts)})
    write("vrml_gzip", m, vrml97_assembly(parts, names, gz=True), {"vrml_bbox_m": bboxes(parts)})
    write("vrml_unmatched", m, vrml97_assembly(parts, names, stray=True), {"vrml_bbox_m": bboxes(parts), "warning": "vrml-unmatched"})
    write("vrml_v1", m, vrml1(parts, ["Obj01", "Obj02", "Obj03"]), {"vrml_bbox_m": bboxes(parts)})
    t, tparts = assembly_model(twins=True)
    write("vrml_twins", t, vrml97_assembly(tparts, ["BOLT01", "NUT01"]), {"vrml_bbox_m": bboxes(tparts)})
    write("broken_vrml_ambiguous", t, vrml97_assembly(tparts, ["Obj01", "Obj02"]), {"error_contains": "ambiguous"})
    pinned = vrml97_assembly(tparts, ["Obj01", "Obj02"])
    pinned["matching.json"] = json.dumps({"201": "ASM/Obj01", "202": "ASM/Obj02"}, indent=1) + "\n"
    write("vrml_pinned", t, pinned, {"vrml_bbox_m": bboxes(tparts)})
    print("wrote vrml_assembly, vrml_gzip, vrml_unmatched, vrml_v1, vrml_twins, vrml_pinned, broken_vrml_ambiguous")


main()
