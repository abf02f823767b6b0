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
  ServoMotor:        i_cmd = limit(i_ref, -I_max, I_max)
                     Tc*der(i) = i_cmd - i,      J*der(w) = k*i - tau_a
  Gear (Ideal / LossyGear lossTable=[0, eta, eta, 0, 0]):
                     phi_motor = ratio*q,  joint torque = eta*ratio*tau_a while tau_a*w >= 0
                     (power from the motor to the joint), ratio*tau_a/eta otherwise.

The rotor inertia seen through the gear is an armature J*ratio^2 (times eta or 1/eta) on the
joint; the mass matrix comes from Pinocchio's CRBA with that armature added, the bias forces
from its nle.

The limiters and the gear's direction of power flow are modes: each solve_ivp call integrates
with the modes fixed and stops at the first zero crossing (terminal event, in the direction that
leaves the mode) of a limiter's input minus its limit or of tau_a*w; the mode switches there and
the integration restarts. Calls also end at the reference's samples (where the linearly
interpolated reference kinks), so no step crosses a kink.

Usage: drive_check.py IN.json OUT.json
IN: {"urdf": text, "gravity": [x,y,z], "joints": [names in state order], "q0": [...],
     "drives": [{"joint": name, "motor": "dc"|"servo", "R","L","k","J","d","V_max","I_max","Tc",
                 "kp","ks","Ts","ratio","eta", "t": [...], "q": [...], "qd": [...]}],
     "duration": s, "times": [output times], "rtol": r, "atol": a}
