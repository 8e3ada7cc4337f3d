#!/usr/bin/python3
"""The studio's HTTP under hostile clients, with real processes and sockets: a client reading a multi-MB output
very slowly (a tiny receive buffer, a few KB then a nap) beside a normal client, whose requests must all be
answered while the slow one still reads; the slow one then gets the whole file, byte for byte. Ctrl-C while a
slow client is mid-transfer ends the studio before that client is done, the transfer cut short. Then the request forms: bare-LF lines
are answered, a repeated Host, Origin or Sec-Fetch-Site is refused; a 1.5 MB file asked for, then a second
request or stray bytes on the same socket, still comes whole; a FIFO swapped in for the recipe is refused,
the studio still answering. The waits are bounds against a hang,
never timings: every assertion is about order or content.

usage: studio_clients.py SELFSIM"""
import os, shutil, signal, socket, sys, tempfile, threading, time

import studio_lib
from studio_lib import check, exchange, finish, get, until

selfsim = sys.argv[1]
tmp = tempfile.mkdtemp()
recipe = os.path.join(tmp, "r.lua")
with open(recipe, "w") as f:
    f.write('save(polyline { { 0, 0 }, { 1, 0 } }, "a.svg")\n')
out = os.path.join(tmp, "out")


def start_studio():
    p, port, line = studio_lib.start_studio(selfsim, recipe, out)
    if port is None:
        print("FAIL: the studio did not say where it listens: " + line + p.stdout.read())
        sys.exit(1)
    return p, port


class SlowReader(threading.Thread):
    """Asks for PATH with a tiny receive buffer and reads 4 KB every 20 ms until released, then at once."""

    def __init__(self, port, path):
        super().__init__(daemon=True)
        self.sock = socket.socket()
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        self.sock.settimeout(60)
        self.sock.connect(("127.0.0.1", port))
        self.sock.sendall(b"GET %s HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n" % (path.encode(), port))
        self.got = 0
        self.data = b""
        self.release = threading.Event()
        self.done = threading.Event()

    def run(self):
        data = bytearray()
        try:
            while True:
                slow = not self.release.is_set()
                chunk = self.sock.recv(4096 if slow else 1 << 20)
                if not chunk:
                    break
                data += chunk
                self.got = len(data)
                if slow:
                    time.sleep(0.02)
        except OSError:
            pass
        self.sock.close()
        self.data = bytes(data)
        self.done.set()


