#!/usr/bin/python3
"""The peers scalcal is compared with (bench/compare.py): what a researcher would write with NumPy and
SciPy alone to find an optimal calibration program of N positions for D, A, E or S.

  lbfgs     L-BFGS-B on the smooth criteria D (as log det K) and A, exact analytic gradient
  slsqp     SLSQP; for E and S the epigraph form  min t  s.t.  t >= N K(r,r)  or  t >= N lambda_max(K)
  exchange  modified Fedorov exchange on a 20,000-point Fibonacci lattice (D and A); its optimum is
            on the lattice, so slightly above the continuous one
  pnorm     E and S: L-BFGS-B on a p-norm surrogate (p = 8, then 32, then 128: N (tr K^p)^(1/p) for E,
            N (sum_r K(r,r)^p)^(1/p) for S, exact gradients), then SLSQP on the epigraph from there

usage: peers.py --method lbfgs|slsqp|exchange --criterion D|A|E|S --positions N --starts K --seed S
                [--workers W]
Prints one JSON object: peer, criterion, positions, starts, value (best normalised value), hits (starts
within 1e-8 relative of the best), seconds (wall time of the multistart), plus seconds_per_start (mean
time of one start in its worker) and converged (starts whose solver reported success).
Exit 2 when the method does not apply to the criterion.

Every optimiser works on unnormalised v in R^{3N} with eta_i = v_i / |v_i|: unconstrained, no poles
(unlike angles), and the gradient is the eta-gradient projected on the tangent plane, divided by |v_i|.
"""
import os

# One BLAS thread per process: the parallelism is the Pool's, and 9 x 9 products gain nothing from
# threads.  Must precede the numpy import.
for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_name] = "1"

import argparse
import json
import sys
import time
from functools import lru_cache
from multiprocessing import Pool

import numpy as np
from scipy.optimize import minimize

APPLIES = {"lbfgs": "DA", "slsqp": "DAES", "exchange": "DA", "pnorm": "ES"}
CANDIDATES = 20000


def rows(eta):
    """The design rows h(eta) = (x, y, z, x^2, y^2, z^2, xy, yz, zx), shape (N, 9)."""
    x, y, z = eta.T
    return np.stack([x, y, z, x * x, y * y, z * z, x * y, y * z, z * x], axis=1)


def row_jacobian(eta):
    """d h / d eta, shape (N, 9, 3)."""
    x, y, z = eta.T
    o, l = np.zeros_like(x), np.ones_like(x)
    return np.stack([np.stack([l, o, o, 2 * x, o, o, y, o, z], axis=1),
                     np.stack([o, l, o, o, 2 * y, o, x, z, o], axis=1),
                     np.stack([o, o, l, o, o, 2 * z, o, y, x], axis=1)], axis=2)


def normalise(v):
    v = v.reshape(-1, 3)
    r = np.linalg.norm(v, axis=1, keepdims=True)
    return v / r, r


def to_v(g_h, eta, r):
    """Chain rule from a gradient over the rows, g_h (..., N, 9), to one over v (..., 3N)."""
    g = np.einsum("...nk,nkc->...nc", g_h, row_jacobian(eta))
    g = (g - np.sum(g * eta, axis=-1, keepdims=True) * eta) / r  # tangent of v / |v|
    return g.reshape(*g.shape[:-2], -1)


def value(eta, criterion):
    """The normalised criterion of a program (what scalcal reports)."""
    n = len(eta)
    m = rows(eta).T @ rows(eta)
    if criterion == "D":  # through log det: det M grows like N^9, det K shrinks like N^-9
        return float(np.exp(9 * np.log(n) - np.linalg.slogdet(m)[1]))
    if criterion == "E":
        return float(n / np.linalg.eigvalsh(m)[0])
    k = np.linalg.inv(m)
    return float(n * (np.trace(k) if criterion == "A" else np.max(np.diag(k))))


def smooth(v, criterion):
    """Objective and v-gradient for D (log of the normalised D, so the scale is O(10)) and A.
    d log det M = tr(K dM), d tr K = -tr(K^2 dM), dM = sum_i dh_i h_i^T + h_i dh_i^T, so a scalar f
    with df = tr(G dM), G symmetric, has d f / d h_i = 2 G h_i."""
    eta, r = normalise(v)
    n = len(eta)
    h = rows(eta)
    m = h.T @ h
    try:
        c = np.linalg.cholesky(m)
    except np.linalg.LinAlgError:  # a singular program: a wall the line search backs off from
        return 1e30, np.zeros_like(v)
    k = np.linalg.inv(m)
    if criterion == "D":
        f, g = 9 * np.log(n) - 2 * np.sum(np.log(np.diag(c))), -k
    else:
        f, g = n * np.trace(k), -n * (k @ k)
    return f, to_v(2 * h @ g, eta, r)


