#!/usr/bin/env python3
"""Write a variant of a scene for a measurement (docs/methods.md).

    tools/scene_variant.py BASE OUT [auto] [modes=N] [cut=HZ] [dt=S] [entry=L] [method=M]

auto     removes the bridge's `modes:` and the solver's `time_step` (the automatic choice);
modes=N  sets `bridge.modes: {count: N}`, cut=HZ `{max_frequency: HZ}`;
dt=S     sets `solver.time_step`; entry=L `bridge.entry_length`; method=M `solver.method`.
Data files the scene names by relative paths are rewritten as absolute paths, so OUT may be
anywhere: run it with `--data-dir` naming the base scene's folder.
"""
import os
import re
import sys

base, out, *args = sys.argv[1:]
opts = dict(a.split("=", 1) if "=" in a else (a, "") for a in args)
folder = os.path.dirname(os.path.abspath(base))
src = open(base).read()

# Data files: every value that looks like a path to a data file.
def absolute(m):
    key, path = m.group(1), m.group(2)
    return key + (path if os.path.isabs(path) else os.path.normpath(os.path.join(folder, path)))

src = re.sub(r"(\b(?:stiffness|mass|damping_matrix|dof_map|file):\s*)([\w./-]+\.(?:mtx|rsa|rua|csv|AT2|at2|inp|txt))", absolute, src)
src = re.sub(r"(\$schema=)(\S+)", lambda m: m.group(1) + os.path.normpath(os.path.join(folder, m.group(2))), src)

lines = src.split("\n")
res = []
for line in lines:
    if ("auto" in opts or "modes" in opts or "cut" in opts) and re.match(r"^  modes:", line):
        continue
    res.append(line)
    if line.startswith("bridge:"):
        if "modes" in opts:
            res.append(f"  modes: {{count: {opts['modes']}}}")
        elif "cut" in opts:
            res.append(f"  modes: {{max_frequency: {opts['cut']}}}")
        if "entry" in opts:
            res.append(f"  entry_length: {opts['entry']}")
src = "\n".join(res)
if "auto" in opts or "dt" in opts:
    src = re.sub(r"time_step: [^,}\n]+,\s*", "", src)
    src = re.sub(r"^  time_step: .*\n", "", src, flags=re.M)
if "dt" in opts:
    src = re.sub(r"^solver: \{", f"solver: {{time_step: {opts['dt']}, ", src, flags=re.M)
if "method" in opts:
    src = re.sub(r"(solver: \{.*?)method: [a-z_]+", lambda m: m.group(1) + "method: " + opts["method"], src)
open(out, "w").write(src)
