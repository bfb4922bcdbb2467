#!/usr/bin/python3
"""Independent Python reference for the gyro calibrations of numeric/gyro/ on the public logs.

Written apart from the C++ code, so the two can be compared (tests/gyro/public_logs_test.cpp):
- hand rotations (the Xsens pair of IMU-TK, the MPU-6050 log of tomisuarez2/ImuCalibration): the
  accelerometer's still poses and scalar fit from real_data_fit.py (its own detector, T upper
  triangular), gravity's direction at each pose, then the gyro's C (3x3) and o fitted so that the
  gyro, integrated from pose to pose with IMU-TK's RK4 scheme (not scalcal's exponential map), turns
  each direction into the next; the rests' mean outputs observe o; each pair's residual (its two
  components across the measured direction) divided by the predicted noise (the gyro's white noise
  integrated over the motion, both directions' scatter), each rest's by its mean's; then each group
  rescaled by its chi-square per degree of freedom (at least 1) and refitted, as grouped_least_squares.hpp
  documents; scipy.optimize.least_squares with its own finite differences.
- known turns (imucal's Ferraris session): the three whole turns as imucal's own annotation gives
  them (example_ferraris_session_list.json), not scalcal's detection; the bias from this script's
  rests; |diag(1/k) (integral / T - o)| = angle / T for axis6.
Run with Debian's /usr/bin/python3 (NumPy + SciPy); deterministic, no network. `--json` prints one
object. The logs are looked for in data/, ../shared/data/ and SCALCAL_REAL_DATA (gyro columns of the
public logs: see docs/gyro.md for how they are extracted from their sources).
"""
import argparse
import json
import os
import sys

import numpy as np
from scipy.optimize import least_squares

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from real_data_fit import DATA_DIRS, find, fit as acc_fit, static_intervals, unpack  # noqa: E402

# IMU-TK's RK4 on the unit quaternion (imu_tk/integration.h), batched over parameter sets.
def skew4(w):
    """(..., 3) -> (..., 4, 4): the quaternion rate matrix of imu_tk's computeOmegaSkew."""
    z = np.zeros(w.shape[:-1])
    x, y, v = w[..., 0], w[..., 1], w[..., 2]
    return np.stack([np.stack([z, -x, -y, -v], -1), np.stack([x, z, v, -y], -1),
                     np.stack([y, -v, z, x], -1), np.stack([v, y, -x, z], -1)], -2)


def rk4_rotation(W, dt):
    """W: (sets, n, 3) rates, dt: (n - 1,). Rotation matrices (sets, 3, 3), body at start to body at end."""
    q = np.zeros(W.shape[:1] + (4,))
    q[:, 0] = 1
    for i in range(W.shape[1] - 1):
        w0, w1 = W[:, i], W[:, i + 1]
        wm, h = 0.5 * (w0 + w1), dt[i]
        S0, Sm, S1 = skew4(w0), skew4(wm), skew4(w1)
        k1 = 0.5 * np.einsum("sij,sj->si", S0, q)
        k2 = 0.5 * np.einsum("sij,sj->si", Sm, q + 0.5 * h * k1)
        k3 = 0.5 * np.einsum("sij,sj->si", Sm, q + 0.5 * h * k2)
        k4 = 0.5 * np.einsum("sij,sj->si", S1, q + h * k3)
        q = q + h * (k1 + 2 * k2 + 2 * k3 + k4) / 6
        q /= np.linalg.norm(q, axis=1)[:, None]
    w, x, y, z = q.T
    return np.stack([np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
                     np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
                     np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1)], -2)


def tangent(g):
    k = int(np.argmin(np.abs(g)))
    e1 = np.cross(g, np.eye(3)[k])
    e1 /= np.linalg.norm(e1)
    return np.vstack([e1, np.cross(g, e1)])


def load_log(path, rate):
    """Time and (n, 3): a text log (t x y z) or a CSV with ix, iy, iz (time k / rate)."""
    with open(path) as f:
        first = f.readline()
    head = first.strip()
    if head and (head[0].isdigit() or head[0] in "+-."):
        d = np.loadtxt(path)
        return d[:, 0], d[:, 1:4]
    header = first.strip().split(",")
    d = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    x = d[:, [header.index(c) for c in ("ix", "iy", "iz")]]
    return np.arange(len(x)) / rate, x


