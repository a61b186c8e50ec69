# SPDX-License-Identifier: MIT
"""cdp: drive headless Chromium through its DevTools protocol, standard
library only: a local HTTP server for a folder, the browser on a page of
it, and JavaScript evaluated there. Used by tests/web_check.py and
tools/web_screenshot.py.

    with Browser("build/web") as b:
        b.open("index.html")
        value = b.eval("await fixtrace.ready; return 1 + 1")
"""
import base64
import functools
import http.server
import json
import os
import re
import shutil
import socket
import struct
import subprocess
import tempfile
import threading
import time
import urllib.request


def find_chromium():
    """The browser's command, or None."""
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


class _Socket:
    """A WebSocket client of just what the protocol needs: text frames
    out (masked), text frames in (unfragmented or fragmented)."""

    def __init__(self, url):
        m = re.match(r"ws://([^/:]+):(\d+)(/.*)", url)
        self.s = socket.create_connection((m.group(1), int(m.group(2))))
        key = base64.b64encode(os.urandom(16)).decode()
        self.s.sendall(("GET %s HTTP/1.1\r\nHost: %s:%s\r\n"
                        "Upgrade: websocket\r\nConnection: Upgrade\r\n"
                        "Sec-WebSocket-Key: %s\r\n"
                        "Sec-WebSocket-Version: 13\r\n\r\n" %
                        (m.group(3), m.group(1), m.group(2), key)).encode())
        head = b""
        while b"\r\n\r\n" not in head:
            chunk = self.s.recv(1)
            if not chunk:
                raise OSError("DevTools closed the connection")
            head += chunk
        if b" 101 " not in head.split(b"\r\n")[0]:
            raise OSError("no WebSocket: %r" % head[:80])

    def _recv(self, n):
        buf = b""
        while len(buf) < n:
            chunk = self.s.recv(n - len(buf))
            if not chunk:
                raise OSError("DevTools closed the connection")
            buf += chunk
        return buf

    def send(self, text):
        data = text.encode()
        head = bytearray([0x81])
        n = len(data)
        if n < 126:
            head.append(0x80 | n)
        elif n < 65536:
            head.append(0x80 | 126)
            head += struct.pack(">H", n)
        else:
            head.append(0x80 | 127)
            head += struct.pack(">Q", n)
        mask = os.urandom(4)
        head += mask
        self.s.sendall(bytes(head) + bytes(b ^ mask[i % 4]
                                           for i, b in enumerate(data)))

    def recv(self):
        parts = []
        while True:
            b0, b1 = self._recv(2)
            n = b1 & 0x7F
            if n == 126:
                n = struct.unpack(">H", self._recv(2))[0]
            elif n == 127:
                n = struct.unpack(">Q", self._recv(8))[0]
            data = self._recv(n)
            op = b0 & 0x0F
            if op == 0x8:
                raise OSError("DevTools closed the WebSocket")
            if op in (0x9, 0xA):  # ping, pong: not used by DevTools
                continue
            parts.append(data)
            if b0 & 0x80:
                return b"".join(parts).decode()

    def close(self):
        self.s.close()


class Browser:
    """A served folder and a headless Chromium on it."""

    def __init__(self, folder, width=1400, height=1000, timeout=60):
        self.folder = os.path.abspath(folder)
        self.size = (width, height)
        self.timeout = timeout
        self.next_id = 0

    def __enter__(self):
        handler = functools.partial(_Quiet, directory=self.folder)
        self.httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0),
                                                     handler)
        threading.Thread(target=self.httpd.serve_forever,
                         daemon=True).start()
        self.base = "http://127.0.0.1:%d/" % self.httpd.server_address[1]
        self.profile = tempfile.mkdtemp(prefix="fixtrace-chromium-")
        self.proc = subprocess.Popen(
            [find_chromium(), "--headless", "--no-sandbox", "--disable-gpu",
             "--no-first-run", "--no-default-browser-check",
             "--disable-extensions", "--remote-debugging-port=0",
             "--remote-debugging-address=127.0.0.1",
             "--user-data-dir=" + self.profile,
             "--window-size=%d,%d" % self.size, "about:blank"],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE, text=True)
        port = None
        end = time.time() + self.timeout
        while port is None and time.time() < end:
            line = self.proc.stderr.readline()
            if not line and self.proc.poll() is not None:
                raise OSError("chromium exited with status %d" %
                              self.proc.returncode)
            m = re.search(r"DevTools listening on ws://[^:]+:(\d+)/", line)
            if m:
                port = int(m.group(1))
        if port is None:
            raise OSError("chromium did not start its DevTools server")
        # Keep reading the browser's messages so its pipe never fills.
        threading.Thread(target=self.proc.stderr.read, daemon=True).start()
        with urllib.request.urlopen("http://127.0.0.1:%d/json/list" %
                                    port) as r:
            pages = [t for t in json.load(r) if t["type"] == "page"]
        self.ws = _Socket(pages[0]["webSocketDebuggerUrl"])
        return self

    def __exit__(self, *exc):
        try:
            self.ws.close()
        except (AttributeError, OSError):
            pass
        self.proc.terminate()
        try:
            self.proc.wait(10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        self.httpd.shutdown()
        shutil.rmtree(self.profile, ignore_errors=True)

    def call(self, method, **params):
        """One protocol command; returns its result (events are
        skipped)."""
        self.next_id += 1
        me = self.next_id
        self.ws.send(json.dumps({"id": me, "method": method,
                                 "params": params}))
        while True:
            msg = json.loads(self.ws.recv())
            if msg.get("id") == me:
                if "error" in msg:
                    raise OSError("%s: %s" % (method, msg["error"]))
                return msg["result"]

    def open(self, path):
        """Loads a page of the served folder and waits for its load
        event."""
        self.call("Page.enable")
        self.call("Page.navigate", url=self.base + path)
        end = time.time() + self.timeout
        while time.time() < end:
            if self.eval("return document.readyState") == "complete":
                return
            time.sleep(0.05)
        raise OSError("the page did not load")

    def eval(self, body):
        """Runs body as the body of an async function in the page (await
        allowed; `return X` gives X, as JSON carries it). A JavaScript
        exception raises OSError."""
        expr = "(async () => {\n%s\n})()" % body
        r = self.call("Runtime.evaluate", expression=expr,
                      awaitPromise=True, returnByValue=True,
                      timeout=self.timeout * 1000)
        if "exceptionDetails" in r:
            d = r["exceptionDetails"]
            raise OSError("JavaScript: %s" % d.get("exception", {}).get(
                "description", d.get("text")))
        return r["result"].get("value")

    def screenshot(self, path):
        """The whole page, at the window's width, as a PNG file."""
        size = self.call("Page.getLayoutMetrics")["cssContentSize"]
        self.call("Emulation.setDeviceMetricsOverride", width=self.size[0],
                  height=int(size["height"]) + 1, deviceScaleFactor=1,
                  mobile=False)
        r = self.call("Page.captureScreenshot", format="png")
        with open(path, "wb") as f:
            f.write(base64.b64decode(r["data"]))

