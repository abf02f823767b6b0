#!/usr/bin/env python3
"""Independent check of a DXF shape file written by cad2mo.

Usage: dxf_check.py FILE.dxf EXPECTED_FACES

Reads FILE.dxf with ezdxf (an independent DXF implementation: `pip install ezdxf`), runs ezdxf's
auditor and fails on audit errors, counts the 3DFACE entities in modelspace and compares the count
with EXPECTED_FACES, and prints the DXF version, layers and the bounding box of the faces.

Exit status: 0 when every check passes, 1 otherwise (with a message on stderr).
"""

import sys


def fail(message: str) -> None:
    print(f"dxf_check: {message}", file=sys.stderr)
    sys.exit(1)


def main(argv: list) -> None:
    if len(argv) != 3:
        fail("usage: dxf_check.py FILE.dxf EXPECTED_FACES")
    path, expected_text = argv[1], argv[2]
    try:
        expected = int(expected_text)
    except ValueError:
        fail(f"EXPECTED_FACES must be an integer, got {expected_text!r}")

    try:
        import ezdxf
        from ezdxf.lldxf.const import DXFError
    except ImportError:
        fail("the Python package ezdxf is not installed (pip install ezdxf)")

    try:
        doc = ezdxf.readfile(path)
    except IOError as e:
        fail(f"{path}: cannot read: {e}")
    except DXFError as e:
        fail(f"{path}: not a valid DXF file: {e}")

    auditor = doc.audit()
    for fix in auditor.fixes:
        print(f"audit fix: {fix.message}")
    if auditor.has_errors:
        for err in auditor.errors:
            print(f"audit error: {err.message}", file=sys.stderr)
        fail(f"{path}: {len(auditor.errors)} audit error(s)")

    msp = doc.modelspace()
    faces = msp.query("3DFACE")
    count = len(faces)
    others = sorted({e.dxftype() for e in msp if e.dxftype() != "3DFACE"})

    lo = [float("inf")] * 3
    hi = [float("-inf")] * 3
    for face in faces:
        for name in ("vtx0", "vtx1", "vtx2", "vtx3"):
            p = face.dxf.get(name)
            if p is None:
                continue
            for k in range(3):
                lo[k] = min(lo[k], p[k])
                hi[k] = max(hi[k], p[k])

    print(f"file: {path}")
    print(f"dxf version: {doc.dxfversion} ({doc.acad_release}), $INSUNITS {doc.header.get('$INSUNITS', 'not set')}")
    print("layers: " + ", ".join(f"{layer.dxf.name} (ACI {layer.dxf.color})" for layer in doc.layers))
    print(f"3DFACE entities: {count}")
    if others:
        print("other entities: " + ", ".join(others))
    if count:
        print(
            "bounding box: min ({:.9g}, {:.9g}, {:.9g}) max ({:.9g}, {:.9g}, {:.9g})".format(
                *lo, *hi
            )
        )
    else:
        print("bounding box: empty")

    if count != expected:
        fail(f"{path}: expected {expected} 3DFACE entities, found {count}")


if __name__ == "__main__":
    main(sys.argv)
