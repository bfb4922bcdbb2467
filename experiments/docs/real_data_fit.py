#!/usr/bin/python3
"""Independent Python reference for the scalar calibration of the real logs of data/.

Written separately from the C++ code so the two can be compared: its own static-interval detector
(the same idea as scalcal's: a moving variance against a noise floor taken from the log's quiet
windows, or from an initial still period), then a direct nonlinear least-squares fit of
|T (m_i - o)| = g on the interval means with scipy.optimize.least_squares, T upper triangular for
the 9-parameter model (paper9), diagonal for bias and scale only (axis6), a multiple of the
identity for offsets only (bias3). A magnetometer's tumbling log (every="sample") is fitted as MATLAB's
magcal fits one: every sample, then again without the samples beyond 5 robust scales of the residuals
(1.4826 times their median absolute value), until none is. Run with Debian's /usr/bin/python3 (NumPy +
SciPy).
Deterministic, no network. `--json` prints one object: per log, the intervals, the fit and the RMS.
"""
import argparse
import json
import os
import sys

import numpy as np
from scipy.optimize import least_squares

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DATA_DIRS = [os.path.join(ROOT, "data"), os.path.join(os.path.dirname(ROOT), "shared", "data")]
if os.environ.get("SCALCAL_REAL_DATA"):
    DATA_DIRS.append(os.environ["SCALCAL_REAL_DATA"])

# name: file, its columns, the sample rate (None: the file's time column), |I| (None: unknown,
# the fit maps to unit modulus), and the model scalcal's --model auto is expected to choose.
LOGS = {
    "xsens": dict(file="xsens_acc.txt", kind="text", rate=None, magnitude=9.81744, model="paper9"),
    "mpu6050": dict(file="mpu6050_acc.csv", kind="csv", rate=100.0, magnitude=9.80665, model="axis6"),
    "nilspod_ferraris": dict(file="nilspod_ferraris_acc.csv", kind="csv", rate=102.4, magnitude=9.80665,
                             model="axis6"),
    "qmc5883l": dict(file="qmc5883l_mag.csv", kind="csv", rate=50.0, magnitude=None, model="paper9", every="sample"),
}


def find(name):
    for d in DATA_DIRS:
        p = os.path.join(d, name)
        if os.path.exists(p):
            return p
    return None


def load(spec, path):
    """Time (seconds) and the (n, 3) raw outputs."""
    if spec["kind"] == "text":
        d = np.loadtxt(path)
        return d[:, 0], d[:, 1:4]
    with open(path) as f:
        header = f.readline().strip().split(",")
    d = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    x = d[:, [header.index(c) for c in ("ix", "iy", "iz")]]
    return np.arange(len(x)) / spec["rate"], x


def window_variance(x, window):
    """Norm of the per-axis variance over the window centred on each sample (NaN near the ends)."""
    x = x - x[0]
    c1 = np.vstack([np.zeros(3), np.cumsum(x, axis=0)])
    c2 = np.vstack([np.zeros(3), np.cumsum(x * x, axis=0)])
    m1 = (c1[window:] - c1[:-window]) / window
    m2 = (c2[window:] - c2[:-window]) / window
    v = np.linalg.norm(np.maximum(m2 - m1 * m1, 0.0), axis=1)
    out = np.full(len(x), np.nan)
    out[window // 2: window // 2 + len(v)] = v
    return out


def static_intervals(t, x, factor=6.0, window_s=1.0, min_s=1.0, still_s=0.0):
    """Runs of windows quieter than factor x the noise floor, at least min_s long."""
    period = np.median(np.diff(t))
    window = max(11, int(round(window_s / period)) | 1)
    v = window_variance(x, window)
    if still_s > 0:
        floor = np.linalg.norm(x[t <= t[0] + still_s].var(axis=0))
    else:
        finite = np.sort(v[np.isfinite(v)])
        low = finite[int(0.05 * (len(finite) - 1))]
        floor = np.median(finite[finite <= 3 * low])
    quiet = np.where(np.isfinite(v), v < factor * floor, False)
    edges = np.diff(np.concatenate(([0], quiet.astype(np.int8), [0])))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1) - 1
    need = int(np.ceil(min_s / period))
    return [(a, b) for a, b in zip(starts, ends) if b - a + 1 >= need], floor, window


def unpack(p, model):
    o = p[:3]
    T = np.zeros((3, 3))
    if model == "bias3":
        T[np.diag_indices(3)] = np.exp(p[3])
    else:
        T[np.diag_indices(3)] = np.exp(p[3:6])
    if model == "paper9":
        T[0, 1], T[0, 2], T[1, 2] = p[6:9]
    return o, T


