#!/usr/bin/env python3
"""Independent reading of a VRML 97 file with VTK, for cross-checking cad2mo's VRML front end.

Usage: vtk_check.py FILE.wrl [--time]

Reads FILE with VTK's vtkVRMLImporter (`pip install vtk`; an independent VRML 97 reader),
triangulates every actor's geometry with vtkTriangleFilter (polygons only: lines and points are
dropped), applies each actor's matrix, and prints one JSON line:

    {"triangles": N, "bounds": [xmin, xmax, ymin, ymax, zmin, zmax],
     "local_bounds": [...], "actors": A, "seconds": S}

`bounds` cover the points the triangles use (not unused points), in the scene's coordinates
(each actor's matrix applied); `local_bounds` the same points as written in the file, without
the actors' matrices (VTK 9.7's importer builds garbage actor matrices for some Transforms, see
the Rust test that calls this script). Both are null when there is no triangle. gzip input (magic bytes 1f 8b) is decompressed to a
temporary file first, since the importer reads plain text only. `seconds` is the importer's
reading time plus triangulation.

Exit status: 0 on success, 1 when VTK is missing or the file cannot be read (message on stderr).
"""

import gzip
import json
import os
import sys
import tempfile
import time


def fail(message: str) -> None:
    print(f"vtk_check: {message}", file=sys.stderr)
    sys.exit(1)


def main(argv: list) -> None:
    if len(argv) < 2:
        fail("usage: vtk_check.py FILE.wrl [--time]")
    path = argv[1]
    try:
        import numpy as np
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
    except ImportError:
        fail("the Python package vtk is not installed (pip install vtk)")
    vtk.vtkObject.GlobalWarningDisplayOff()

    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        fail(f"{path}: cannot read: {e}")
    tmp = None
    if data[:2] == b"\x1f\x8b":
        tmp = tempfile.NamedTemporaryFile(suffix=".wrl", delete=False)
        tmp.write(gzip.decompress(data))
        tmp.close()
        path = tmp.name
    del data

    try:
        start = time.perf_counter()
        importer = vtk.vtkVRMLImporter()
        importer.SetFileName(path)
        window = vtk.vtkRenderWindow()
        window.SetOffScreenRendering(1)
        importer.SetRenderWindow(window)
        importer.Update()
        renderer = importer.GetRenderer()
        if renderer is None:
            fail(f"{argv[1]}: VTK produced no renderer")
        actors = renderer.GetActors()
        actors.InitTraversal()
        triangles = 0
        lo = np.array([np.inf] * 3)
        hi = np.array([-np.inf] * 3)
        llo = np.array([np.inf] * 3)
        lhi = np.array([-np.inf] * 3)
        count = 0
        for _ in range(actors.GetNumberOfItems()):
            actor = actors.GetNextActor()
            mapper = actor.GetMapper()
            if mapper is None:
                continue
            mapper.Update()
            polydata = mapper.GetInput()
            if polydata is None:
                continue
            count += 1
            tri = vtk.vtkTriangleFilter()
            tri.SetInputData(polydata)
            tri.PassVertsOff()
            tri.PassLinesOff()
            tri.Update()
            out = tri.GetOutput()
            polys = out.GetPolys()
            n = polys.GetNumberOfCells()
            if n == 0:
                continue
            triangles += n
            conn = vtk_to_numpy(polys.GetConnectivityArray())
            pts = vtk_to_numpy(out.GetPoints().GetData()).astype(np.float64)
            used = pts[np.unique(conn)]
            llo = np.minimum(llo, used.min(axis=0))
            lhi = np.maximum(lhi, used.max(axis=0))
            m = actor.GetMatrix()
            mat = np.array([[m.GetElement(r, c) for c in range(4)] for r in range(4)])
            world = used @ mat[:3, :3].T + mat[:3, 3]
            lo = np.minimum(lo, world.min(axis=0))
            hi = np.maximum(hi, world.max(axis=0))
        seconds = time.perf_counter() - start
    finally:
        if tmp is not None:
            os.unlink(tmp.name)

    def interleave(lo, hi):
        if triangles == 0:
            return None
        # Non-finite values (garbage actor matrices) as null: strict JSON has no NaN.
        return [float(x) if np.isfinite(x) else None for x in (lo[0], hi[0], lo[1], hi[1], lo[2], hi[2])]

    print(
        json.dumps(
            {
                "triangles": int(triangles),
                "bounds": interleave(lo, hi),
                "local_bounds": interleave(llo, lhi),
                "actors": count,
                "seconds": seconds,
            }
        )
    )


if __name__ == "__main__":
    main(sys.argv)
