"""OCCT (cadquery-ocp) side of the STEP tests: an independent reading of STEP files, and the
generator of our own small STEP cases.

    python3 step_occt.py measure OUT FILE...
                                           writes to OUT, as JSON per file, every solid's volume
                                           (m^3), centroid (m) and bounding-box diagonal (m),
                                           placements and units applied by OCCT's own reader
    python3 step_occt.py generate DIR      writes box.step, cylinder.step, torus.step,
                                           assembly.step (one part placed twice),
                                           inch_box.step (a box written in inches) and
                                           colours.step (a box coloured sRGB (0.8, 0.4, 0.2);
                                           a white cylinder whose top face is blue) into DIR

OCCT prints its statistics on stdout, hence the OUT file. Everything is in metres whatever unit the file uses (OCCT converts to its session unit,
millimetres here; we divide by 1000).
"""

import json
import math
import sys

from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox, BRepPrimAPI_MakeCylinder, BRepPrimAPI_MakeTorus
from OCP.BRepBndLib import BRepBndLib
from OCP.Bnd import Bnd_Box
from OCP.BRepGProp import BRepGProp
from OCP.GProp import GProp_GProps
from OCP.IFSelect import IFSelect_RetDone
from OCP.Interface import Interface_Static
from OCP.STEPControl import STEPControl_Reader, STEPControl_Writer, STEPControl_AsIs
from OCP.TopAbs import TopAbs_SOLID
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS
from OCP.gp import gp_Ax2, gp_Pnt, gp_Dir, gp_Trsf, gp_Vec, gp_Ax1
from OCP.TopLoc import TopLoc_Location


def solids_of(path):
    reader = STEPControl_Reader()
    if reader.ReadFile(path) != IFSelect_RetDone:
        raise SystemExit(f"{path}: OCCT cannot read it")
    reader.TransferRoots()
    shape = reader.OneShape()
    out = []
    exp = TopExp_Explorer(shape, TopAbs_SOLID)
    while exp.More():
        solid = TopoDS.Solid(exp.Current())
        props = GProp_GProps()
        BRepGProp.VolumeProperties_s(solid, props)
        c = props.CentreOfMass()
        box = Bnd_Box()
        BRepBndLib.Add_s(solid, box)
        lo, hi = box.CornerMin(), box.CornerMax()
        x0, y0, z0, x1, y1, z1 = lo.X(), lo.Y(), lo.Z(), hi.X(), hi.Y(), hi.Z()
        diag = math.sqrt((x1 - x0) ** 2 + (y1 - y0) ** 2 + (z1 - z0) ** 2)
        out.append(
            {
                "volume": props.Mass() * 1e-9,
                "centroid": [c.X() * 1e-3, c.Y() * 1e-3, c.Z() * 1e-3],
                "diagonal": diag * 1e-3,
            }
        )
        exp.Next()
    return out


def measure(out, paths):
    with open(out, "w") as f:
        json.dump({p: solids_of(p) for p in paths}, f)


def write(shape, path, unit="MM"):
    Interface_Static.SetCVal_s("write.step.unit", unit)
    Interface_Static.SetCVal_s("write.step.schema", "AP214IS")
    w = STEPControl_Writer()
    w.Transfer(shape, STEPControl_AsIs)
    if w.Write(path) != IFSelect_RetDone:
        raise SystemExit(f"{path}: OCCT cannot write it")


