#!/usr/bin/env python3
"""An independent closed-loop simulation of joint drives, for the cad2mo cross-check
(tests/simulation.rs): scipy's solve_ivp (DOP853) over Pinocchio's rigid-body dynamics, with the
drive equations typed from the Modelica classes cad2mo writes
(engine/src/pipeline/back/modelica/mechatronics/classes.rs):

  CascadePPI:        w_cmd = kp*(ratio*q_ref - phi_motor) + ratio*qd_ref
                     i_ref = ks*(e + x/Ts),  der(x) = e,  e = w_cmd - w_motor
  DCPermanentMagnet: i_cmd = limit(i_ref, -I_max, I_max)
                     v_cmd = R*i_cmd + k*w + L/Tc*(i_cmd - i)
                     v     = limit(v_cmd, -V_max, V_max)
                     L*der(i) = v - R*i - k*w,   J*der(w) = k*i - d*w - tau_a
  Gear (Ideal / LossyGear lossTable=[0, eta, eta, 0, 0]):
                     phi_motor = ratio*q,  joint torque = eta*ratio*tau_a while tau_a*w >= 0
                     (power from the motor to the joint), ratio*tau_a/eta otherwise.

The rotor inertia seen through the gear is an armature J*ratio^2 (times eta or 1/eta) on the
joint; the mass matrix comes from Pinocchio's CRBA with that armature added, the bias forces
from its nle (so the armature enters explicitly, not through model.armature). The direction of
power flow depends on the acceleration: it starts from the sign of (k*i - d*w)*w and drives
whose tau_a*w disagrees switch, at most 4 passes (the same rule as cad2mo's, stated in its
simulation module).

Usage: drive_check.py IN.json OUT.json
IN: {"urdf": text, "gravity": [x,y,z], "joints": [names in state order], "q0": [...],
     "drives": [{"joint": name, "R","L","k","J","d","V_max","I_max","Tc","kp","ks","Ts","ratio","eta",
                 "t": [...], "q": [...], "qd": [...]}], "duration": s, "times": [output times]}
OUT: {"q": [[per joint] per output time], "i": [[per drive] per output time]}
Exit code 3 when pinocchio or scipy cannot be imported.
"""
import json
import sys
import xml.etree.ElementTree as ET

try:
    import numpy as np
    import pinocchio as pin
    from scipy.integrate import solve_ivp
except ImportError as e:  # pragma: no cover
    print(f"NOTICE: {e}")
    sys.exit(3)


def main():
    spec = json.load(open(sys.argv[1]))
    root = ET.fromstring(spec["urdf"])
    for parent in list(root.iter()):
        for child in list(parent):
            if child.tag in ("visual", "collision", "gazebo", "transmission", "sensor"):
                parent.remove(child)
    model = pin.buildModelFromXML(ET.tostring(root, encoding="unicode"))
    model.gravity.linear[:] = spec["gravity"]
    data = model.createData()
    names = spec["joints"]
    n = len(names)
    for name in names:
        j = model.joints[model.getJointId(name)]
        if j.nq != 1 or j.nv != 1:
            raise SystemExit(f"joint {name}: only 1-dof joints")
    iq = [model.joints[model.getJointId(name)].idx_q for name in names]
    iv = [model.joints[model.getJointId(name)].idx_v for name in names]
    drives = spec["drives"]
    dc = [names.index(d["joint"]) for d in drives]
    nd = len(drives)

    def rhs(t, y):
        q = pin.neutral(model)
        v = np.zeros(model.nv)
        for a in range(n):
            q[iq[a]] = y[a]
            v[iv[a]] = y[n + a]
        dy = np.zeros_like(y)
        sig = []
        forward = []
        for k, d in enumerate(drives):
            r = d["ratio"]
            i, x = y[2 * n + 2 * k], y[2 * n + 2 * k + 1]
            phi, w = r * y[dc[k]], r * y[n + dc[k]]
            q_ref = np.interp(t, d["t"], d["q"])
            qd_ref = np.interp(t, d["t"], d["qd"])
            e = d["kp"] * (r * q_ref - phi) + r * qd_ref - w
            i_ref = d["ks"] * (e + x / d["Ts"])
            i_cmd = min(max(i_ref, -d["I_max"]), d["I_max"])
            v_cmd = d["R"] * i_cmd + d["k"] * w + d["L"] / d["Tc"] * (i_cmd - i)
            volt = min(max(v_cmd, -d["V_max"]), d["V_max"])
            dy[2 * n + 2 * k] = (volt - d["R"] * i - d["k"] * w) / d["L"]
            dy[2 * n + 2 * k + 1] = e
            sig.append((i, w))
            forward.append((d["k"] * i - d["d"] * w) * w >= 0.0)
        M = pin.crba(model, data, q)
        M = np.triu(M) + np.triu(M, 1).T
        nle = pin.nonLinearEffects(model, data, q, v)
        for _ in range(4):
            tau = np.zeros(model.nv)
            Ma = M.copy()
            for k, d in enumerate(drives):
                i, w = sig[k]
                f = 1.0 if d["eta"] >= 1.0 else (d["eta"] if forward[k] else 1.0 / d["eta"])
                tau[iv[dc[k]]] += f * d["ratio"] * (d["k"] * i - d["d"] * w)
                Ma[iv[dc[k]], iv[dc[k]]] += f * d["J"] * d["ratio"] ** 2
            a = np.linalg.solve(Ma, tau - nle)
            changed = False
            for k, d in enumerate(drives):
                if d["eta"] >= 1.0:
                    continue
                i, w = sig[k]
                tau_a = d["k"] * i - d["d"] * w - d["J"] * d["ratio"] * a[iv[dc[k]]]
                fw = tau_a * w >= 0.0
                if fw != forward[k]:
                    forward[k] = fw
                    changed = True
            if not changed:
                break
        for b in range(n):
            dy[b] = y[n + b]
            dy[n + b] = a[iv[b]]
        return dy

    y0 = np.zeros(2 * n + 2 * nd)
    y0[:n] = spec["q0"]
    sol = solve_ivp(rhs, (0.0, spec["duration"]), y0, method="DOP853", t_eval=spec["times"], rtol=1e-12, atol=1e-12)
    if not sol.success:
        raise SystemExit(f"solve_ivp: {sol.message}")
    out = {"q": [[float(sol.y[a, s]) for a in range(n)] for s in range(len(sol.t))],
           "i": [[float(sol.y[2 * n + 2 * k, s]) for k in range(nd)] for s in range(len(sol.t))],
           "nfev": int(sol.nfev)}
    json.dump(out, open(sys.argv[2], "w"))


if __name__ == "__main__":
    main()
