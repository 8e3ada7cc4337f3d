#!/usr/bin/python3
"""The studio in a real browser: headless Chromium (Debian's chromium and chromium-driver, driven by
python3-selenium) opens the page, moves a slider and checks that the picture changed, types a value outside
the range and checks that its error shows in place while the picture stays, picks a choice, saves the
recipe and sees the picture follow. Then what the page must refuse: another Host (DNS rebinding), a path out
of the output folder, a value outside its range. The waits are bounds against a hang, not timings.

usage: check_studio.py SELFSIM [SCREENSHOT.png]   exit 77 when Chromium or Selenium is missing"""
import http.client, os, re, shutil, signal, subprocess, sys, tempfile

from browser_lib import By, Keys, Options, Service, check, failures, until, webdriver

selfsim = sys.argv[1]

RECIPE = """local curves = require "selfsim.curves"
local level = param("level", 6, {{ min = 1, max = 12, doc = "levels of the curve" }})
local name = param("name", "dragon", {{ choices = {{ "dragon", "terdragon" }} }})
save(curves[name]():curve(level), "c.svg", {{ stroke = "{colour}" }})
"""

tmp = tempfile.mkdtemp()
recipe = os.path.join(tmp, "r.lua")
with open(recipe, "w") as f:
    f.write(RECIPE.format(colour="#7b2cbf"))
studio = subprocess.Popen([selfsim, "studio", recipe, "--port", "0", "-o", os.path.join(tmp, "out")],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
driver = None
try:
    line = studio.stdout.readline()
    port = re.search(r"127\.0\.0\.1:(\d+)", line)
    check(port is not None, "the studio says where it listens: " + line)
    port = int(port.group(1))

    def get(path, host=None, headers=()):
        c = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
        c.putrequest("GET", path, skip_host=True)
        c.putheader("Host", host or "127.0.0.1:%d" % port)
        for k, v in headers:
            c.putheader(k, v)
        c.endheaders()
        r = c.getresponse()
        return r.status, r.read()

    o = Options()
    for a in ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=1280,900"]:
        o.add_argument(a)
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=o)
    driver.get("http://127.0.0.1:%d/" % port)

    def picture():  # the drawn curve, once loaded: its address and its pixels
        img = driver.find_element(By.CSS_SELECTOR, 'img[alt="c.svg"]')
        if not driver.execute_script("return arguments[0].complete && arguments[0].naturalWidth > 0", img):
            return None
        return img.get_attribute("src"), img.screenshot_as_png

    first = until(picture)
    check(first is not None, "the page shows the first run's picture")
    svg_first = get("/out/c.svg")[1]

    # Move the slider two steps to the right, as the keyboard does.
    slider = driver.find_element(By.ID, "param-level")
    slider.send_keys(Keys.ARROW_RIGHT, Keys.ARROW_RIGHT)
    check(driver.find_element(By.ID, "number-level").get_attribute("value") == "8", "the slider moved to 8")
    moved = until(lambda: (lambda p: p if p and p[0] != first[0] else None)(picture()))
    check(moved is not None and moved[1] != first[1], "the picture changed after the slider moved")
    check(get("/out/c.svg")[1] != svg_first, "the output file changed after the slider moved")

    # A value outside the range: its error in place, the picture kept.
    box = driver.find_element(By.ID, "number-level")
    box.clear()
    box.send_keys("99")
    error = until(lambda: (lambda e: e.text if e.is_displayed() else None)(driver.find_element(By.ID, "error")))
    check(error is not None and "'level' must be in [1, 12]" in error, "a bad value shows its error: %r" % error)
    check(picture()[0] == moved[0], "a refused value keeps the last picture")

    # A choice, then a save of the recipe: the picture follows both.
    driver.find_element(By.ID, "param-name").send_keys("terdragon")
    chosen = until(lambda: (lambda p: p if p and p[0] != moved[0] else None)(picture()))
    check(chosen is not None, "the picture changed after a choice")
    with open(recipe + ".new", "w") as f:
        f.write(RECIPE.format(colour="#e63946"))
    os.replace(recipe + ".new", recipe)
    check(until(lambda: b"#e63946" in get("/out/c.svg")[1]) is not None, "a save of the recipe runs it again")
    check(until(lambda: (lambda p: p and p[0] != chosen[0])(picture())) is not None,
          "the page shows the run after the save")
    if len(sys.argv) > 2:
        driver.save_screenshot(sys.argv[2])

    # What the studio refuses.
    check(get("/state", host="evil.example:%d" % port)[0] == 403, "another Host is refused")
    check(get("/out/../r.lua")[0] == 404, "a path out of the output folder is refused")
    check(get("/run?level=99")[0] == 400, "a value outside its range is refused")
    check(get("/run?level=2.5")[0] == 400, "a fraction for an integer parameter is refused")
    check(get("/run?levle=3")[0] == 400, "a name that is no parameter is refused")
    # Another site's page cannot make the browser drive it (an <img src=".../run?..."> sends these).
    check(get("/run?level=3", headers=[("Origin", "https://evil.example")])[0] == 403, "a foreign Origin is refused")
    check(get("/run?level=3", headers=[("Sec-Fetch-Site", "cross-site")])[0] == 403, "a cross-site fetch is refused")
    # Connections that send nothing (a slowloris, a browser's preconnect) hold up no other request: with ten
    # of them open, a request is still answered (get's own 10 s limit would fail it otherwise).
    import socket
    idle = [socket.create_connection(("127.0.0.1", port)) for _ in range(10)]
    for s in idle[:5]:
        s.sendall(b"GET /params HTTP/1.1\r\n")  # half a request
    check(get("/params")[0] == 200, "a request is answered while idle connections are open")
    for s in idle:
        s.close()
finally:
    if driver:
        driver.quit()
    studio.send_signal(signal.SIGINT)
    try:
        code = studio.wait(20)
        check(code == 130, "the studio exits 130 at Ctrl-C, not %s" % code)
    except subprocess.TimeoutExpired:
        studio.kill()
        check(False, "the studio did not stop at Ctrl-C")
    shutil.rmtree(tmp, ignore_errors=True)

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
