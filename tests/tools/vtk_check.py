#!/usr/bin/env python3
"""Independent reading of VRML 97 files with VTK, for cross-checking cad2mo's VRML front end.

Usage: vtk_check.py FILE.wrl [FILE.wrl ...]

Reads each FILE with VTK's vtkVRMLImporter (`pip install vtk`; an independent VRML 97 reader),
triangulates every actor's geometry with vtkTriangleFilter (polygons only: lines and points are
dropped), and prints one JSON line per file:

    {"file": F, "triangles": N, "bounds": [xmin, xmax, ymin, ymax, zmin, zmax],
     "local_bounds": [...], "actors": A, "seconds": S}

`bounds` cover the points the triangles use (not unused points) in the scene's coordinates,
each actor's matrix applied; `local_bounds` the same points as written in the file, without the
actors' matrices (VTK 9.7's importer builds garbage actor matrices for some Transforms: see the
Rust test that calls this script). Both are null when there is no triangle, and a non-finite
bound is null. gzip input (magic bytes 1f 8b) is decompressed to a temporary file first: the
importer reads plain text only; a file without a header line (legal for inlined parts, read as
nothing by VTK) gets `#VRML V2.0 utf8` prepended in that copy. `seconds` is the importer's reading time plus triangulation.

Each file is read in a forked child, because the importer crashes (SIGSEGV) on some valid files
(PROTO, some primitives); such a file gets {"file": F, "error": "..."}. Each file is read twice:
VTK 9.7's importer sometimes builds actor matrices from uninitialised memory (garbage, NaN or
1e200 entries, different from run to run), so when the two readings' world bounds differ (or are
not finite) `bounds` is null and `"bounds_unstable": true` is added.

Exit status: 0 when every file was read, 1 otherwise or when VTK is missing (message on stderr).
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


def read_one(path: str, vtk, np, vtk_to_numpy) -> dict:
    with open(path, "rb") as f:
        data = f.read()
    compressed = data[:2] == b"\x1f\x8b"
    if compressed:
        data = gzip.decompress(data)
    # VTK reads nothing from a header-less file (legal for inlined parts): give it the header.
    header_less = not data.lstrip().startswith(b"#")
    tmp = None
    if compressed or header_less:
        tmp = tempfile.NamedTemporaryFile(suffix=".wrl", delete=False)
        if header_less:
            tmp.write(b"#VRML V2.0 utf8\n")
        tmp.write(data)
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
            return {"error": "VTK produced no renderer"}
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
            with np.errstate(all="ignore"):
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
        values = (lo[0], hi[0], lo[1], hi[1], lo[2], hi[2])
        # Non-finite values (garbage actor matrices) as null: strict JSON has no NaN.
        return [float(x) if np.isfinite(x) else None for x in values]

    return {
        "triangles": int(triangles),
        "bounds": interleave(lo, hi),
        "local_bounds": interleave(llo, lhi),
        "actors": count,
        "seconds": seconds,
    }


def main(argv: list) -> None:
    files = argv[1:]
    if not files:
        fail("usage: vtk_check.py FILE.wrl [FILE.wrl ...]")
    try:
        import numpy as np
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
    except ImportError:
        fail("the Python package vtk is not installed (pip install vtk)")
    vtk.vtkObject.GlobalWarningDisplayOff()
    try:
        vtk.vtkLogger.SetStderrVerbosity(vtk.vtkLogger.VERBOSITY_OFF)
    except AttributeError:
        pass

    def start_child(path: str, churn: bool):
        sys.stdout.flush()
        r, w = os.pipe()
        pid = os.fork()
        if pid == 0:
            os.close(r)
            if churn:
                # Leave other bytes in freed heap memory, so uninitialised reads differ.
                junk = [os.urandom(4096 + 64 * k) for k in range(2000)]
                del junk
                np.random.default_rng().random(200_000).tolist()
            try:
                result = read_one(path, vtk, np, vtk_to_numpy)
            except Exception as e:  # noqa: BLE001 - reported per file
                result = {"error": f"{type(e).__name__}: {e}"}
            with os.fdopen(w, "w") as out:
                out.write(json.dumps(result))
            os._exit(0)
        os.close(w)
        return pid, r

    def finish_child(pid: int, r: int) -> dict:
        with os.fdopen(r) as inp:
            text = inp.read()
        _, status = os.waitpid(pid, 0)
        if not text:
            return {"error": f"VTK crashed (wait status {status})"}
        return json.loads(text)

    # Every file twice (plain, then with a churned heap), a few children at a time.
    jobs = [(path, churn) for path in files for churn in (False, True)]
    results = {}
    running = []
    width = max(1, min(4, os.cpu_count() or 1))
    while jobs or running:
        while jobs and len(running) < width:
            path, churn = jobs.pop(0)
            running.append((path, churn, *start_child(path, churn)))
        path, churn, pid, r = running.pop(0)
        results[(path, churn)] = finish_child(pid, r)

    ok = True
    for path in files:
        first = results[(path, False)]
        second = results[(path, True)]
        if "error" in first:
            ok = False
        elif second.get("bounds") != first.get("bounds") or None in (first.get("bounds") or []):
            # The importer's actor matrices come from uninitialised memory in some cases: a
            # second reading that disagrees marks the world bounds as unreliable.
            first["bounds"] = None
            first["bounds_unstable"] = True
        first["file"] = path
        print(json.dumps(first))
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main(sys.argv)
