"""Writes synthetic-vertical.AT2 and synthetic-lateral.AT2: synthetic ground
accelerations in the PEER NGA .AT2 layout, for the shipped ground-motion
scenarios (no real record ships with vbi; use a PEER record in its place for
real work).

Kanai-Tajimi-like content: a sum of 200 cosines with frequencies 0.5-20 Hz,
amplitudes shaped by the Kanai-Tajimi spectrum (ground frequency 15.6 rad/s,
damping 0.6, Clough & Penzien's firm soil) and phases from Python's random
module seeded with 2026; a Jennings-Housner-Hudson envelope (rise 2 s, strong
phase 2-6 s, decay exp(-0.3 (t - 6))); 12 s at DT = 0.005 s. The vertical
record: seed 2026, scaled to a peak of 0.1 g. The lateral one: seed 2027,
scaled to a peak of 0.2 g (the EMBS paper's scene shakes the viaduct
laterally only). Run: python3 make_synthetic.py
"""
import math
import random

DT, N = 0.005, 2400
wg, zg = 15.6, 0.6


def envelope(t):
    if t < 2.0:
        return (t / 2.0) ** 2
    if t < 6.0:
        return 1.0
    return math.exp(-0.3 * (t - 6.0))


def write(name, seed, pga, label):
    rng = random.Random(seed)
    terms = []
    for i in range(200):
        f = 0.5 + (20.0 - 0.5) * (i + rng.random()) / 200
        w = 2 * math.pi * f
        r = w / wg
        kt = (1 + 4 * zg * zg * r * r) / ((1 - r * r) ** 2 + 4 * zg * zg * r * r)
        terms.append((w, math.sqrt(kt), 2 * math.pi * rng.random()))
    samples = []
    for k in range(N):
        t = k * DT
        samples.append(envelope(t) * sum(a * math.cos(w * t + p) for w, a, p in terms))
    peak = max(abs(s) for s in samples)
    samples = [pga * s / peak for s in samples]
    with open(name, "w") as out:
        out.write("PEER NGA STRONG MOTION DATABASE RECORD\n")
        out.write(f"Synthetic {label} record (vbi scenarios/records/make_synthetic.py), 2026, {'UP' if label == 'vertical' else 'H1'}\n")
        out.write("ACCELERATION TIME SERIES IN UNITS OF G\n")
        out.write(f"NPTS= {N:6d}, DT= {DT:8.4f} SEC\n")
        for i in range(0, N, 5):
            out.write("".join(f"{s:15.7E}" for s in samples[i : i + 5]) + "\n")


write("synthetic-vertical.AT2", 2026, 0.10, "vertical")
write("synthetic-lateral.AT2", 2027, 0.20, "lateral")
