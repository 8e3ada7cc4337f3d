#!/usr/bin/python3
"""The studio's previews are drawn like a run: by a child `selfsim preview` with the run's --timeout and
--max-memory, never inside the studio's loop. While a preview is being drawn (held with SIGSTOP, so "during"
is certain rather than timed) the studio answers other requests; Ctrl-C or SIGTERM to the studio alone then ends it and
the preview, leaving no lock, run log, staging folder or partial PNG in the output folder. Then a `.studio`
link: refused at the start with its name, nothing written where it points. The waits are bounds against a
hang, never timings: every assertion is about order or content. Skips (77) without an X display or Xvfb.

usage: studio_previews.py SELFSIM"""
import os, re, shutil, signal, subprocess, sys, tempfile, time

import studio_lib
from studio_lib import check, finish, get, until

selfsim = sys.argv[1]
if not os.environ.get("DISPLAY") and not shutil.which("Xvfb"):
    print("skipped: no X display and no Xvfb")
    sys.exit(77)

tmp = tempfile.mkdtemp()
recipe = os.path.join(tmp, "r.lua")
with open(recipe, "w") as f:  # a mesh whose preview takes a while to read and render
    f.write('local n = param("n", 1, { min = 1, max = 9 })\n'
            'local curves = require "selfsim.curves"\n'
            'save(develop(curves.dragon(), { levels = 7, smooth = 3 }), "mesh.vtp")\n')
out = os.path.join(tmp, "out")


def start_studio(*extra):
    return studio_lib.start_studio(selfsim, recipe, out, *extra)


def children(pid):
    """The process ids of pid's children (ours: the studio we started, and its children)."""
    try:
        with open(f"/proc/{pid}/task/{pid}/children") as f:
            return [int(c) for c in f.read().split()]
    except OSError:
        return []


def argv(pid):
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            return [a.decode(errors="replace") for a in f.read().split(b"\0")[:-1]]
    except OSError:
        return []