studio, port = start_studio()
try:
    check(until(lambda: os.path.exists(os.path.join(out, "a.svg"))), "the first run wrote a.svg")
    blob = os.urandom(16 << 20)  # well over what the kernel's socket buffers hold (4 MB each way by default)
    with open(os.path.join(out, "blob.bin"), "wb") as f:
        f.write(blob)

    # --- a slow reader beside a normal client -----------------------------------------------------------
    slow = SlowReader(port, "/out/blob.bin")
    slow.start()
    check(until(lambda: slow.got >= 65536 or slow.done.is_set()), "the slow reader gets its first 64 KB")
    answers = [get(port, p) for p in ["/params", "/state", "/out/a.svg", "/params", "/state", "/out/a.svg"]]
    slow_done_meanwhile = slow.done.is_set()
    check(all(status == 200 for status, _ in answers),
          "every normal request answered 200 while the slow reader reads: %s" % [s for s, _ in answers])
    check(not slow_done_meanwhile, "the normal requests were answered before the slow reader was done")
    # beside it, clients that never read and clients that send nothing hold up nobody either
    stalled = []
    for _ in range(3):
        s = socket.socket()
        s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        s.connect(("127.0.0.1", port))
        s.sendall(b"GET /out/blob.bin HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n" % port)
        stalled.append(s)
    idle = [socket.create_connection(("127.0.0.1", port)) for _ in range(200)]  # over the cap of 128
    status, _ = get(port, "/params")
    check(status == 200, "a request beside 3 stalled readers and 200 idle connections is answered (%s)" % status)
    check(not slow.done.is_set(), "... also before the slow reader was done")
    for s in stalled + idle:
        s.close()
    slow.release.set()
    slow.join(120)
    head, _, body = slow.data.partition(b"\r\n\r\n")
    check(head.startswith(b"HTTP/1.1 200 "), "the slow reader's answer is a 200: %r" % head[:40])
    check(body == blob, "the slow reader gets the whole file, byte-exact (%d of %d bytes)" % (len(body), len(blob)))

    # --- request forms ----------------------------------------------------------------------------------
    status, body = exchange(port, b"GET /params HTTP/1.1\nHost: 127.0.0.1:%d\n\n" % port)
    check(status == 200 and body.startswith(b"{"), "a bare-LF request is answered (%s)" % status)
    status, _ = exchange(port, b"GET /params HTTP/1.1\r\nHost: 127.0.0.1:%d\n\r\n" % port)
    check(status == 200, "a request mixing CRLF and LF is answered (%s)" % status)
    ours = b"http://127.0.0.1:%d" % port
    for name, first, last in [(b"Origin", b"http://evil.example", ours), (b"Origin", ours, b"http://evil.example"),
                              (b"Sec-Fetch-Site", b"cross-site", b"same-origin"),
                              (b"Sec-Fetch-Site", b"same-origin", b"cross-site"),
                              (b"Host", b"127.0.0.1:%d" % port, b"evil.example")]:
        status, _ = get(port, "/params", b"%s: %s\r\n%s: %s\r\n" % (name, first, name, last))
        check(status in (400, 403), "two %s headers (%s, then %s) refused (%s)" % (name, first, last, status))
    status, _ = get(port, "/params", b"origin: http://evil.example\r\nORIGIN: %s\r\n" % ours)
    check(status in (400, 403), "two Origin headers in different cases refused (%s)" % status)
    status, _ = get(port, "/params", b"Origin : http://evil.example\r\n")
    check(status in (400, 403), "a space before a header's colon refused (%s)" % status)
    status, _ = get(port, "/params", b"Origin:\r\n")
    check(status in (400, 403), "an empty Origin refused (%s)" % status)
    status, _ = get(port, "/params", b"X-A: 1\rOrigin: http://evil.example\r\n")
    check(status in (400, 403), "a bare CR inside a header line refused (%s)" % status)
    status, _ = get(port, "/params", b"Origin: %s\r\n" % ours)
    check(status == 200, "one Origin of our own is answered (%s)" % status)
    status, _ = exchange(port, b"GET /params HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n" % port, half_close=True)
    check(status == 200, "a request whose client then closes its sending side is answered (%s)" % status)

    # --- more bytes after a request for a large file ----------------------------------------------------
    # A second request on the same socket (or any stray bytes) sent once the answer has begun: the studio
    # reads no second request, but closing with them unread made the kernel reset the connection and drop
    # the answer's queued tail (the client got ~128 KB, then ECONNRESET). The nap lets the studio queue the
    # whole answer first; the check is about content only.
    middle = blob[: 3 << 19]  # 1.5 MB
    with open(os.path.join(out, "middle.bin"), "wb") as f:
        f.write(middle)
    for what, more in [("a pipelined second GET /params", b"GET /params HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n" % port),
                       ("64 KB of stray bytes", b"x" * 65536)]:
        s = socket.create_connection(("127.0.0.1", port), timeout=30)
        data = b""
        try:
            s.sendall(b"GET /out/middle.bin HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n" % port)
            data = s.recv(16)  # the answer has begun: the request was read
            s.sendall(more)
            time.sleep(0.3)
            while chunk := s.recv(65536):
                data += chunk
        except OSError as e:
            print("  (%s: %s after %d bytes)" % (what, e, len(data)))
        s.close()
        head, _, body = data.partition(b"\r\n\r\n")
        check(head.startswith(b"HTTP/1.1 200 ") and body == middle,
              "after %s, the whole 1.5 MB file comes, byte-exact (%d bytes)" % (what, len(body)))

    # --- a FIFO in the recipe's place -------------------------------------------------------------------
    # Reading the recipe's parameters again (in the studio's own process) opened it and waited there for a
    # writer: no request was answered until Ctrl-C. Now it is refused, and the page shows why.
    os.remove(recipe)
    os.mkfifo(recipe)
    state = until(lambda: (lambda a: a[0] == 200 and b"is a FIFO" in a[1] and a)(get(port, "/state")), 60, 0.2)
    check(bool(state), "a FIFO swapped in for the recipe is shown as the run's error, the studio answering")
    check(b"cannot open recipe '%s': is a FIFO, not a regular file" % recipe.encode() in (state or (0, b""))[1],
          "... naming the recipe: %r" % (state or (0, b""))[1][:300])
    status, _ = get(port, "/params")
    check(status == 200, "with a FIFO for a recipe, /params is still answered (%s)" % status)

    # --- Ctrl-C while a slow client is mid-transfer -----------------------------------------------------
    slow = SlowReader(port, "/out/blob.bin")
    slow.start()
    check(until(lambda: slow.got >= 65536 or slow.done.is_set()), "the second slow reader gets its first 64 KB")
    studio.send_signal(signal.SIGINT)
    code = None
    end = time.monotonic() + 60  # a bound against a hang, not a timing
    while code is None and time.monotonic() < end:
        pid, status = os.waitpid(studio.pid, os.WNOHANG)
        if pid == studio.pid:
            code = os.waitstatus_to_exitcode(status)
            studio.returncode = code
        else:
            time.sleep(0.02)
    check(code is not None and not slow.done.is_set(),
          "SIGINT ends the studio before the slow reader is done (exit %s, slow reader done: %s)"
          % (code, slow.done.is_set()))
    check(code == 130, "SIGINT: exit 130 (got %s)" % code)
    slow.release.set()
    slow.join(120)
    # What the kernel had taken in still arrives after the exit; a studio that stopped mid-transfer sent
    # no more than that (a few MB at most), one that finished the transfer first sent it all.
    body = slow.data.partition(b"\r\n\r\n")[2]
    check(len(body) < len(blob), "the studio stopped mid-transfer: the slow reader got %d of %d bytes"
          % (len(body), len(blob)))
finally:
    if studio.returncode is None:
        studio.kill()
        studio.wait()
    shutil.rmtree(tmp, ignore_errors=True)
finish()
