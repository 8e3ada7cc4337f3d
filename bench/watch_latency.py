#!/usr/bin/python3
"""How soon `selfsim run --watch` has new files after a save (issue 26: within 0.5 s for a recipe that runs
in 0.1 s). Saves the recipe N times as an editor does (a temporary renamed over it) and times from the rename until the output file is replaced (polled every 2 ms).

usage: bench/watch_latency.py [BUILD] [N]"""
import os, statistics, subprocess, sys, tempfile, time

build = sys.argv[1] if len(sys.argv) > 1 else "build"
n = int(sys.argv[2]) if len(sys.argv) > 2 else 10
selfsim = os.path.abspath(os.path.join(build, "selfsim"))
recipe = """local curves = require "selfsim.curves"
save(curves.dragon():curve(18), "c.svg")  -- about 0.1 s a run; save {i}
"""

def save(path, text):
    with open(path + ".new", "w") as f:
        f.write(text)
    os.replace(path + ".new", path)

def identity(path):
    try:
        s = os.stat(path)
        return (s.st_ino, s.st_mtime_ns)
    except FileNotFoundError:
        return None

with tempfile.TemporaryDirectory() as tmp:
    r = os.path.join(tmp, "r.lua")
    out = os.path.join(tmp, "out", "c.svg")
    save(r, recipe.format(i=0))
    one = time.monotonic()
    subprocess.run([selfsim, "run", r, "-o", os.path.join(tmp, "plain"), "-q"], check=True)
    print("one plain run (fresh process): %.3f s" % (time.monotonic() - one))
    watch = subprocess.Popen([selfsim, "run", r, "--watch", "-o", os.path.join(tmp, "out"), "-q"])
    while identity(out) is None:
        time.sleep(0.01)
    times = []
    for i in range(n):
        time.sleep(0.3)
        before = identity(out)
        start = time.monotonic()
        save(r, recipe.format(i=i + 1))
        while identity(out) == before:
            time.sleep(0.002)
        times.append(time.monotonic() - start)
    watch.terminate()
    watch.wait()
    print("save to new file: median %.3f s, min %.3f s, max %.3f s over %d saves" %
          (statistics.median(times), min(times), max(times), n))