def hand_rotations(acc_file, gyro_file, rate, g, acc_model):
    t, a = load_log(find(acc_file), rate)
    _, w = load_log(find(gyro_file), rate)
    iv, _, _ = static_intervals(t, a)
    means = np.array([a[i:j + 1].mean(axis=0) for i, j in iv])
    res, _ = acc_fit(means, g, acc_model)
    o_a, T_a = unpack(res.x, acc_model)
    grav, gstd, rests = [], [], []
    for i, j in iv:
        c = (a[i:j + 1] - o_a) @ T_a.T
        m = c.mean(axis=0)
        grav.append(m / np.linalg.norm(m))
        gstd.append(np.sqrt(((c - m) ** 2).sum() / (3 * (len(c) - 1))) / (np.linalg.norm(m) * np.sqrt(len(c))))
        s = w[i:j + 1]
        rests.append((s.mean(axis=0), s.std(axis=0, ddof=1), len(s)))
    pairs = [(iv[k][1], iv[k + 1][0]) for k in range(len(iv) - 1)]
    E = [tangent(grav[k + 1]) for k in range(len(pairs))]
    o0 = np.mean([r[0] for r in rests], axis=0)
    rate_noise = np.median([r[1].mean() for r in rests])

    def residuals(P, scales):
        """P: (sets, 12) -> (sets, rows)."""
        out = []
        for k, (i, j) in enumerate(pairs):
            C = P[:, :9].reshape(-1, 3, 3)
            W = np.einsum("sab,snb->sna", C, w[i:j + 1][None] - P[:, None, 9:])
            R = rk4_rotation(W, np.diff(t[i:j + 1]))
            pred = np.einsum("sba,b->sa", R, grav[k])
            out.append((pred - grav[k + 1]) @ E[k].T / (sigma[k] * np.sqrt(scales[0])))
        for m, sd, n in rests:
            out.append((m - P[:, 9:]) * np.sqrt(n) / sd / np.sqrt(scales[1]))
        return np.concatenate(out, axis=1)

    # The start: scalcal's is its own search; this one starts from the nominal gain on the identity
    # (both logs' gyros are labelled as their accelerometers).
    gain = {"xsens_gyro.txt": 1 / 4778.0, "mpu6050_gyro.csv": np.pi / 180 / 131.0}[gyro_file]
    p = np.concatenate([(gain * np.eye(3)).ravel(), o0])
    walk = np.array([np.sum(np.diff(t[i:j + 1]) ** 2) for i, j in pairs])
    sigma = np.sqrt((gain * rate_noise) ** 2 * walk +
                    np.array(gstd[:-1]) ** 2 + np.array(gstd[1:]) ** 2)
    scale = np.array([1.0, 1.0])
    step = np.concatenate([np.full(9, 1e-4 * gain), np.full(3, 1e-2)])

    def jac(q, s):
        Q = np.vstack([q + np.diag(step), q - np.diag(step)])
        r = residuals(Q, s)
        return ((r[:12] - r[12:]) / (2 * step[:, None])).T

    npairs = 2 * len(pairs)
    for _ in range(8):
        sol = least_squares(lambda q: residuals(q[None], scale)[0], p, jac=lambda q: jac(q, scale),
                            x_scale=np.concatenate([np.full(9, gain), np.ones(3)]), xtol=1e-12, ftol=1e-12)
        p = sol.x
        J = jac(p, scale)
        r = residuals(p[None], scale)[0]
        S = np.linalg.solve(J.T @ J, J.T)
        h = np.einsum("ij,ji->i", J, S)
        new = scale.copy()
        for grp, rows in ((0, slice(0, npairs)), (1, slice(npairs, None))):
            chi2 = np.sum(r[rows] ** 2) * scale[grp]
            dof = np.sum(1 - h[rows])
            new[grp] = max(1.0, chi2 / dof)
        done = np.all(np.abs(new / scale - 1) < 1e-3)
        scale = new
        if done:
            break
    J = jac(p, scale)
    cov = np.linalg.inv(J.T @ J)
    C, o = p[:9].reshape(3, 3), p[9:]
    W = [(w[i:j + 1] - o) @ C.T for i, j in pairs]
    ang = []
    for k, (i, j) in enumerate(pairs):
        R = rk4_rotation(W[k][None], np.diff(t[i:j + 1]))[0]
        pr = R.T @ grav[k]
        ang.append(np.arctan2(np.linalg.norm(np.cross(pr, grav[k + 1])), pr @ grav[k + 1]))
    return {"acc_file": acc_file, "gyro_file": gyro_file, "poses": len(iv), "acc_model": acc_model,
            "acc_offset": o_a.tolist(), "acc_matrix": T_a.tolist(), "matrix": C.tolist(), "offset": o.tolist(),
            "standard_error": np.sqrt(np.diag(cov)).tolist(), "scales": scale.tolist(),
            "misfit_rms_deg": float(np.degrees(np.sqrt(np.mean(np.square(ang))))), "nfev": int(sol.nfev)}


