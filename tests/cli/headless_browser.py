"""headless_browser.py - one headless Chromium for a whole test script.

The browser tests (view_test.py, robot_meshes_test.py) open many pages. A
Chromium started per page (--dump-dom, then again for --screenshot) spent
seconds starting up for every one, and waited out a fixed virtual-time
budget each time. Here one Chromium, driven over the DevTools protocol on a
pipe (--remote-debugging-pipe: no port, no network), opens the pages in turn
in its one 1280x800 tab, each as a fresh document, and gives back the DOM and
screenshots that --dump-dom and --screenshot gave.

A page is ready when the viewer has built its scene (body data-ready="true")
or has reported an error (window.mdlcErrors); then a few frames of its render
loop run before anything is read, so that errors in drawing show too.
"""
import base64
import fcntl
import json
import os
import select
import subprocess
import time

# SwiftShader gives WebGL without a GPU
FLAGS = ["--headless=new", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
         "--use-angle=swiftshader", "--window-size=1280,800", "--no-first-run",
         "--no-default-browser-check"]

READY = ("document.body !== null && document.body.dataset.ready === 'true' || "
         "(window.mdlcErrors || []).length > 0")
# a few frames of the render loop (or 2 s, should frames not come)
SETTLE = ("new Promise((done) => { let n = 0; setTimeout(done, 2000); "
          "const frame = () => (++n >= 5 ? done() : requestAnimationFrame(frame)); "
          "requestAnimationFrame(frame); })")


def _above_4(fd):
    moved = fcntl.fcntl(fd, fcntl.F_DUPFD, 10)
    os.close(fd)
    return moved


class BrowserError(Exception):
    pass


class Browser:
    """One Chromium; open(url), then dom() and screenshot(png) of that page."""

    def __init__(self, path, timeout=120):
        self.timeout = timeout
        to_browser, self._send = os.pipe()
        self._receive, from_browser = os.pipe()
        # the ends Chromium gets, above 4, so that placing one on 3 or 4
        # overwrites not the other
        to_browser, from_browser = (_above_4(fd) for fd in (to_browser, from_browser))
        # Chromium reads the protocol from fd 3 and writes it to fd 4; every
        # other descriptor of this process is closed on exec (PEP 446)
        def protocol_fds():
            os.dup2(to_browser, 3)
            os.dup2(from_browser, 4)
        self._process = subprocess.Popen(
            [path, *FLAGS, "--remote-debugging-pipe", "about:blank"], preexec_fn=protocol_fds,
            close_fds=False, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL)
        os.close(to_browser)
        os.close(from_browser)
        self._buffer = b""
        self._id = 0
        self._session = None
        try:
            targets = self._call("Target.getTargets")["targetInfos"]
            page = next(t for t in targets if t["type"] == "page")
            self._session = self._call("Target.attachToTarget", targetId=page["targetId"],
                                       flatten=True)["sessionId"]
            self._call("Page.enable")
        except BaseException:
            self.close()
            raise

    def __enter__(self):
        return self

    def __exit__(self, *_):
        self.close()

    def close(self):
        if self._process.poll() is None:
            try:
                self._session = None
                self._call("Browser.close", timeout=10)
            except (BrowserError, OSError):
                pass
            try:
                self._process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self._process.kill()
                self._process.wait()
        for fd in (self._send, self._receive):
            try:
                os.close(fd)
            except OSError:
                pass

    def _message(self, deadline):
        while b"\0" not in self._buffer:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self._receive], [], [], left)[0]:
                raise BrowserError("Chromium did not answer in time")
            chunk = os.read(self._receive, 1 << 20)
            if not chunk:
                raise BrowserError("Chromium closed the DevTools pipe (did it crash?)")
            self._buffer += chunk
        message, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(message)

    def _call(self, method, timeout=None, **params):
        self._id += 1
        request = {"id": self._id, "method": method, "params": params}
        if self._session:
            request["sessionId"] = self._session
        data = json.dumps(request).encode() + b"\0"
        while data:
            data = data[os.write(self._send, data):]
        deadline = time.monotonic() + (timeout or self.timeout)
        while True:
            reply = self._message(deadline)
            if reply.get("id") == self._id:  # anything else is an event
                if "error" in reply:
                    raise BrowserError(f"{method}: {reply['error']}")
                return reply["result"]

    def evaluate(self, expression, promise=False):
        """The value of a JavaScript expression in the page; None when it throws."""
        result = self._call("Runtime.evaluate", expression=expression, returnByValue=True,
                            awaitPromise=promise)
        return None if "exceptionDetails" in result else result["result"].get("value")

    def open(self, url, for_screenshot=False, timeout=60):
        """Loads url as a new document (a page that differs only in its #hash
        too), and waits until it is ready or `timeout` seconds pass. As
        --screenshot did, a page opened for_screenshot fills the whole
        1280x800 window; otherwise, as for --dump-dom, the window keeps room
        for the browser's bars."""
        if for_screenshot:
            self._call("Emulation.setDeviceMetricsOverride", width=1280, height=800,
                       deviceScaleFactor=1, mobile=False)
        else:
            self._call("Emulation.clearDeviceMetricsOverride")
        self._call("Page.navigate", url="about:blank")
        self._call("Page.navigate", url=url)
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            try:
                if self.evaluate(READY):
                    break
            except BrowserError:  # the document was being replaced
                pass
            time.sleep(0.1)
        self.evaluate(SETTLE, promise=True)

    def dom(self):
        """The page's DOM as --dump-dom printed it."""
        return self.evaluate("document.documentElement.outerHTML") or ""

    def screenshot(self, png):
        """A PNG of the page, as --screenshot wrote it."""
        data = self._call("Page.captureScreenshot", format="png")["data"]
        with open(png, "wb") as f:
            f.write(base64.b64decode(data))
