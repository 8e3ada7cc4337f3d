#!/usr/bin/python3
"""The studio's 3D views in a real browser: headless Chromium (Debian's chromium and chromium-driver, driven by
python3-selenium) with WebGL drawn by SwiftShader opens the page of a recipe that makes a surface, a 3D curve,
a growth series and an SVG. Each 3D result is a canvas whose pixels are not blank, and change when the view
is dragged round (real mouse events, through OrbitControls); the series' slider draws another step; the SVG
stays an SVG picture. Then the page with WebGL off, and with three.js missing: the preview PNGs, and the
reason on the page. And the /three/ addresses: the two on the list answer, every other is refused. The
waits are bounds against a hang, not timings.

usage: check_studio_3d.py SELFSIM [SCREENSHOT.png]
exit 77 when Chromium, Selenium or libjs-three is missing"""
import http.client, os, re, shutil, signal, subprocess, sys, tempfile

import browser_lib
from browser_lib import ActionChains, By, Keys, Options, Service, check, failures, webdriver

if not os.path.exists("/usr/share/javascript/three/build/three.min.js"):
    print("skipped: libjs-three is not installed (make deps installs it)")
    sys.exit(77)

selfsim = sys.argv[1]


def until(condition, seconds=60):  # software WebGL draws slowly: longer bounds
    return browser_lib.until(condition, seconds)


RECIPE = """local levels = param("levels", 3, { min = 1, max = 4 })
local ball = volume.sphere { center = { 0, 0, 0 }, radius = 1 }
local s = exclusion.surface { region = ball, start = { { -.5, -.4, 0 }, { .5, -.4, 0 }, { 0, .5, 0 } },
                              radius = 0.3, factor = 0.8, levels = levels }
save(s, "surface.vtp")
save(s:levels(), "growth.pvd")
local tree = lsystem { axiom = "A", angle = 30, rules = { "A -> F [ & + A ] [ ^ - A ] F A" } }
save(tree:curve { level = 4, normalize = false }, "tree.vtp")
local koch = lsystem { axiom = "F", angle = 90, rules = { "F -> F+F-F-F+F" } }:curve(2)
save(koch, "koch.svg")
save(koch, "koch.vtp")
"""

# The share of a canvas's pixels that are not the white background, and its pixels kept as window[key] (and
# the share that differ from window[before], when given).
INK = """
const c = arguments[0], key = arguments[1], before = arguments[2];
const t = document.createElement("canvas");
t.width = c.width; t.height = c.height;
const g = t.getContext("2d");
g.drawImage(c, 0, 0);
const d = g.getImageData(0, 0, t.width, t.height).data;
let ink = 0, changed = 0;
const old = before ? window[before] : null;
for (let i = 0; i < d.length; i += 4) {
  if (d[i] < 240 || d[i + 1] < 240 || d[i + 2] < 240) ++ink;
  if (old && (Math.abs(d[i] - old[i]) > 8 || Math.abs(d[i + 1] - old[i + 1]) > 8 || Math.abs(d[i + 2] - old[i + 2]) > 8)) ++changed;
}
window[key] = d;
return [ink / (d.length / 4), changed / (d.length / 4)];
"""

tmp = tempfile.mkdtemp()
recipe = os.path.join(tmp, "r.lua")
with open(recipe, "w") as f:
    f.write(RECIPE)
no_three = os.path.join(tmp, "no-three")
os.mkdir(no_three)
studios, drivers = [], []


def start_studio(env=None):
    p = subprocess.Popen([selfsim, "studio", recipe, "--port", "0", "-o", os.path.join(tmp, "out")],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         env=dict(os.environ, **(env or {})))
    studios.append(p)
    line = p.stdout.readline()
    port = re.search(r"127\.0\.0\.1:(\d+)", line)
    check(port is not None, "the studio says where it listens: " + line)
    return int(port.group(1))


def browser(webgl):
    o = Options()
    flags = ["--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1400,1000"]
    # WebGL in software (SwiftShader through ANGLE): no GPU needed. Off: no WebGL context at all.
    flags += ["--use-angle=swiftshader", "--enable-unsafe-swiftshader"] if webgl else ["--disable-3d-apis"]
    for a in flags:
        o.add_argument(a)
    d = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=o)
    drivers.append(d)
    return d


def get(port, path):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    c.request("GET", path)
    r = c.getresponse()
    return r.status, r.getheader("Content-Type"), r.read()


