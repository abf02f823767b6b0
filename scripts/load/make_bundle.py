#!/usr/bin/env python3
"""Writes a synthetic first-generation SimMechanics bundle (zip) for load tests: a chain of N
bodies hung by revolute joints, each with a binary STL mesh, padded to about TARGET_MB.

usage: make_bundle.py OUT.zip [BODIES] [TARGET_MB]"""
import io, math, struct, sys, zipfile

def frame(name, node, ref, pos):
    r = f' ref="{ref}"' if ref else ""
    return (f'<Frame{r}><name>"{name}"</name><displayName>""</displayName><nodeID>"{node}"</nodeID>'
            f'<position>{pos[0]},{pos[1]},{pos[2]}</position><positionOrigin>"WORLD"</positionOrigin>'
            f'<positionReferenceFrame>"WORLD"</positionReferenceFrame><positionUnits>"mm"</positionUnits>'
            f'<orientation>1,0,0,0,1,0,0,0,1</orientation><orientationType>"3x3 Transform"</orientationType>'
            f'<orientationUnits>"rad"</orientationUnits><orientationReferenceFrame>"WORLD"</orientationReferenceFrame></Frame>')

def body(name, node, mass, frames, stl):
    return (f'<Body><name>"{name}"</name><nodeID>"{node}"</nodeID><status>""</status><mass>{mass}</mass>'
            f'<massUnits>"kg"</massUnits><inertia>0.001,0,0,0,0.002,0,0,0,0.0025</inertia><inertiaUnits>"kg*m^2"</inertiaUnits>'
            f'<volume>{mass / 2700 * 1e9}</volume><volumeUnits>"mm^3"</volumeUnits><surfaceArea>1000</surfaceArea>'
            f'<surfaceAreaUnits>"mm^2"</surfaceAreaUnits><frames>{"".join(frames)}</frames>'
            f'<geometryFileName>"{stl}"</geometryFileName></Body>')

def joint(name, node, base, follower, kind, axis):
    return (f'<SimpleJoint><name>"{name}"</name><nodeID>"{node}"</nodeID><status>""</status>'
            f'<base><JointSide><name>""</name><connection><Frame ref="{base}"></Frame></connection></JointSide></base>'
            f'<follower><JointSide><name>""</name><connection><Frame ref="{follower}"></Frame></connection></JointSide></follower>'
            f'<primitives><Primitive><name>"{kind}"</name><nodeID>""</nodeID><referenceFrame>"WORLD"</referenceFrame>'
            f'<axis>{axis}</axis></Primitive></primitives></SimpleJoint>')

def stl(triangles, seed):
    out = io.BytesIO()
    out.write(b"load test mesh".ljust(80, b" "))
    out.write(struct.pack("<I", triangles))
    for i in range(triangles):
        a = (i * 0.01 + seed) % 6.283
        p = [(10 * math.cos(a), 10 * math.sin(a), i * 0.001), (10 * math.cos(a + 0.1), 10 * math.sin(a + 0.1), i * 0.001), (0, 0, i * 0.001 + 1)]
        out.write(struct.pack("<12fH", 0, 0, 1, *p[0], *p[1], *p[2], 0))
    return out.getvalue()

def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 30
    target = float(sys.argv[3]) if len(sys.argv) > 3 else 5.0
    tris = max(12, int(target * 1e6 / n / 50))
    bodies, joints, files = [], [], {}
    bodies.append(body("RootPart", "LOAD/RootPart", 0,
                       [frame("CG", "R::CG", 0, (0, 0, 0)), frame("CS1", "R::CS1", 0, (0, 0, 0)),
                        frame("CS2", "R::G", 1, (0, 0, 0)), frame("CS3", "R::0", 2, (0, 0, 0))], ""))
    joints.append(joint("RootGround--RootPart", "RootGround:-:LOAD/RootPart", 3, 1, "weld", "0.57735,0.57735,0.57735"))
    ref = 4
    prev = 2
    for i in range(n):
        x = 100.0 * i
        parent_ref, child_ref = ref, ref + 1
        ref += 2
        frames = [frame("CG", f"{i}::CG", 0, (x + 50, 0, 0)), frame("CS1", f"{i}::CS1", 0, (x, 0, 0)),
                  frame("CS2", f"{i}::parent", parent_ref, (x, 0, 0)), frame("CS3", f"{i}::child", child_ref, (x + 100, 0, 0))]
        name = f"LINK_{i}"
        bodies.append(body(name, str(100 + i), 1.0 + i * 0.1, frames, f"{name}_prt.stl"))
        base_name = "RootPart" if i == 0 else f"LINK_{i - 1}"
        joints.append(joint(f"{base_name}--{name}", f"{i}:-:j", prev, parent_ref, "revolute", ["0,0,1", "0,1,0"][i % 2]))
        prev = child_ref
        files[f"meshes/{name.lower()}_prt.stl"] = stl(tris, i)
    ground = frame("CS1", "RootGround::CS1", 3, (0, 0, 0))
    xml = ('<?xml version="1.0" encoding="UTF-8" standalone="no" ?>\n<PhysicalModelingXMLFile>'
           '<formatVersion>"1.0.4"</formatVersion><createdUsing>"cad2mo load generator"</createdUsing>'
           '<createdFrom>"generated"</createdFrom><createdOn>"01/01/26||00:00:00"</createdOn><createdBy>"load"</createdBy>'
           f'<name>"LOAD"</name><SimMechanics><name>"LOAD"</name><nodeID>"LOAD"</nodeID><bodies>{"".join(bodies)}</bodies>'
           f'<joints>{"".join(joints)}</joints><grounds><Ground><name>"RootGround"</name><nodeID>"RootGround"</nodeID>'
           f'<frame>{ground}</frame></Ground></grounds><subsystems></subsystems></SimMechanics></PhysicalModelingXMLFile>\n')
    with zipfile.ZipFile(out, "w", zipfile.ZIP_STORED) as z:
        z.writestr("LOAD.xml", xml)
        for k, v in files.items():
            z.writestr(k, v)

main()
