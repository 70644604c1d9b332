"""Writes synthetic-vertical.AT2: a synthetic vertical ground acceleration
in the PEER NGA .AT2 layout, for the shipped ground-motion scenario (no real
record ships with vbi; use a PEER record in its place for real work).

Kanai-Tajimi-like content: a sum of 200 cosines with frequencies 0.5-20 Hz,
amplitudes shaped by the Kanai-Tajimi spectrum (ground frequency 15.6 rad/s,
damping 0.6, Clough & Penzien's firm soil) and phases from Python's random
module seeded with 2026; a Jennings-Housner-Hudson envelope (rise 2 s, strong
phase 2-6 s, decay exp(-0.3 (t - 6))); scaled to a peak of 0.1 g; 12 s at
DT = 0.005 s. Run: python3 make_synthetic.py
"""
import math
import random

DT, N, PGA = 0.005, 2400, 0.10
rng = random.Random(2026)
wg, zg = 15.6, 0.6
terms = []
for i in range(200):
    f = 0.5 + (20.0 - 0.5) * (i + rng.random()) / 200
    w = 2 * math.pi * f
    r = w / wg
    kt = (1 + 4 * zg * zg * r * r) / ((1 - r * r) ** 2 + 4 * zg * zg * r * r)
    terms.append((w, math.sqrt(kt), 2 * math.pi * rng.random()))


def envelope(t):
    if t < 2.0:
        return (t / 2.0) ** 2
    if t < 6.0:
        return 1.0
    return math.exp(-0.3 * (t - 6.0))


samples = []
for k in range(N):
    t = k * DT
    samples.append(envelope(t) * sum(a * math.cos(w * t + p) for w, a, p in terms))
peak = max(abs(s) for s in samples)
samples = [PGA * s / peak for s in samples]
with open("synthetic-vertical.AT2", "w") as out:
    out.write("PEER NGA STRONG MOTION DATABASE RECORD\n")
    out.write("Synthetic vertical record (vbi scenarios/records/make_synthetic.py), 2026, UP\n")
    out.write("ACCELERATION TIME SERIES IN UNITS OF G\n")
    out.write(f"NPTS= {N:6d}, DT= {DT:8.4f} SEC\n")
    for i in range(0, N, 5):
        out.write("".join(f"{s:15.7E}" for s in samples[i : i + 5]) + "\n")
