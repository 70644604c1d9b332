#!/usr/bin/env python3
"""prof.py A B col...: time profile (0.05 s windows, % of B's peak) and the dominant
frequencies (naive DFT, 10 Hz bins to 1 kHz) of A - B for each column."""
import sys, csv, math, cmath
def load(p):
    with open(p + '/history.csv') as f:
        r = csv.reader(f); h = [x.split(' ')[0] for x in next(r)]; rows = [list(map(float, x)) for x in r]
    return h, rows
ha, a = load(sys.argv[1]); hb, b = load(sys.argv[2])
t = [x[0] for x in a]; dt = t[1] - t[0]
for n in sys.argv[3:]:
    ja, jb = ha.index(n), hb.index(n)
    d = [x[ja] - y[jb] for x, y in zip(a, b)]
    peak = max(abs(y[jb]) for y in b)
    w = int(round(0.05 / dt))
    print(n, 'peak', '%.4g' % peak, 'profile %:', [round(100 * max(abs(v) for v in d[k:k + w]) / peak, 1) for k in range(0, len(d), w)])
    amps = []
    for f in range(10, 1000, 10):
        s = sum(v * cmath.exp(-2j * math.pi * f * tk) for v, tk in zip(d[::2], t[::2]))
        amps.append((abs(s), f))
    amps.sort(reverse=True)
    print('  top |DFT| freqs (Hz):', [f for _, f in amps[:8]])
