#!/usr/bin/python3
"""How soon the studio's 3D view shows a surface of about 1 M triangles (issue 38: under 3 s in headless
Chromium, from the request to the first frame drawn). The recipe loads a 709 x 709 height field written here
as binary PLY (1,002,528 triangles, a `height` point field to colour by) and saves it as .vtp; the studio
makes its payload after the run, and the page records performance.now() marks: `request` (the view asks for
its index), `received` (the step's bytes are in), `drawn` (the first frame's pixels can be read back). Each
load is a fresh page (the studio sends no-store: nothing cached). WebGL is SwiftShader, in software, on the
CPU: no GPU. Also printed: the studio's own part, from its start to the payload on disk (the run, then the
payload beside the PNG).

usage: bench/studio_3d_load.py [BUILD] [N]"""
import math, os, re, statistics, struct, subprocess, sys, tempfile, time
from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service

build = sys.argv[1] if len(sys.argv) > 1 else "build"
n = int(sys.argv[2]) if len(sys.argv) > 2 else 5
side = 709  # 2 * 708 * 708 = 1,002,528 triangles


def write_ply(path):
    with open(path, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                 "property float z\nproperty float height\nelement face %d\nproperty list uchar int vertex_indices\n"
                 "end_header\n" % (side * side, 2 * (side - 1) ** 2)).encode())
        rows = []
        for j in range(side):
            for i in range(side):
                x, z = i / (side - 1) * 2 - 1, j / (side - 1) * 2 - 1
                y = 0.15 * math.sin(6 * x) * math.cos(5 * z) + 0.1 * math.sin(17 * x * z)
                rows.append(struct.pack("<ffff", x, y, z, y))
        f.write(b"".join(rows))
        faces = []
        for j in range(side - 1):
            for i in range(side - 1):
                a = j * side + i
                faces.append(struct.pack("<BiiiBiii", 3, a, a + side, a + 1, 3, a + 1, a + side, a + side + 1))
        f.write(b"".join(faces))


with tempfile.TemporaryDirectory() as tmp:
    write_ply(os.path.join(tmp, "surface.ply"))
    recipe = os.path.join(tmp, "r.lua")
    with open(recipe, "w") as f:
        f.write('save(load("surface.ply"), "surface.vtp")\n')
    out = os.path.join(tmp, "out")
    started = time.monotonic()
    studio = subprocess.Popen([os.path.join(build, "selfsim"), "studio", recipe, "--port", "0", "-o", out],
                              stdout=subprocess.PIPE, text=True)
    port = re.search(r"127\.0\.0\.1:(\d+)", studio.stdout.readline()).group(1)
    index = os.path.join(out, ".studio", "surface.vtp.3d", "index.json")
    while not os.path.exists(index):
        time.sleep(0.01)
    made = time.monotonic() - started
    payload = os.path.getsize(os.path.join(out, ".studio", "surface.vtp.3d", "0.bin"))
    o = Options()
    for a in ["--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1200,900",
              "--use-angle=swiftshader", "--enable-unsafe-swiftshader"]:
        o.add_argument(a)
    d = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=o)
    marks = "const v = window.studio3d && window.studio3d.views['surface.vtp']; return v && (v.ready || v.error) ? [v.marks, v.error || ''] : null"
    loads = []
    for _ in range(n + 1):  # the first load warms Chromium up (its GPU process, the shader cache): not counted
        d.get("http://127.0.0.1:%s/" % port)
        m = None
        while not m:
            time.sleep(0.02)
            m = d.execute_script(marks)
        if m[1]:
            sys.exit("no view: " + m[1])
        loads.append(m[0])
    d.quit()
    studio.terminate()
    studio.wait()
    total = [m["drawn"] - m["request"] for m in loads[1:]]
    fetch = [m["received"] - m["request"] for m in loads[1:]]
    draw = [m["drawn"] - m["received"] for m in loads[1:]]
    print("studio start to payload on disk (run, previews and payload): %.2f s; payload %.1f MB" % (made, payload / 1e6))
    print("first load (cold Chromium): %.0f ms" % (loads[0]["drawn"] - loads[0]["request"]))
    print("request to first frame: median %.0f ms (min %.0f, max %.0f) over %d loads" %
          (statistics.median(total), min(total), max(total), n))
    print("  of which index, renderer and bytes in: median %.0f ms; parse, upload and draw: median %.0f ms" %
          (statistics.median(fetch), statistics.median(draw)))