OUT: {"q": [[per joint] per output time], "i": [[per drive] per output time], "nfev": n,
      "events": n}
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
    # modes[k] = [current limiter (-1, 0, 1), voltage limiter (-1, 0, 1), power flows backward]
    modes = [[0, 0, False] for _ in drives]

    def lim(x, m, mode):
        return m if mode == 1 else (-m if mode == -1 else x)

    def evaluate(t, y):
        """dy and the switching functions g[k] = [i_ref - I_max, i_ref + I_max, v_cmd - V_max,
        v_cmd + V_max, tau_a*w] in the current modes."""
        q = pin.neutral(model)
        v = np.zeros(model.nv)
        for a in range(n):
            q[iq[a]] = y[a]
            v[iv[a]] = y[n + a]
        dy = np.zeros_like(y)
        g = []
        tau = np.zeros(model.nv)
        M = pin.crba(model, data, q)
        M = np.triu(M) + np.triu(M, 1).T
        nle = pin.nonLinearEffects(model, data, q, v)
        sig = []
        for k, d in enumerate(drives):
            r = d["ratio"]
            i, x = y[2 * n + 2 * k], y[2 * n + 2 * k + 1]
            phi, w = r * y[dc[k]], r * y[n + dc[k]]
            q_ref = np.interp(t, d["t"], d["q"])
            qd_ref = np.interp(t, d["t"], d["qd"])
            e = d["kp"] * (r * q_ref - phi) + r * qd_ref - w
            i_ref = d["ks"] * (e + x / d["Ts"])
            i_cmd = lim(i_ref, d["I_max"], modes[k][0])
            if d["motor"] == "servo":
                v_cmd = 0.0
                dy[2 * n + 2 * k] = (i_cmd - i) / d["Tc"]
                gk = [i_ref - d["I_max"], i_ref + d["I_max"], -1.0, 1.0]
                fric = 0.0
            else:
                v_cmd = d["R"] * i_cmd + d["k"] * w + d["L"] / d["Tc"] * (i_cmd - i)
                volt = lim(v_cmd, d["V_max"], modes[k][1])
                dy[2 * n + 2 * k] = (volt - d["R"] * i - d["k"] * w) / d["L"]
                gk = [i_ref - d["I_max"], i_ref + d["I_max"], v_cmd - d["V_max"], v_cmd + d["V_max"]]
                fric = d["d"]
            dy[2 * n + 2 * k + 1] = e
            f = 1.0 if d["eta"] >= 1.0 else (1.0 / d["eta"] if modes[k][2] else d["eta"])
            tau[iv[dc[k]]] += f * r * (d["k"] * i - fric * w)
            M[iv[dc[k]], iv[dc[k]]] += f * d["J"] * r ** 2
            g.append(gk)
            sig.append((i, w, fric))
        acc = np.linalg.solve(M, tau - nle)
        for k, d in enumerate(drives):
            i, w, fric = sig[k]
            g[k].append(0.0 if d["eta"] >= 1.0 else (d["k"] * i - fric * w - d["J"] * d["ratio"] * acc[iv[dc[k]]]) * w)
        for b in range(n):
            dy[b] = y[n + b]
            dy[n + b] = acc[iv[b]]
        return dy, g

    nfev = [0]

    def rhs(t, y):
        nfev[0] += 1
        return evaluate(t, y)[0]

    def events_of_modes():
        """Terminal events leaving the current modes: (function, new mode entry)."""
        evs = []
        for k, d in enumerate(drives):
            for slot, (hi, lo) in ((0, (0, 1)), (1, (2, 3))):
                if slot == 1 and d["motor"] == "servo":
                    continue
                m = modes[k][slot]
                cands = []
                if m == 0:
                    cands = [(hi, 1, 1), (lo, -1, -1)]
                elif m == 1:
                    cands = [(hi, -1, 0)]
                else:
                    cands = [(lo, 1, 0)]
                for idx, direction, new in cands:
                    evs.append((k, idx, direction, (k, slot, new)))
            if d["eta"] < 1.0:
                back = modes[k][2]
                evs.append((k, 4, 1 if back else -1, (k, 2, not back)))
        funcs = []
        for (k, idx, direction, change) in evs:
            def fn(t, y, k=k, idx=idx):
                return evaluate(t, y)[1][k][idx]
            fn.terminal = True
            fn.direction = direction
            funcs.append(fn)
        return funcs, [e[3] for e in evs]

    y = np.zeros(2 * n + 2 * nd)
    y[:n] = spec["q0"]
    # Initial modes from the signs at t = 0.
    _, g = evaluate(0.0, y)
    for k, d in enumerate(drives):
        modes[k][0] = 1 if g[k][0] > 0 else (-1 if g[k][1] < 0 else 0)
        modes[k][1] = 1 if g[k][2] > 0 else (-1 if g[k][3] < 0 else 0)
        modes[k][2] = d["eta"] < 1.0 and g[k][4] < 0
    T = spec["duration"]
    breaks = sorted({x for d in drives for x in d["t"] if 0.0 < x < T} | {T})
    times = spec["times"]
    out_q, out_i = [None] * len(times), [None] * len(times)
    t = 0.0
    events = 0
    while t < T:
        t_stop = next(b for b in breaks if b > t + 1e-13)
        funcs, changes = events_of_modes()
        sol = solve_ivp(rhs, (t, t_stop), y, method="DOP853", rtol=spec["rtol"], atol=spec["atol"],
                        dense_output=True, events=funcs)
        if sol.status < 0:
            raise SystemExit(f"solve_ivp at t = {t}: {sol.message}")
        t_end = float(sol.t[-1])
        for s, to in enumerate(times):
            if out_q[s] is None and to <= t_end + 1e-12 * max(1.0, abs(t_end)):
                ys = sol.sol(min(max(to, t), t_end))
                out_q[s] = [float(ys[a]) for a in range(n)]
                out_i[s] = [float(ys[2 * n + 2 * k]) for k in range(nd)]
        if sol.status == 1:
            fired = [(float(te[0]), j) for j, te in enumerate(sol.t_events) if len(te)]
            te, j = min(fired)
            k, slot, new = changes[j]
            modes[k][slot] = new
            y = sol.sol(te)
            t = te
            events += 1
            if events > 10000:
                raise SystemExit("over 10000 events: the modes chatter")
        else:
            y = sol.y[:, -1]
            t = t_end
    json.dump({"q": out_q, "i": out_i, "nfev": nfev[0], "events": events}, open(sys.argv[2], "w"))


if __name__ == "__main__":
    main()
