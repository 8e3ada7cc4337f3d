"""What the studio's robustness tests (studio_clients.py, studio_previews.py) share: counted checks, bounded
waits, starting a studio on a free port and HTTP exchanges with it. Imported from the scripts' own folder
(Python puts a script's folder first on its path); not a test itself."""
import re, socket, subprocess, sys, time

passed = failed = 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAIL: " + what, flush=True)


def finish():
    """Says how many checks passed and failed, and exits 1 when any failed."""
    print("%d passed, %d failed" % (passed, failed))
    sys.exit(1 if failed else 0)


def until(condition, seconds=60, step=0.05):
    """condition()'s first true value, asked every `step` s; None after `seconds` (a bound against a hang)."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        value = condition()
        if value:
            return value
        time.sleep(step)
    return None


def start_studio(selfsim, recipe, out, *extra):
    """(process, port, first line): a studio on a port of its choosing; port None when it did not say."""
    p = subprocess.Popen([selfsim, "studio", recipe, "--port", "0", "-o", out, *extra], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    line = p.stdout.readline()
    m = re.search(r"127\.0\.0\.1:(\d+)", line)
    return p, (int(m.group(1)) if m else None), line


def exchange(port, raw, timeout=30, half_close=False):
    """Sends raw bytes (then closes its sending side, if asked), reads to the end: (status or None, body).
    None also when nothing could be sent (no studio listening)."""
    try:
        s = socket.create_connection(("127.0.0.1", port), timeout=timeout)
    except OSError:
        return None, b""
    data = b""
    try:
        s.sendall(raw)
        if half_close:
            s.shutdown(socket.SHUT_WR)
        while chunk := s.recv(65536):
            data += chunk
    except OSError:
        pass
    finally:
        s.close()
    m = re.match(rb"HTTP/1\.1 (\d+) ", data)
    return (int(m.group(1)) if m else None), data.partition(b"\r\n\r\n")[2]


def get(port, path, extra=b""):
    """(status or None, body) of GET path, with `extra` header lines."""
    return exchange(port, b"GET %s HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n%s\r\n" % (path.encode(), port, extra))
