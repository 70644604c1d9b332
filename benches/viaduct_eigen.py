"""scipy's side of benches/viaduct_eigen.sh: the lowest COUNT modes of the
Matrix Market pencil in DIR with scipy.sparse.linalg.eigsh(K, COUNT, M,
sigma=0) (shift-invert ARPACK on SuperLU), timed per phase; prints the
frequencies (Hz) after a `frequencies` line and the largest relative
residual ||K phi - lambda M phi|| / ||K phi||.

Usage: python viaduct_eigen.py DIR [COUNT=100]
"""
import sys
import time

import numpy as np
import scipy
import scipy.io
import scipy.sparse.linalg as sla

folder = sys.argv[1]
count = int(sys.argv[2]) if len(sys.argv) > 2 else 100
start = time.perf_counter()
K = scipy.io.mmread(folder + "/K.mtx").tocsc()
M = scipy.io.mmread(folder + "/M.mtx").tocsc()
read = time.perf_counter() - start
t = time.perf_counter()
lam, phi = sla.eigsh(K, count, M, sigma=0, which="LM")
solve = time.perf_counter() - t
order = np.argsort(lam)
lam, phi = lam[order], phi[:, order]
residual = max(
    np.linalg.norm(K @ phi[:, i] - lam[i] * (M @ phi[:, i])) / np.linalg.norm(K @ phi[:, i])
    for i in range(count)
)
print(f"order {K.shape[0]}, modes {count}, scipy {scipy.__version__}")
print(f"read {read:.2f} s, eigsh {solve:.2f} s, total {time.perf_counter() - start:.2f} s")
print(f"largest plain residual {residual:.3e}")
print("frequencies")
for value in lam:
    print(f"{np.sqrt(value) / (2 * np.pi):.12e}")