def generate(folder):
    # A 40 x 20 x 10 mm box with a corner at (5, 6, 7) mm.
    box = BRepPrimAPI_MakeBox(gp_Pnt(5, 6, 7), 40, 20, 10).Shape()
    write(box, f"{folder}/box.step")
    # A cylinder, radius 10 mm, height 30 mm, along z from (0, 0, 0).
    cyl = BRepPrimAPI_MakeCylinder(10, 30).Shape()
    write(cyl, f"{folder}/cylinder.step")
    # A torus about z, major radius 30 mm, minor 8 mm.
    tor = BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 30, 8).Shape()
    write(tor, f"{folder}/torus.step")
    # A box written in inches (same geometry in mm as box.step).
    write(box, f"{folder}/inch_box.step", unit="INCH")
    # An assembly: one 20 x 10 x 5 mm box part placed twice (moved 100 mm along x; moved 50 mm
    # along y and turned 90 degrees about z), through XCAF so the file has the product structure.
    from OCP.TDocStd import TDocStd_Document
    from OCP.TCollection import TCollection_ExtendedString
    from OCP.XCAFDoc import XCAFDoc_DocumentTool
    from OCP.STEPCAFControl import STEPCAFControl_Writer

    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    tool = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    part = BRepPrimAPI_MakeBox(20, 10, 5).Shape()
    assy = tool.NewShape()
    part_label = tool.AddShape(part, False)
    t1 = gp_Trsf()
    t1.SetTranslation(gp_Vec(100, 0, 0))
    t2 = gp_Trsf()
    t2.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), math.pi / 2)
    t3 = gp_Trsf()
    t3.SetTranslation(gp_Vec(0, 50, 0))
    tool.AddComponent(assy, part_label, TopLoc_Location(t1))
    tool.AddComponent(assy, part_label, TopLoc_Location(t3.Multiplied(t2)))
    tool.UpdateAssemblies()
    Interface_Static.SetCVal_s("write.step.unit", "MM")
    w = STEPCAFControl_Writer()
    w.Transfer(doc, STEPControl_AsIs)
    if w.Write(f"{folder}/assembly.step") != IFSelect_RetDone:
        raise SystemExit("assembly.step: OCCT cannot write it")
    colours(folder)


def colours(folder):
    # Two parts coloured through XCAF: a 20 x 10 x 5 mm box, sRGB (0.8, 0.4, 0.2) (OCCT writes
    # COLOUR_RGB); a cylinder of radius 10 mm and height 10 mm standing on (50, 0, 0), white, its
    # top face blue (OCCT writes DRAUGHTING_PRE_DEFINED_COLOURs and an OVER_RIDING_STYLED_ITEM).
    from OCP.TDocStd import TDocStd_Document
    from OCP.TCollection import TCollection_ExtendedString
    from OCP.XCAFDoc import XCAFDoc_DocumentTool, XCAFDoc_ColorSurf
    from OCP.STEPCAFControl import STEPCAFControl_Writer
    from OCP.Quantity import Quantity_Color, Quantity_TOC_RGB, Quantity_TOC_sRGB
    from OCP.TopAbs import TopAbs_FACE
    from OCP.BRepAdaptor import BRepAdaptor_Surface
    from OCP.GeomAbs import GeomAbs_Plane

    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    shapes = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    colours = XCAFDoc_DocumentTool.ColorTool_s(doc.Main())
    box = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 20, 10, 5).Shape()
    cyl = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(50, 0, 0), gp_Dir(0, 0, 1)), 10, 10).Shape()
    box_label = shapes.AddShape(box, False)
    cyl_label = shapes.AddShape(cyl, False)
    colours.SetColor(box_label, Quantity_Color(0.8, 0.4, 0.2, Quantity_TOC_sRGB), XCAFDoc_ColorSurf)
    colours.SetColor(cyl_label, Quantity_Color(1.0, 1.0, 1.0, Quantity_TOC_RGB), XCAFDoc_ColorSurf)
    exp = TopExp_Explorer(cyl, TopAbs_FACE)
    while exp.More():
        face = TopoDS.Face(exp.Current())
        if BRepAdaptor_Surface(face).GetType() == GeomAbs_Plane:
            props = GProp_GProps()
            BRepGProp.SurfaceProperties_s(face, props)
            if props.CentreOfMass().Z() > 5:
                top = shapes.AddSubShape(cyl_label, face)
                colours.SetColor(top, Quantity_Color(0.0, 0.0, 1.0, Quantity_TOC_RGB), XCAFDoc_ColorSurf)
        exp.Next()
    Interface_Static.SetCVal_s("write.step.unit", "MM")
    w = STEPCAFControl_Writer()
    w.Transfer(doc, STEPControl_AsIs)
    if w.Write(f"{folder}/colours.step") != IFSelect_RetDone:
        raise SystemExit("colours.step: OCCT cannot write it")


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "measure":
        measure(sys.argv[2], sys.argv[3:])
    elif len(sys.argv) == 3 and sys.argv[1] == "generate":
        generate(sys.argv[2])
    else:
        raise SystemExit(__doc__)