def fit(means, g, model):
    """|T (m_i - o)| = g by nonlinear least squares on the relative error, from the half-range start."""
    lo, hi = means.min(axis=0), means.max(axis=0)
    o0, s0 = (lo + hi) / 2, np.log(g / ((hi - lo) / 2))
    p0 = {"paper9": np.concatenate([o0, s0, np.zeros(3)]), "axis6": np.concatenate([o0, s0]),
          "bias3": np.concatenate([o0, [s0.mean()]])}[model]

    def relative(p):
        o, T = unpack(p, model)
        return (np.linalg.norm((means - o) @ T.T, axis=1) - g) / g

    res = least_squares(relative, p0, x_scale="jac", xtol=1e-15, ftol=1e-15, gtol=1e-15, method="lm")
    return res, relative(res.x)


def design_condition(directions, model):
    x, y, z = directions.T
    cols = [x, y, z] + ([x * x, y * y, z * z] if model != "bias3" else []) + ([x * y, y * z, z * x] if model == "paper9" else [])
    H = np.column_stack(cols)
    e = np.linalg.eigvalsh(H.T @ H)
    return float(e[-1] / e[0])


def run_every_sample(spec, t, x):
    """A tumbling magnetometer's log: every sample a position, the outliers left out until none is."""
    g = spec["magnitude"] or 1.0
    keep = np.ones(len(x), dtype=bool)
    for _ in range(10):
        res, rel = fit(x[keep], g, spec["model"])
        o, T = unpack(res.x, spec["model"])
        rel_all = (np.linalg.norm((x - o) @ T.T, axis=1) - g) / g
        scale = 1.4826 * np.median(np.abs(rel_all[keep]))
        new = np.abs(rel_all) <= 5 * scale
        if np.array_equal(new, keep):
            break
        keep = new
    return {
        "file": spec["file"], "rate": spec["rate"], "magnitude": spec["magnitude"], "model": spec["model"],
        "every": "sample", "rows": int(len(x)), "samples_used": int(keep.sum()), "intervals": int(keep.sum()),
        "offset": o.tolist(), "matrix": T.tolist(), "gains_geometric_mean": float(np.linalg.det(T) ** (-1 / 3)),
        "rms_means_relative": float(np.sqrt(np.mean(rel_all[keep] ** 2))),
        "nfev": int(res.nfev), "status": int(res.status),
    }


def run(name, spec):
    path = find(spec["file"])
    if path is None:
        return {"file": spec["file"], "missing": True}
    t, x = load(spec, path)
    keep = np.all(np.isfinite(x), axis=1)
    if spec.get("every") == "sample":
        return run_every_sample(spec, t[keep], x[keep])
    iv, floor, window = static_intervals(t[keep], x[keep])
    x = x[keep]
    means = np.array([x[a:b + 1].mean(axis=0) for a, b in iv])
    g = spec["magnitude"] or 1.0
    res, rel = fit(means, g, spec["model"])
    o, T = unpack(res.x, spec["model"])
    directions = (means - o) @ T.T
    directions /= np.linalg.norm(directions, axis=1)[:, None]
    return {
        "file": spec["file"], "rate": spec["rate"], "magnitude": spec["magnitude"], "model": spec["model"],
        "rows": int(len(x)), "window": int(window), "noise_floor": float(floor), "intervals": len(iv),
        "interval_bounds": [[float(t[a]), float(t[b])] for a, b in iv],
        "offset": o.tolist(), "matrix": T.tolist(),
        "rms_means_relative": float(np.sqrt(np.mean(rel ** 2))),
        "condition": {m: design_condition(directions, m) for m in ("paper9", "axis6", "bias3")},
        "nfev": int(res.nfev), "status": int(res.status),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--json", action="store_true", help="print one JSON object instead of the report")
    ap.add_argument("logs", nargs="*", default=list(LOGS), help="which logs (default: all)")
    a = ap.parse_args()
    out = {"logs": {name: run(name, LOGS[name]) for name in a.logs}}
    missing = [r["file"] for r in out["logs"].values() if r.get("missing")]
    if a.json and missing:  # real_data_fit.json holds every log: never write it with one left out
        sys.exit(f"not found in {DATA_DIRS} (set SCALCAL_REAL_DATA to their folder): {', '.join(missing)}")
    if a.json:
        print(json.dumps(out, indent=1))
        return
    for name, r in out["logs"].items():
        if r.get("missing"):
            print(f"{name}: {r['file']} not found in {DATA_DIRS}", file=sys.stderr)
            continue
        if r.get("every") == "sample":
            print(f"{name}: every sample, {r['samples_used']} of {r['rows']} used, model {r['model']}, RMS "
                  f"|m| - 1 {r['rms_means_relative']:.4e}, offset {np.round(r['offset'], 2).tolist()}")
            continue
        print(f"{name}: {r['intervals']} intervals, model {r['model']}, RMS |a| - g over the interval means "
              f"{r['rms_means_relative']:.4e} of |I|; condition paper9 {r['condition']['paper9']:.3g}, "
              f"axis6 {r['condition']['axis6']:.3g}")


if __name__ == "__main__":
    main()
