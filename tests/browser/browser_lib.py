"""What the studio's browser tests share: the skip (exit 77) where Chromium, chromium-driver or Selenium is
missing, the failures with check(), and until() for waits that are bounds against a hang, not timings."""
import os
import shutil
import sys
import time

try:
    from selenium import webdriver  # noqa: F401  (the tests take Selenium's names from here)
    from selenium.webdriver.chrome.options import Options  # noqa: F401
    from selenium.webdriver.chrome.service import Service  # noqa: F401
    from selenium.webdriver.common.action_chains import ActionChains  # noqa: F401
    from selenium.webdriver.common.by import By  # noqa: F401
    from selenium.webdriver.common.keys import Keys  # noqa: F401
except ImportError:
    print("skipped: python3-selenium is not installed (make test installs it)")
    sys.exit(77)
if not shutil.which("chromium") or not os.path.exists("/usr/bin/chromedriver"):
    print("skipped: chromium or chromium-driver is not installed (make test installs them)")
    sys.exit(77)

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL: " + what)


def until(condition, seconds=30):
    """condition()'s first true value within `seconds` (an exception counts as not yet), else None."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        try:
            value = condition()
            if value:
                return value
        except Exception:
            pass
        time.sleep(0.1)
    return None