def ferraris_turns(gyro_file, rate, annotation):
    t, w = load_log(find(gyro_file), rate)
    iv, _, _ = static_intervals(t, w)
    rests = [(w[i:j + 1].mean(axis=0), w[i:j + 1].std(axis=0, ddof=1), j - i + 1) for i, j in iv]
    o_rest = np.sum([m * n / sd ** 2 for m, sd, n in rests], axis=0) / np.sum([n / sd ** 2 for m, sd, n in rests], axis=0)
    turns, annotated = [], []
    for axis in ("x_rot", "y_rot", "z_rot"):
        a, b = annotation[axis]["start"], annotation[axis]["end"]
        seg = w[a:b + 1]
        annotated.append(np.sum(0.5 * (seg[1:] + seg[:-1]), axis=0) / rate)
        # The whole motion: from the end of this script's last rest before the annotated turn to the
        # start of its first rest after it (imucal's annotation trims the turn's slow start and stop).
        a = max(j for i, j in iv if j <= a)
        b = min(i for i, j in iv if i >= b)
        seg = w[a:b + 1]
        turns.append((np.sum(0.5 * (seg[1:] + seg[:-1]), axis=0) / rate, (b - a) / rate))
    # axis6 with the offset from the rests (weighted mean): each turn gives one gain, solved jointly.
    def r(k):
        return np.array([np.linalg.norm((I - T * o_rest) / k) - 2 * np.pi for I, T in turns])
    sol = least_squares(r, np.full(3, 57.3), xtol=1e-15, ftol=1e-15, gtol=1e-15, method="lm")
    trimmed = least_squares(lambda k: np.array([np.linalg.norm((I - (annotation[ax]["end"] - annotation[ax]["start"]) / rate
                                                                  * o_rest) / k) - 2 * np.pi
                                                for I, ax in zip(annotated, ("x_rot", "y_rot", "z_rot"))]),
                            np.full(3, 57.3), xtol=1e-15, ftol=1e-15, gtol=1e-15, method="lm")
    return {"gyro_file": gyro_file, "rests": len(iv), "offset": o_rest.tolist(), "gain": sol.x.tolist(),
            "turn_spans_s": [T for _, T in turns], "turn_integrals": [I.tolist() for I, _ in turns],
            "gain_annotated_windows": trimmed.x.tolist()}


FERRARIS_ANNOTATION = {"x_rot": {"start": 6770, "end": 7093}, "y_rot": {"start": 8081, "end": 8405},
                       "z_rot": {"start": 9205, "end": 9512}}


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args()
    out = {}
    if find("xsens_gyro.txt"):
        out["xsens"] = hand_rotations("xsens_acc.txt", "xsens_gyro.txt", None, 9.81744, "paper9")
    if find("mpu6050_gyro.csv"):
        out["mpu6050"] = hand_rotations("mpu6050_acc.csv", "mpu6050_gyro.csv", 100.0, 9.80665, "axis6")
    if find("nilspod_ferraris_gyro.csv"):
        out["nilspod_ferraris"] = ferraris_turns("nilspod_ferraris_gyro.csv", 102.4, FERRARIS_ANNOTATION)
    print(json.dumps(out, indent=1) if a.json else out)


if __name__ == "__main__":
    main()
