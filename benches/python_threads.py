"""Two Python threads each running a scene, against one run alone.

The GIL is released while a scene computes, so on a machine with two free
cores two runs take about the time of one. This is a measurement, not a
test (the load-independent check is python/tests/test_behaviour.py::
test_python_runs_while_a_scene_computes).

    python benches/python_threads.py        # with `vbi` installed (python/ci.sh)
"""

import threading
import time
from pathlib import Path

import vbi

SCENE = (Path(__file__).resolve().parents[1] / "scenarios" / "yang-yau-sprung-mass.yaml").read_text()
SCENE = SCENE.replace("time_step: 1.0e-4", "time_step: 1.0e-5")

vbi.run(SCENE)  # warm up
for attempt in range(5):
    start = time.perf_counter()
    vbi.run(SCENE)
    one = time.perf_counter() - start
    threads = [threading.Thread(target=vbi.run, args=(SCENE,)) for _ in range(2)]
    start = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    two = time.perf_counter() - start
    print(f"one run {one:.3f} s, two threads {two:.3f} s, ratio {two / one:.2f}")
