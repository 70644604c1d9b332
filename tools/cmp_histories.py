#!/usr/bin/env python3
"""tools/cmp_histories.py REF RUN [RUN...]: per column, max |run - ref| / max |ref| (%) on the run's times
(the reference interpolated linearly; its step divides the run's)."""
import sys, csv
def load(p):
    with open(p) as f:
        r = csv.reader(f); h = next(r); rows = [list(map(float, x)) for x in r]
    return h, rows
hr, ref = load(sys.argv[1] + '/history.csv')
tref = [x[0] for x in ref]
import bisect
def at(t, j):
    i = bisect.bisect_left(tref, t - 1e-12)
    if i < len(tref) and abs(tref[i] - t) < 1e-9: return ref[i][j]
    i = max(1, min(i, len(tref) - 1)); t0, t1 = tref[i-1], tref[i]
    w = (t - t0) / (t1 - t0); return ref[i-1][j] * (1 - w) + ref[i][j] * w
names = [n for n in hr[1:] if '_static' not in n]
print('%-28s' % 'run', ' '.join('%10s' % n.split(' ')[0][:10] for n in names))
for run in sys.argv[2:]:
    h, rows = load(run + '/history.csv')
    errs = []
    for n in names:
        j = h.index(n); jr = hr.index(n)
        peak = max(abs(x[jr]) for x in ref)
        e = max(abs(x[j] - at(x[0], jr)) for x in rows if x[0] <= tref[-1] + 1e-9)
        errs.append(100 * e / peak if peak else float('nan'))
    print('%-28s' % run.split('/')[-1][:28], ' '.join('%10.3f' % e for e in errs))