def alive(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def stopped(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] == "T"
    except OSError:
        return False


# 1. A preview being drawn does not hold the page loop, and runs under the run's limits; 2. Ctrl-C or
# SIGTERM to the studio alone, the preview still held: everything ends and the folder is clean.
for stop in (signal.SIGINT, signal.SIGTERM):
    studio, port, line = start_studio("--timeout", "120")
    check(port is not None, "the studio says where it listens: " + line)
    preview = None
    for attempt in range(1, 6):  # a preview that ends before it is seen is drawn again for another value
        if attempt > 1:
            get(port, f"/run?n={attempt}")
        end = time.monotonic() + 120
        while preview is None and time.monotonic() < end and studio.poll() is None:
            for c in children(studio.pid):
                a = argv(c)
                if len(a) > 1 and a[1] == "preview":
                    try:
                        os.kill(c, signal.SIGSTOP)  # held mid-drawing: "during" is certain
                    except OSError:
                        continue
                    # Held, unless it had already ended (a zombie takes the signal without stopping).
                    if until(lambda: stopped(c) or not alive(c), 10) and stopped(c):
                        preview = c
            status, body = get(port, "/state") if preview is None else (None, b"")
            if preview is None and status == 200 and b'"running": false' in body:
                break  # this run's previews are done: try again
            time.sleep(0.002)
        if preview is not None:
            break
    check(preview is not None, "the studio draws its previews in a child `selfsim preview`")
    if preview is not None:
        a = argv(preview)
        check("--max-memory" in a and a[a.index("--timeout") + 1] == "120" if "--timeout" in a else False,
              "the preview runs under the run's --timeout and --max-memory: " + " ".join(a))
        status, body = get(port, "/params")
        check(status == 200 and b'"parameters"' in body, f"/params answered while a preview is drawn: {status}")
        status, body = get(port, "/state")
        check(status == 200 and b'"running": true' in body, f"/state answered (still drawing) meanwhile: {status} {body!r}")
        check(stopped(preview), "the preview was still being drawn when those answers came")
        helpers = [c for c in children(preview)]  # Xvfb, the renderer's child
        studio.send_signal(stop)
        try:
            code = studio.wait(60)
        except subprocess.TimeoutExpired:
            studio.kill()
            code = None
        check(code == 130, f"{stop.name} during a preview ends the studio with 130, got {code}")
        check(until(lambda: not alive(preview), 30) is not None or not alive(preview), "the preview ended with the studio")
        for h in helpers:
            check(until(lambda: not alive(h), 30) is not None or not alive(h), f"the preview's helper {argv(h)} ended")
        left = []
        for root, dirs, files in os.walk(out):
            for name in dirs + files:
                if name.startswith(".selfsim") or ".part-" in name:
                    left.append(os.path.join(root, name))
        check(not left, f"nothing of the studio or the preview is left behind: {left}")
        check(os.path.isfile(os.path.join(out, "mesh.vtp")), "the run's own file stays")
    if studio.poll() is None:
        studio.kill()
        studio.wait()


# 3. Left alone, the preview is drawn and shown; a `.studio` link swapped in afterwards is not written through.
outside = os.path.join(tmp, "outside")
os.makedirs(outside)
shutil.rmtree(out, ignore_errors=True)
studio, port, line = start_studio()


def shown(generation):
    status, body = get(port, "/state")
    m = re.search(rb'"shown": (\d+)', body)
    return status == 200 and b'"running": false' in body and m and int(m.group(1)) >= generation and body


body = until(lambda: shown(1), 120)
m = re.search(rb'"image": "(/out/\.studio/mesh\.vtp\.png)[^"]*"', body or b"")
check(m is not None, f"the drawn preview is shown: {body!r}")
if m:
    status, png = get(port, m.group(1).decode())
    check(status == 200 and png.startswith(b"\x89PNG"), f"the preview is served as a PNG: {status}")
shutil.rmtree(os.path.join(out, ".studio"))
os.symlink(outside, os.path.join(out, ".studio"))
get(port, "/run?n=2")
check(until(lambda: shown(2), 120) is not None, "a run after the link is planted still ends and is shown")
check(os.listdir(outside) == [], f"nothing written through the .studio link: {os.listdir(outside)}")
studio.send_signal(signal.SIGINT)
studio.wait(60)
os.unlink(os.path.join(out, ".studio"))

# 4. A `.studio` link at the start: refused with its name, nothing written there.
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
os.symlink(outside, os.path.join(out, ".studio"))
studio, port, line = start_studio()
try:
    rest, _ = studio.communicate(timeout=60)
    code = studio.returncode
except subprocess.TimeoutExpired:  # still serving: the link was not refused
    studio.send_signal(signal.SIGINT)
    rest, _ = studio.communicate()
    code = None
text = line + rest
check(code not in (0, None), f"a .studio link ends the studio with an error, got {code}")
check(".studio" in text and "link" in text, "the message names the link: " + text.strip())
check(os.listdir(outside) == [], f"nothing written through the link: {os.listdir(outside)}")

# 5. An output whose name takes 252 of the 255 bytes a name may have: its preview's name in .studio/ is
# shortened (fitting_name, as a sweep's are) instead of failing as "longer than 255 bytes".
long_name = "l" * 248 + ".vtp"
with open(recipe, "w") as f:
    f.write('local n = param("n", 1, { min = 1, max = 9 })\n'
            'local curves = require "selfsim.curves"\n'
            f'save(develop(curves.dragon(), {{ levels = 2, smooth = 1 }}), "{long_name}")\n')
shutil.rmtree(out, ignore_errors=True)
studio, port, line = start_studio()
body = until(lambda: shown(1), 120)
m = re.search(rb'"image": "(/out/\.studio/l+~[0-9a-f]+\.png)[^"]*"', body or b"")
check(m is not None, f"the preview of a 252-byte output is shown: {body!r}")
if m:
    status, png = get(port, m.group(1).decode())
    check(status == 200 and png.startswith(b"\x89PNG"), f"and served as a PNG: {status}")
studio.send_signal(signal.SIGINT)
studio.wait(60)

# 6. A 3D view its reader cannot hold under --max-memory (a 709 x 709 grid, 19 MB of PLY, at 64M): the page's
# reason names the limit, as the preview's line does ("cannot read 'big.ply': out of memory" alone before).
import math, struct
n = 709
big = os.path.join(tmp, "big.ply")
with open(big, "wb") as f:
    f.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {n * n}\nproperty float x\nproperty float y\n"
             f"property float z\nelement face {2 * (n - 1) ** 2}\nproperty list uchar int vertex_indices\n"
             "end_header\n").encode())
    f.write(b"".join(struct.pack("<fff", i / n, j / n, 0.1 * math.sin(i / 20)) for j in range(n) for i in range(n)))
    f.write(b"".join(struct.pack("<BiiiBiii", 3, j * n + i, j * n + i + 1, j * n + i + n, 3, j * n + i + 1,
                                 j * n + i + n + 1, j * n + i + n) for j in range(n - 1) for i in range(n - 1)))
with open(recipe, "w") as f:
    f.write('local n = param("n", 1)\nsave(load("big.ply"), "big.ply")\n')
shutil.rmtree(out, ignore_errors=True)
studio, port, line = start_studio("--max-memory", "64M")
index = os.path.join(out, ".studio", "big.ply.3d", "index.json")
until(lambda: os.path.isfile(index), 120)
try:
    with open(index) as f:
        view = f.read()
except OSError:
    view = ""
check('"error"' in view and "--max-memory" in view, f"a view over --max-memory names the limit: {view!r}")
studio.send_signal(signal.SIGINT)
studio.wait(60)

shutil.rmtree(tmp, ignore_errors=True)
finish()