def pnorm(v, criterion, p):
    """A smooth surrogate of E or S that tends to it as p grows, and its v-gradient.
    S: f = N (sum_r K(r,r)^p)^(1/p), df = -N sum_r w_r (K dM K)(r,r), w_r = (K(r,r)/s)^(p-1), s = (sum K(r,r)^p)^(1/p);
    E: f = N (tr K^p)^(1/p) = N (sum_k lambda_k(M)^-p)^(1/p), df = -N tr(U diag(w_k / lambda_k) U^T dM),
    w_k = (lambda_k^-1 / s)^(p-1), s = (sum lambda_k^-p)^(1/p); scaled by the largest term, so no overflow."""
    eta, r = normalise(v)
    n = len(eta)
    h = rows(eta)
    m = h.T @ h
    if criterion == "S":
        try:
            k = np.linalg.inv(m)
        except np.linalg.LinAlgError:
            return 1e30, np.zeros_like(v)
        d = np.diag(k)
        if np.min(d) <= 0:
            return 1e30, np.zeros_like(v)
        top = np.max(d)
        s = top * np.sum((d / top) ** p) ** (1 / p)
        w = (d / s) ** (p - 1)
        g = -n * (k * w) @ k  # -N K diag(w) K
    else:
        lam, u = np.linalg.eigh(m)
        if lam[0] <= 0:
            return 1e30, np.zeros_like(v)
        inv = 1 / lam
        top = np.max(inv)
        s = top * np.sum((inv / top) ** p) ** (1 / p)
        w = (inv / s) ** (p - 1)
        g = -n * (u * (w * inv * inv)) @ u.T
    return n * s, to_v(2 * h @ g, eta, r)


def epigraph_constraints(criterion, n):
    """SLSQP inequality constraints over x = (v, t), each >= 0, with exact Jacobians.
    S: t - N K(r,r) for r = 0..8; dK = -K dM K gives d K(r,r) / d h_i = -2 (k_r . h_i) k_r.
    E: t - N / lambda_min(M) (= N lambda_max K); d lambda_min = u^T dM u for the unit min eigenvector
    u (where lambda_min is simple; at the E optimum it is multiple, so the constraint is nonsmooth
    there: exactly the difficulty a generic NLP solver meets)."""
    def parts(x):
        eta, r = normalise(x[:-1])
        h = rows(eta)
        return eta, r, h, h.T @ h

    if criterion == "S":
        def fun(x):
            return x[-1] - n * np.diag(np.linalg.inv(parts(x)[3]))

        def jac(x):
            eta, r, h, m = parts(x)
            k = np.linalg.inv(m)
            hk = h @ k  # hk[i, r] = k_r . h_i
            g_h = 2 * n * hk.T[:, :, None] * k.T[:, None, :]  # (9 constraints, N, 9): -N * (-2 ...)
            return np.hstack([to_v(g_h, eta, r), np.ones((9, 1))])
    else:
        def fun(x):
            return np.array([x[-1] - n / np.linalg.eigvalsh(parts(x)[3])[0]])

        def jac(x):
            eta, r, h, m = parts(x)
            w, u = np.linalg.eigh(m)
            hu = h @ u[:, 0]
            g_h = (2 * n / w[0] ** 2) * hu[:, None] * u[:, 0][None, :]
            return np.hstack([to_v(g_h, eta, r), [1.0]])[None, :]
    return {"type": "ineq", "fun": fun, "jac": jac}


@lru_cache(maxsize=1)
def lattice():
    """Fibonacci lattice: near-uniform candidates; their rows, shape (CANDIDATES, 9)."""
    i = np.arange(CANDIDATES) + 0.5
    z = 1 - 2 * i / CANDIDATES
    phi = np.pi * (1 + 5 ** 0.5) * i
    s = np.sqrt(1 - z * z)
    eta = np.stack([s * np.cos(phi), s * np.sin(phi), z], axis=1)
    return eta, rows(eta)


def exchange(eta0, criterion):
    """Modified Fedorov exchange (Cook & Nachtsheim): for each position in turn, swap it for the
    candidate that improves the criterion most, by the update formulas vectorised over candidates;
    passes until no swap improves.  With U = [x, x_j], M' = M + U diag(1, -1) U^T:
      det M' / det M = (1 + d(x)) (1 - d(x_j)) + d(x, x_j)^2,
      tr K' = tr K - tr(W^-1 U^T K^2 U),  W = diag(1, -1) + U^T K U   (Woodbury),
    with d(a, b) = a^T K b.  The accepted swap recomputes K by inversion: cheaper than drift."""
    ceta, ch = lattice()
    idx = np.argmax(eta0 @ ceta.T, axis=1)  # the candidate nearest each start position
    n = len(idx)
    improved, stale = True, True
    while improved:
        improved = False
        for j in range(n):
            if stale:
                k = np.linalg.inv(ch[idx].T @ ch[idx])
                ck = ch @ k
                d = np.einsum("ck,ck->c", ck, ch)
                if criterion == "A":
                    ck2 = ck @ k
                    p = np.einsum("ck,ck->c", ck2, ch)
                    trace = np.trace(k)
                stale = False
            xj = ch[idx[j]]
            dxj, dj = ck @ xj, d[idx[j]]
            if criterion == "D":
                gain = (1 + d) * (1 - dj) + dxj ** 2 - 1  # relative increase of det M
            else:
                pxj, pj = ck2 @ xj, p[idx[j]]
                detw = (1 + d) * (dj - 1) - dxj ** 2
                with np.errstate(divide="ignore", invalid="ignore"):
                    drop = ((dj - 1) * p - 2 * dxj * pxj + (1 + d) * pj) / detw
                # detw = 0 makes M' singular: never a gain
                gain = np.where(np.isfinite(drop) & (detw != 0), drop / trace, -np.inf)
            best = int(np.argmax(gain))
            if gain[best] > 1e-12:  # a strict gain on a finite set: the passes terminate
                idx[j] = best
                improved, stale = True, True
    return ceta[idx]


