#!/usr/bin/python3
"""The baseline a researcher would write without scalcal: NumPy (vectorised random search over
batches of programs) and SciPy BFGS with an analytic gradient for one D start at N = 18.
Prints two lines: random_programs_per_s and bfgs_seconds_per_start (and the D it reached)."""
import time
import numpy as np
from scipy.optimize import minimize

N = 18

def design(eta):  # eta: (..., N, 3) -> H: (..., N, 9)
    x, y, z = eta[..., 0], eta[..., 1], eta[..., 2]
    return np.stack([x, y, z, x * x, y * y, z * z, x * y, y * z, z * x], axis=-1)

def random_search(count, batch=20000, seed=1):
    rng = np.random.default_rng(seed)
    best = np.inf
    for start in range(0, count, batch):
        b = min(batch, count - start)
        v = rng.normal(size=(b, N, 3))
        v /= np.linalg.norm(v, axis=-1, keepdims=True)
        H = design(v)
        M = np.einsum("bni,bnj->bij", H, H)
        sign, logdet = np.linalg.slogdet(M)
        d = np.where(sign > 0, 9 * np.log(N) - logdet, np.inf)
        best = min(best, np.exp(d.min()))
    return best

def d_objective(angles):
    a1, a2 = angles[:N], angles[N:]
    eta = np.stack([np.cos(a2) * np.cos(a1), np.cos(a2) * np.sin(a1), np.sin(a2)], axis=-1)
    H = design(eta)
    M = H.T @ H
    K = np.linalg.inv(M)
    f = 9 * np.log(N) - np.linalg.slogdet(M)[1]
    x, y, z = eta[:, 0], eta[:, 1], eta[:, 2]
    G = -2 * (H @ K)  # d f / d h_i
    dx = G[:, 0] + G[:, 3] * 2 * x + G[:, 6] * y + G[:, 8] * z
    dy = G[:, 1] + G[:, 4] * 2 * y + G[:, 6] * x + G[:, 7] * z
    dz = G[:, 2] + G[:, 5] * 2 * z + G[:, 7] * y + G[:, 8] * x
    da1 = dx * (-np.cos(a2) * np.sin(a1)) + dy * (np.cos(a2) * np.cos(a1))
    da2 = dx * (-np.sin(a2) * np.cos(a1)) + dy * (-np.sin(a2) * np.sin(a1)) + dz * np.cos(a2)
    return f, np.concatenate([da1, da2])

if __name__ == "__main__":
    count = 200000
    t = time.perf_counter()
    random_search(count)
    print("random_programs_per_s", count / (time.perf_counter() - t))
    rng = np.random.default_rng(1)
    starts, total, best = 5, 0.0, np.inf
    for k in range(starts):
        x0 = np.concatenate([rng.uniform(-np.pi, np.pi, N), rng.uniform(-1.4, 1.4, N)])
        t = time.perf_counter()
        r = minimize(d_objective, x0, jac=True, method="BFGS", options={"gtol": 1e-9, "maxiter": 5000})
        total += time.perf_counter() - t
        best = min(best, np.exp(r.fun))
    print("bfgs_seconds_per_start", total / starts)
    print("bfgs_best_D", best)
