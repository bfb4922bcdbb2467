"""Numerical evidence for E at N = 9 (proofs/non_attainment.md): how far m points can come from the equality
conditions of the E limit, by least squares from seeded random starts (SciPy). Not a proof: a least-squares
minimum found from finitely many starts is an upper bound on the true minimum residual, not a lower one.

The conditions, for unit vectors eta_i and k(eta) = (sqrt(4/3) g(eta), eta / sqrt 3) in R^8 (g the five harmonic
quadratics in the coefficient basis of h): 9 points attain E = 12 iff sum_i k_i k_i^T = I_8, iff the 9 x 9 matrix
I - Gram(k) is u u^T for a unit u (Naimark's complement), and then u_i = (3 - c . eta_i) / sqrt(27 delta) with
c = sum eta_i, delta = 3 - |c|^2 / 9. Any m of the points satisfy the same with (I - Gram(k)) restricted to them.
Printed: for each m, the smallest over the starts of the largest residual entry at each start's least-squares
point, with u free ("frame") and with c free ("c"); then, for 12 seeded c, how many points of c's curve |K| = 1 are orthogonal to one
point of it (K(eta) = (k(eta), (3 - c . eta) / sqrt(27 delta)): nine points of the curve, mutually orthogonal).
Usage: python3 e_nine_residuals.py [STARTS]"""
import sys

import numpy as np
import scipy.optimize as so

R43 = np.sqrt(4 / 3)


def kvec(X):
    x, y, z = X.T
    g = np.c_[x * y, y * z, z * x, (x * x - y * y) / np.sqrt(2), (x * x + y * y - 2 * z * z) / np.sqrt(6)]
    return np.c_[R43 * g, X / np.sqrt(3)]


def unit(v, m):
    p = v[:3 * m].reshape(m, 3)
    return p / np.linalg.norm(p, axis=1)[:, None]


def frame_residual(m):
    def f(v):
        k, u = kvec(unit(v, m)), v[3 * m:]
        return (np.eye(m) - k @ k.T - np.outer(u, u))[np.triu_indices(m)]
    return f, m


def c_residual(m):
    def f(v):
        X, c = unit(v, m), v[3 * m:]
        delta = 3 - c @ c / 9
        if delta <= 0:
            return np.full(m * (m + 1) // 2, 10.0)
        k, w = kvec(X), (3 - X @ c) / np.sqrt(27 * delta)
        return (np.eye(m) - k @ k.T - np.outer(w, w))[np.triu_indices(m)]
    return f, 3


def smallest(make, m, starts, rng):
    f, extra = make(m)
    best = np.inf
    for _ in range(starts):
        v = np.r_[rng.normal(size=3 * m), 0.3 * rng.normal(size=extra)]
        r = so.least_squares(f, v, method="trf", max_nfev=5000)
        best = min(best, np.abs(r.fun).max())
    return best


def lifted(X, c):
    delta = 3 - c @ c / 9
    return np.c_[kvec(np.atleast_2d(X)), (3 - np.atleast_2d(X) @ c) / np.sqrt(27 * delta)]


def sphere(a):
    return np.array([np.sin(a[0]) * np.cos(a[1]), np.sin(a[0]) * np.sin(a[1]), np.cos(a[0])])


def partners(c, rng, starts=400):
    """A point of c's curve (|K| = 1) and the distinct points of the curve orthogonal to it, by Newton."""
    norm = lambda a: [lifted(sphere(a), c)[0] @ lifted(sphere(a), c)[0] - 1]
    for _ in range(50):
        r = so.least_squares(norm, [rng.uniform(0, 3), rng.uniform(0, 6)], xtol=1e-15, ftol=1e-15, gtol=1e-15)
        if abs(r.fun[0]) < 1e-12:
            break
    else:
        return None
    k1, found = lifted(sphere(r.x), c)[0], []
    both = lambda a: [norm(a)[0], lifted(sphere(a), c)[0] @ k1]
    for _ in range(starts):
        s = so.root(both, [np.arccos(rng.uniform(-1, 1)), rng.uniform(0, 2 * np.pi)], method="hybr")
        if s.success and np.max(np.abs(both(s.x))) < 1e-11 and all(np.linalg.norm(sphere(s.x) - q) > 1e-6
                                                                   for q in found):
            found.append(sphere(s.x))
    return found


def main():
    starts = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    for m in (5, 6, 7, 9):
        rng = np.random.default_rng(m)
        print(f"m = {m}: frame {smallest(frame_residual, m, starts, rng):.3g}, "
              f"c {smallest(c_residual, m, starts, rng):.3g}  ({starts} starts each)")
    rng = np.random.default_rng(5)
    for _ in range(12):
        c = rng.normal(size=3)
        c *= rng.uniform(0, 3.8) / np.linalg.norm(c)
        found = partners(c, rng)
        if found is None:
            print(f"|c| = {np.linalg.norm(c):.2f}: no point of the curve found")
            continue
        K = lifted(np.array(found), c) if found else np.zeros((0, 9))
        pairs = int(np.sum(np.abs(K @ K.T) < 1e-8) // 2)
        print(f"|c| = {np.linalg.norm(c):.2f}: {len(found)} points orthogonal to the first, {pairs} orthogonal pairs "
              "among them")


if __name__ == "__main__":
    main()
