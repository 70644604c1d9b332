#!/usr/bin/env python3
"""prof2.py REF RUN col...: error time profile of RUN against REF (REF sampled at RUN's
times; REF's step divides RUN's), 0.025 s windows, % of REF's peak, and where the max is."""
import sys, csv
def load(p):
    with open(p + '/history.csv') as f:
        r = csv.reader(f); h = [x.split(' ')[0] for x in next(r)]; rows = [list(map(float, x)) for x in r]
    return h, rows
hr, ref = load(sys.argv[1]); hb, b = load(sys.argv[2])
tr = [x[0] for x in ref]; idx = {round(t, 9): i for i, t in enumerate(tr)}
for n in sys.argv[3:]:
    jr, jb = hr.index(n), hb.index(n)
    peak = max(abs(x[jr]) for x in ref)
    d = [(y[0], y[jb] - ref[idx[round(y[0], 9)]][jr]) for y in b if round(y[0], 9) in idx]
    w = 0.025
    prof = {}
    for t, e in d:
        k = int(t / w); prof[k] = max(prof.get(k, 0), abs(e))
    tm, em = max(d, key=lambda x: abs(x[1]))
    print(n, 'max %.3f %% at t=%.4f' % (100 * abs(em) / peak, tm), [round(100 * prof[k] / peak, 2) for k in sorted(prof)])