def one_start(task):
    """One start of the multistart: (value, solver success, seconds)."""
    method, criterion, n, seed, k = task
    t0 = time.perf_counter()
    v = np.random.default_rng([seed, k]).normal(size=(n, 3))
    eta0 = normalise(v)[0]
    v = eta0.ravel()
    ok = True
    if method == "exchange":
        eta = exchange(eta0, criterion)
    elif method == "lbfgs":
        res = minimize(smooth, v, args=(criterion,), jac=True, method="L-BFGS-B",
                       options={"gtol": 1e-10, "ftol": 1e-15, "maxiter": 10000, "maxfun": 100000})
        eta, ok = normalise(res.x)[0], res.success
    elif method == "pnorm":
        for p in (8, 32, 128):
            res = minimize(pnorm, v, args=(criterion, p), jac=True, method="L-BFGS-B",
                           options={"gtol": 1e-7, "ftol": 1e-12, "maxiter": 5000})
            v = normalise(res.x)[0].ravel()
        eta1 = normalise(v)[0]
        x0 = np.append(v, value(eta1, criterion))
        # From the surrogate's optimum the epigraph needs far fewer steps; 1e-12 is as tight as the
        # 1e-6 reach test of compare.py asks, with margin.
        res = minimize(lambda x: x[-1], x0, jac=lambda x: np.eye(len(x))[-1], method="SLSQP",
                       constraints=[epigraph_constraints(criterion, n)],
                       options={"ftol": 1e-12, "maxiter": 1000})
        eta, ok = normalise(res.x[:-1])[0], res.success
    elif criterion in "DA":
        res = minimize(smooth, v, args=(criterion,), jac=True, method="SLSQP",
                       options={"ftol": 1e-16, "maxiter": 1000})
        eta, ok = normalise(res.x)[0], res.success
    else:
        x0 = np.append(v, value(eta0, criterion))  # t starts feasible, at the start's value
        res = minimize(lambda x: x[-1], x0, jac=lambda x: np.eye(len(x))[-1], method="SLSQP",
                       constraints=[epigraph_constraints(criterion, n)],
                       options={"ftol": 1e-16, "maxiter": 1000})
        eta, ok = normalise(res.x[:-1])[0], res.success
    # The reported value is recomputed from the program, not taken from t or the solver's f.
    return value(eta, criterion), bool(ok), time.perf_counter() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--method", required=True, choices=sorted(APPLIES))
    ap.add_argument("--criterion", required=True, choices=list("DAES"))
    ap.add_argument("--positions", type=int, required=True)
    ap.add_argument("--starts", type=int, default=8)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--workers", type=int, default=2)
    a = ap.parse_args()
    if a.criterion not in APPLIES[a.method]:
        print(f"peers.py: {a.method} does not apply to criterion {a.criterion} "
              f"(only {', '.join(APPLIES[a.method])})", file=sys.stderr)
        return 2
    if a.positions < 9 or a.starts < 1 or a.workers < 1:
        print("peers.py: need --positions >= 9, --starts >= 1, --workers >= 1", file=sys.stderr)
        return 1
    tasks = [(a.method, a.criterion, a.positions, a.seed, k) for k in range(a.starts)]
    t0 = time.perf_counter()
    if a.workers == 1:  # no Pool: one process, so its peak memory is the whole run's
        results = [one_start(t) for t in tasks]
    else:
        with Pool(a.workers) as pool:
            results = pool.map(one_start, tasks, chunksize=1)
    seconds = time.perf_counter() - t0
    values = np.array([r[0] for r in results])
    best = float(np.nanmin(values))
    print(json.dumps({
        "peer": a.method, "criterion": a.criterion, "positions": a.positions, "starts": a.starts,
        "value": best, "hits": int(np.sum(values <= best * (1 + 1e-8))), "seconds": seconds,
        "seconds_per_start": float(np.mean([r[2] for r in results])),
        "converged": int(sum(r[1] for r in results))}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