def views_ready(driver):
    # The page's views, once every one has drawn its first frame (or given up with a reason).
    return driver.execute_script("""
        const s = window.studio3d;
        if (!s || s.reason === null) return null;
        const v = Object.values(s.views);
        if (!v.length || !v.every(x => x.ready || x.error)) return null;
        return v.map(x => [x.name, !!x.ready, x.error || ""]);""")


def output(driver, name):
    return driver.find_element(By.CSS_SELECTOR, 'div.output[data-name="%s"]' % name)


try:
    port = start_studio()

    # The /three/ addresses: the two on the list, from the installed package; nothing else.
    status, kind, body = get(port, "/three/three.min.js")
    check(status == 200 and kind.startswith("text/javascript") and b"REVISION" in body,
          "three.min.js is served as JavaScript: %s %s" % (status, kind))
    check(get(port, "/three/OrbitControls.js")[0] == 200, "OrbitControls.js is served")
    for path in ["/three/../r.lua", "/three/%2e%2e/r.lua", "/three/build/three.min.js", "/three/three.js",
                 "/three/OrbitControls.js/..", "/three/examples/js/controls/OrbitControls.js", "/three/",
                 "/three//three.min.js", "/three/three.min.js/", "/three/THREE.MIN.JS"]:
        check(get(port, path)[0] == 404, "an address off the list is refused: " + path)

    # WebGL on: every 3D result is a view.
    driver = browser(True)
    driver.get("http://127.0.0.1:%d/" % port)
    ready = until(lambda: views_ready(driver))
    check(ready is not None, "the views draw")
    ready = {name: (ok, why) for name, ok, why in ready or []}
    check(set(ready) == {"surface.vtp", "growth.pvd", "tree.vtp"}, "a view per 3D result: %s" % sorted(ready))
    check(all(ok for ok, _ in ready.values()), "every view drew: %s" % ready)
    check(driver.execute_script("return window.studio3d.reason") == "", "no reason given when views draw")
    check(not driver.find_element(By.ID, "view-note").is_displayed(), "no note when every 3D result is a view")
    svg = driver.find_element(By.CSS_SELECTOR, 'img[alt="koch.svg"]')
    check(svg.get_attribute("src").split("?")[0].endswith("/out/koch.svg"), "2D stays an SVG picture")
    # The same drawing saved as an SVG and a .vtp is drawn once, as the SVG; the .vtp says so, not a bare link.
    koch_vtp = output(driver, "koch.vtp").text
    check("drawn as koch.svg" in koch_vtp, "koch.vtp says it is drawn as koch.svg: %r" % koch_vtp)

    # (A curve is drawn in lines a pixel wide: less of its canvas is ink than of a surface's.)
    for name, least in [("surface.vtp", 0.01), ("tree.vtp", 0.002), ("growth.pvd", 0.01)]:
        canvas = output(driver, name).find_element(By.TAG_NAME, "canvas")
        ink = driver.execute_script(INK, canvas, "before")[0]
        check(ink > least, "%s: the canvas draws something (%.4f of its pixels)" % (name, ink))
        legend = output(driver, name).find_element(By.CLASS_NAME, "legend").text
        check(name == "tree.vtp" or "level" in legend, "%s: its legend names the field: %r" % (name, legend))
        if name == "growth.pvd":
            continue
        # A drag across the canvas, as a person's mouse: OrbitControls turns the camera round.
        ActionChains(driver).move_to_element(canvas).click_and_hold().move_by_offset(150, 40).release().perform()
        changed = until(lambda: (lambda r: r[1] if r[1] > least else None)(
            driver.execute_script(INK, canvas, "after", "before")), 10)
        check(changed is not None, "%s: the picture changes when the view is dragged round" % name)

    # The series: opened at its last step, with one legend; the slider draws the first.
    growth = output(driver, "growth.pvd")
    slider = growth.find_element(By.CSS_SELECTOR, "input.step")
    check(slider.get_attribute("max") == "3" and slider.get_attribute("value") == "3",
          "the series opens at its last of 4 steps")
    canvas = growth.find_element(By.TAG_NAME, "canvas")
    legend = growth.find_element(By.CLASS_NAME, "legend").text
    driver.execute_script(INK, canvas, "last")
    slider.send_keys(Keys.HOME)
    check(until(lambda: driver.execute_script("return window.studio3d.views['growth.pvd'].step") == 0, 20),
          "the slider steps the series to its first step")
    stepped = driver.execute_script(INK, canvas, "first", "last")
    check(stepped[1] > 0.005, "the first step draws differently from the last (%.4f of pixels)" % stepped[1])
    check(stepped[0] > 0.0005, "the first step draws something")
    check("step 1 of 4" in growth.text, "the step is named beside the slider")
    check(growth.find_element(By.CLASS_NAME, "legend").text == legend, "one legend for every step")
    if len(sys.argv) > 2:
        driver.save_screenshot(sys.argv[2])

    # Another run (the slider of its parameter moved): the surface's view is looked at as it was left.
    turned = driver.execute_script("return window.studio3d.views['surface.vtp'].direction()")
    before = driver.execute_script("return window.studio3d.views['surface.vtp'].generation")
    driver.find_element(By.ID, "param-levels").send_keys(Keys.ARROW_LEFT)
    again = until(lambda: driver.execute_script(
        "const v = window.studio3d.views['surface.vtp'];"
        "return v && v.ready && v.generation > arguments[0] ? {d: v.direction()} : null", before))
    check(again is not None, "the view is drawn again after another run")
    check(again is not None and max(abs(a - b) for a, b in zip(again["d"], turned)) < 1e-6,
          "the view keeps the direction it was turned to: %s, then %s" % (turned, again and again["d"]))

    # A view the studio could not make (its index says why): that result's PNG, and the reason under it.
    with open(os.path.join(tmp, "out", ".studio", "tree.vtp.3d", "index.json"), "w") as f:
        f.write('{"error": "cannot read \'tree.vtp\': a test\'s reason"}\n')
    driver.get("http://127.0.0.1:%d/" % port)
    reason = until(lambda: output(driver, "tree.vtp").find_element(By.CLASS_NAME, "view-error").text)
    check(reason == "no 3D view: cannot read 'tree.vtp': a test's reason", "a view not made says why: %r" % reason)
    check(until(lambda: output(driver, "tree.vtp").find_element(By.CSS_SELECTOR, 'img[alt="tree.vtp"]')) is not None,
          "a view not made shows its PNG")
    check(until(lambda: views_ready(driver)) is not None and
          output(driver, "surface.vtp").find_elements(By.TAG_NAME, "canvas"), "the other views still draw")

    # WebGL off: the preview PNGs, and why.
    off = browser(False)
    off.get("http://127.0.0.1:%d/" % port)
    note = until(lambda: (lambda e: e.text if e.is_displayed() else None)(off.find_element(By.ID, "view-note")))
    check(note is not None and "WebGL" in note, "without WebGL the page says why: %r" % note)
    png = until(lambda: (lambda i: i.get_attribute("src") if off.execute_script(
        "return arguments[0].complete && arguments[0].naturalWidth > 0", i) else None)(
        off.find_element(By.CSS_SELECTOR, 'img[alt="surface.vtp"]')))
    check(png is not None and ".studio/surface.vtp.png" in png, "without WebGL the PNG preview shows: %s" % png)
    check(not off.find_elements(By.TAG_NAME, "canvas"), "without WebGL no canvas is made")

    # three.js missing (SELFSIM_THREE at an empty folder): the same, with that reason.
    first = studios.pop()
    first.send_signal(signal.SIGINT)
    check(first.wait(20) == 130, "the studio exits 130 at Ctrl-C")
    port = start_studio({"SELFSIM_THREE": no_three})
    check(get(port, "/three/three.min.js")[0] == 404, "without three.js its address is not found")
    driver.get("http://127.0.0.1:%d/" % port)
    note = until(lambda: (lambda e: e.text if e.is_displayed() else None)(driver.find_element(By.ID, "view-note")))
    check(note is not None and "libjs-three" in note, "without three.js the page says why: %r" % note)
    check(until(lambda: driver.find_element(By.CSS_SELECTOR, 'img[alt="growth.pvd"]')) is not None,
          "without three.js the PNG preview shows")
finally:
    for d in drivers:
        d.quit()
    for s in studios:
        s.send_signal(signal.SIGINT)
        try:
            s.wait(20)
        except subprocess.TimeoutExpired:
            s.kill()
            check(False, "the studio did not stop at Ctrl-C")
    shutil.rmtree(tmp, ignore_errors=True)

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
