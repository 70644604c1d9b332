#!/usr/bin/env python3
"""Write a variant of a scene: variant.py BASE OUT modes=N dt=S entry=L method=M
(modes/dt fixed explicitly; entry = bridge.entry_length)."""
import sys, re
base, out, *kv = sys.argv[1:]
opts = dict(a.split('=', 1) for a in kv)
src = open(base).read()
lines = src.split('\n')
res = []
for l in lines:
    res.append(l)
    if l.startswith('  damping:') and ('modes' in opts or 'cut' in opts):
        if 'modes' in opts:
            res.append(f"  modes: {{count: {opts['modes']}}}")
        else:
            res.append(f"  modes: {{max_frequency: {opts['cut']}}}")
    if l.startswith('  damping:') and 'entry' in opts:
        res.append(f"  entry_length: {opts['entry']}")
src = '\n'.join(res)
if 'dt' in opts:
    src = src.replace('free_vibration:', f"time_step: {opts['dt']}, free_vibration:")
if 'method' in opts:
    src = re.sub(r'solver: \{method: [a-z]+(, compare: true)?,', f"solver: {{method: {opts['method']},", src)
open(out, 'w').write(src)
