"""A Chrome DevTools Protocol client over a pipe, for the tests and benchmarks of `prt view`.

Starts Debian's chromium headless with --remote-debugging-pipe: the browser reads commands on
its file descriptor 3 and writes replies and events on 4, each a JSON message ended by a NUL
byte. No WebSocket and no package beyond Python's own library are needed.

    with Browser() as b:
        page = b.open("http://127.0.0.1:8202/")
        page.evaluate("1 + 1")            # -> 2
"""
import json
import os
import shutil
import subprocess
import tempfile
import time


def find_chromium():
    """The path of Debian's chromium (or another Chromium on PATH), or None."""
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class CdpError(RuntimeError):
    pass


class Browser:
    def __init__(self, width=1280, height=900, extra_args=()):
        self.profile = tempfile.mkdtemp(prefix="prt-cdp-")
        to_child_r, self._to_child = os.pipe()
        self._from_child, from_child_w = os.pipe()
        args = [find_chromium() or "chromium", "--headless=new", "--remote-debugging-pipe", "--no-sandbox",
                "--no-first-run", "--no-default-browser-check", "--disable-extensions", "--disable-sync",
                "--disable-background-networking", "--disable-component-update", "--mute-audio",
                "--user-data-dir=" + self.profile, "--window-size=%d,%d" % (width, height)]
        args += list(extra_args)

        def child_fds():  # the pipes at 3 and 4, as the browser expects them, open across exec
            high_r, high_w = os.dup(to_child_r), os.dup(from_child_w)  # neither at 3 or 4 now
            os.dup2(high_r, 3)
            os.dup2(high_w, 4)

        # The descriptors are closed before exec only with close_fds, which runs after preexec_fn
        # and would close 3 and 4 again: the parent's pipe ends are marked close-on-exec instead.
        for fd in (self._to_child, self._from_child):
            os.set_inheritable(fd, False)
        self.process = subprocess.Popen(args, close_fds=False, preexec_fn=child_fds,
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_child_r)
        os.close(from_child_w)
        self._buffer = b""
        self._next_id = 0
        self.events = []

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        try:
            self.send("Browser.close", timeout=5)
        except Exception:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        for fd in (self._to_child, self._from_child):
            try:
                os.close(fd)
            except OSError:
                pass
        shutil.rmtree(self.profile, ignore_errors=True)

    def _read_message(self, deadline):
        import select
        while b"\0" not in self._buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                raise CdpError("no message from the browser in time")
            ready, _, _ = select.select([self._from_child], [], [], left)
            if ready:
                chunk = os.read(self._from_child, 1 << 20)
                if not chunk:
                    raise CdpError("the browser closed its pipe")
                self._buffer += chunk
        message, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(message)

    def send(self, method, params=None, session=None, timeout=60):
        """Sends a command and returns its result; events that arrive meanwhile are kept in events."""
        self._next_id += 1
        message = {"id": self._next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self._to_child, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            reply = self._read_message(deadline)
            if reply.get("id") == self._next_id:
                if "error" in reply:
                    raise CdpError("%s: %s" % (method, reply["error"]))
                return reply.get("result", {})
            self.events.append(reply)

    def pump(self, seconds):
        """Collects the events that arrive within `seconds`."""
        deadline = time.monotonic() + seconds
        try:
            while True:
                self.events.append(self._read_message(deadline))
        except CdpError as e:
            if "in time" not in str(e):
                raise

    def open(self, url):
        target = self.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        page = Page(self, session)
        for domain in ("Runtime", "Log", "Page"):
            page.send(domain + ".enable")
        page.send("Page.navigate", {"url": url})
        return page


class Page:
    def __init__(self, browser, session):
        self.browser = browser
        self.session = session

    def send(self, method, params=None, timeout=60):
        return self.browser.send(method, params, session=self.session, timeout=timeout)

    def evaluate(self, expression, timeout=60):
        """The value of a JavaScript expression (awaited when it is a promise)."""
        result = self.send("Runtime.evaluate", {"expression": expression, "returnByValue": True,
                                                "awaitPromise": True}, timeout=timeout)
        if "exceptionDetails" in result:
            raise CdpError("%s: %s" % (expression, json.dumps(result["exceptionDetails"])[:500]))
        return result["result"].get("value")

    def wait_for(self, expression, timeout=60, interval=0.05):
        """Waits until the expression is truthy; returns its value."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            value = self.evaluate(expression)
            if value:
                return value
            time.sleep(interval)
        raise CdpError("timed out waiting for: " + expression)

    def mouse(self, kind, x, y, button="left", buttons=1):
        self.send("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, "button": button,
                                               "buttons": buttons if kind != "mouseReleased" else 0,
                                               "clickCount": 1 if kind != "mouseMoved" else 0})

    def errors(self):
        """The console errors and uncaught exceptions seen so far, as text."""
        found = []
        for e in self.browser.events:
            if e.get("sessionId") != self.session:
                continue
            method, params = e.get("method"), e.get("params", {})
            if method == "Runtime.exceptionThrown":
                found.append("exception: " + json.dumps(params.get("exceptionDetails", {}))[:300])
            elif method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
                found.append("console.%s: %s" % (params["type"], json.dumps(params.get("args", []))[:300]))
            elif method == "Log.entryAdded" and params.get("entry", {}).get("level") == "error":
                found.append("log: " + params["entry"].get("text", ""))
        return found
