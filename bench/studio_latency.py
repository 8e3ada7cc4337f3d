#!/usr/bin/python3
"""How soon the studio's page shows a new picture after a control moves (issue 26: within 0.5 s for a
recipe that runs in 0.1 s), in headless Chromium: the slider is moved with the keyboard and the time runs
until the picture's address changes and the new image has loaded. Includes the page's 120 ms debounce and
its 150 ms poll of the studio's state.

usage: bench/studio_latency.py [BUILD] [N] [LEVEL]
LEVEL (default 10) is that of the dragon the recipe saves as SVG: it always builds level 22 (about 0.1 s),
so LEVEL sets only how much the browser has to draw (level 18: a 3 MB SVG)."""
import os, re, statistics, subprocess, sys, tempfile, time
from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

build = sys.argv[1] if len(sys.argv) > 1 else "build"
n = int(sys.argv[2]) if len(sys.argv) > 2 else 10
level = int(sys.argv[3]) if len(sys.argv) > 3 else 10
recipe = """local curves = require "selfsim.curves"
local k = param("k", 1, {{ min = 1, max = 100 }})
local work = curves.dragon():curve(22):bbox()  -- builds 4,194,305 points: about 0.1 s a run
save(curves.dragon():curve({level}), "c.svg", {{ stroke_width = 1 + k / 100 }})
""".format(level=level)
with tempfile.TemporaryDirectory() as tmp:
    path = os.path.join(tmp, "r.lua")
    with open(path, "w") as f:
        f.write(recipe)
    one = time.monotonic()
    subprocess.run([os.path.join(build, "selfsim"), "run", path, "-o", os.path.join(tmp, "plain"), "-q"], check=True)
    print("one plain run (fresh process): %.3f s" % (time.monotonic() - one))
    studio = subprocess.Popen([os.path.join(build, "selfsim"), "studio", path, "--port", "0", "-o",
                               os.path.join(tmp, "out")], stdout=subprocess.PIPE, text=True)
    port = re.search(r"127\.0\.0\.1:(\d+)", studio.stdout.readline()).group(1)
    o = Options()
    for a in ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"]:
        o.add_argument(a)
    d = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=o)
    d.get("http://127.0.0.1:%s/" % port)
    loaded = "const i = document.querySelector('img'); return i && i.complete && i.naturalWidth > 0 ? i.src : null"
    while not d.execute_script(loaded):
        time.sleep(0.01)
    times = []
    for _ in range(n):
        time.sleep(0.5)
        before = d.execute_script(loaded)
        start = time.monotonic()
        d.find_element(By.ID, "param-k").send_keys(Keys.ARROW_RIGHT)
        while d.execute_script(loaded) in (None, before):
            time.sleep(0.005)
        times.append(time.monotonic() - start)
    d.quit()
    studio.terminate()
    studio.wait()
    print("slider to new picture: median %.3f s, min %.3f s, max %.3f s over %d moves" %
          (statistics.median(times), min(times), max(times), n))
