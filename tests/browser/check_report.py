#!/usr/bin/env python3
"""Opens fragsim's HTML report from disk in headless Chromium and checks it the way a reader
would see it: the page loads, the console has no error (a broken image or any attempt to reach
the network logs one), every <img> decoded (naturalWidth > 0), every inline <svg> has a size, and
nothing outside the report's folder or a data: URI was loaded. Then takes a full-page screenshot
and checks it is a PNG with more than one colour in it.

The 3D view (three.js on software WebGL: Chromium's SwiftShader, as there is no GPU) must be
there and draw: its canvas has pixels other than the background, moving the time slider changes
them (two screenshots of the canvas differ), the camera view draws too, and nothing was logged as
an error. A page without the view, or whose view reports a failure (no WebGL), fails.

Drives chromedriver over WebDriver (plain HTTP and JSON), with the standard library only.
Usage: check_report.py PAGE.html SCREENSHOT.png [--width PX] [--chromium PATH]
       [--chromedriver PATH]
Exits 0 if every check passed, 1 with one line per failed check otherwise.
"""

import argparse
import base64
import json
import os
import pathlib
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request
import zlib

# The flags the report is checked with: no sandbox (CI runs as root), no GPU, and nothing that
# would talk to the network on its own. host-resolver-rules makes any host name unresolvable, so
# a page that tried to fetch a font or a script from the web would log an error and fail.
CHROMIUM_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-dev-shm-usage",
    "--hide-scrollbars",
    "--force-device-scale-factor=1",
    "--host-resolver-rules=MAP * ~NOTFOUND",
    # WebGL without a GPU: ANGLE on SwiftShader, Chromium's CPU renderer (--disable-gpu alone
    # leaves WebGL off, and the 3D view would fail).
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
]

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
WEBDRIVER_ELEMENT = "element-6066-11e4-a52e-4f735466cecf"

# The 3D view's scene background and the clear colour around a letterboxed camera view.
VIEWER_BACKGROUND = {(0xf4, 0xf6, 0xf8), (0xff, 0xff, 0xff)}
PNG_END = b"IEND\xaeB`\x82"  # the IEND chunk's type and CRC: the last 8 bytes of a PNG file

# Runs in the page after it loaded; returns what the checks need.
PAGE_PROBE = """
const images = Array.from(document.images).map(img => ({
  src: img.getAttribute('src'), complete: img.complete, naturalWidth: img.naturalWidth,
  naturalHeight: img.naturalHeight}));
const svgs = Array.from(document.querySelectorAll('svg')).map(svg => {
  const r = svg.getBoundingClientRect();
  return {label: svg.getAttribute('aria-label') || '', width: r.width, height: r.height};
});
const resources = performance.getEntriesByType('resource').map(r => r.name);
const links = Array.from(document.querySelectorAll('[src],[href]')).map(
  e => e.getAttribute('src') || e.getAttribute('href'));
return {readyState: document.readyState, title: document.title, images: images, svgs: svgs,
        resources: resources, links: links,
        width: document.documentElement.scrollWidth,
        height: document.documentElement.scrollHeight};
"""


class WebDriver:
    """The few WebDriver commands needed, as JSON over HTTP to a local chromedriver."""

    def __init__(self, port):
        self.base = "http://127.0.0.1:%d" % port
        self.session = None

    def call(self, method, path, body=None, timeout=60):
        data = None if body is None else json.dumps(body).encode()
        req = urllib.request.Request(self.base + path, data=data, method=method,
                                     headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(req, timeout=timeout) as resp:
                return json.loads(resp.read().decode() or "{}").get("value")
        except urllib.error.HTTPError as e:
            detail = e.read().decode(errors="replace")
            try:
                detail = json.loads(detail)["value"]["message"].splitlines()[0]
            except (ValueError, KeyError, TypeError, IndexError):
                pass
            raise RuntimeError("%s %s: HTTP %d: %s" % (method, path, e.code, detail)) from None

    def s(self, path):
        return "/session/%s%s" % (self.session, path)


def free_port():
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def wait_ready(driver, proc, seconds=120):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if proc.poll() is not None:
            raise RuntimeError("chromedriver exited with status %d" % proc.returncode)
        try:
            if driver.call("GET", "/status", timeout=2).get("ready"):
                return
        except (OSError, RuntimeError):
            pass
        time.sleep(0.1)
    raise RuntimeError("chromedriver not ready after %d s" % seconds)


def browser_log(driver):
    # chromedriver's log endpoint (not in the W3C standard); the legacy path as a fallback.
    try:
        return driver.call("POST", driver.s("/se/log"), {"type": "browser"}) or []
    except RuntimeError:
        return driver.call("POST", driver.s("/log"), {"type": "browser"}) or []


def full_page_png(driver, width, height):
    """The whole page, not just the window, through the DevTools protocol; the window's
    screenshot if chromedriver does not pass DevTools commands on."""
    try:
        shot = driver.call("POST", driver.s("/goog/cdp/execute"), {
            "cmd": "Page.captureScreenshot",
            "params": {"format": "png", "captureBeyondViewport": True,
                       "clip": {"x": 0, "y": 0, "width": width, "height": height, "scale": 1}}})
        return base64.b64decode(shot["data"])
    except (RuntimeError, KeyError, TypeError):
        return base64.b64decode(driver.call("GET", driver.s("/screenshot")))


def png_idat(png):
    """The compressed pixel data of `png`: its IDAT chunks joined, in order."""
    idat = b""
    at = 8
    while at + 8 <= len(png):
        length, kind = struct.unpack(">I4s", png[at:at + 8])
        if kind == b"IDAT":
            idat += png[at + 8:at + 8 + length]
        at += 12 + length
    return idat


def png_problems(png):
    """Why `png` is not a usable screenshot, or [] if it is: the signature, a size, and more than
    one distinct byte in the pixel data (a blank page would be one colour)."""
    if len(png) < 64 or not png.startswith(PNG_SIGNATURE):
        return ["screenshot: not a PNG (%d bytes)" % len(png)]
    width, height = struct.unpack(">II", png[16:24])
    if width == 0 or height == 0:
        return ["screenshot: empty image %dx%d" % (width, height)]
    try:
        pixels = zlib.decompress(png_idat(png))
    except zlib.error as e:
        return ["screenshot: pixel data does not decompress (%s)" % e]
    # The rows are filtered (each byte minus a prediction from its neighbours), so a one-colour
    # image holds only that colour's few bytes and zeros; a drawn page holds nearly all 256 values.
    if len(set(pixels[::7])) < 16:
        return ["screenshot: the page rendered as a blank image"]
    return []


def png_pixels(png):
    """(width, height, rows of (r, g, b) tuples) of an 8-bit RGB or RGBA PNG, as Chromium writes
    its screenshots."""
    width, height, depth, colour = struct.unpack(">IIBB", png[16:26])
    if depth != 8 or colour not in (2, 6):
        raise RuntimeError("screenshot: PNG of depth %d, colour type %d" % (depth, colour))
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(png_idat(png))
    stride = width * channels
    rows = []
    previous = bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            left = line[x - channels] if x >= channels else 0
            up = previous[x]
            corner = previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + left) & 255
            elif kind == 2:
                line[x] = (line[x] + up) & 255
            elif kind == 3:
                line[x] = (line[x] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                pred = left if pa <= pb and pa <= pc else up if pb <= pc else corner
                line[x] = (line[x] + pred) & 255
        rows.append([tuple(line[i:i + 3]) for i in range(0, stride, channels)])
        previous = line
    return width, height, rows


def drawn_share(rows):
    """The share of pixels that are not the 3D view's background."""
    total = sum(len(r) for r in rows)
    drawn = sum(1 for r in rows for px in r if px not in VIEWER_BACKGROUND)
    return drawn / max(total, 1)


def differing_pixels(a, b):
    return sum(1 for ra, rb in zip(a, b) for pa, pb in zip(ra, rb) if pa != pb)


# Sets the 3D view's controls as a reader would and waits for the frame to be drawn.
VIEWER_SET = """
const [id, value] = arguments;
const control = document.getElementById(id);
control.value = value;
control.dispatchEvent(new Event('input'));
return control.value;
"""

VIEWER_STATE = """
const root = document.getElementById('viewer');
const status = document.getElementById('viewer-status');
const missing = document.getElementById('viewer-missing');
return {state: root ? root.dataset.state : null, status: status ? status.textContent : '',
        missing: missing ? missing.textContent : '',
        max: root ? document.getElementById('viewer-time').max : '0'};
"""


def canvas_png(driver):
    found = driver.call("POST", driver.s("/element"),
                        {"using": "css selector", "value": "#viewer-canvas"})
    element = found[WEBDRIVER_ELEMENT]
    return base64.b64decode(driver.call("GET", driver.s("/element/%s/screenshot" % element)))


def check_viewer(driver, screenshot):
    """The 3D view's checks; returns the problems found."""
    deadline = time.monotonic() + 60
    state = driver.call("POST", driver.s("/execute/sync"), {"script": VIEWER_STATE, "args": []})
    while state["state"] == "loading" and time.monotonic() < deadline:
        time.sleep(0.2)
        state = driver.call("POST", driver.s("/execute/sync"),
                            {"script": VIEWER_STATE, "args": []})
    if state["state"] is None:
        return ["3D view: not in the page: " + (state["missing"] or "no #viewer element")]
    if state["state"] != "ready":
        return ["3D view: %s: %s" % (state["state"], state["status"])]
    problems = []
    shots = {}
    for name, settings in (("start", [("viewer-time", "0")]),
                           ("middle", [("viewer-time", str(int(state["max"]) // 2))]),
                           ("camera", [("viewer-mode", "camera")])):
        for control, value in settings:
            driver.call("POST", driver.s("/execute/sync"),
                        {"script": VIEWER_SET, "args": [control, value]})
        png = canvas_png(driver)
        shots[name] = png_pixels(png)
        if name == "middle":
            with open(screenshot[:-4] + ".3d.png" if screenshot.endswith(".png")
                      else screenshot + ".3d.png", "wb") as out:
                out.write(png)
    for name, (w, h, rows) in shots.items():
        share = drawn_share(rows)
        if w < 100 or h < 100:
            problems.append("3D view: the %s canvas is %dx%d" % (name, w, h))
        elif share < 0.01:
            problems.append("3D view: the %s canvas is background (%.4f of its pixels drawn)"
                            % (name, share))
    moved = differing_pixels(shots["start"][2], shots["middle"][2])
    if moved < 50:
        problems.append("3D view: moving the time slider changed %d pixels" % moved)
    return problems


def launch(chromedriver, prefix):
    """Starts chromedriver on a free port with a fresh profile folder. Returns (driver, proc,
    profile, log_path); open_session then starts Chromium, and shut_down ends them all."""
    profile = tempfile.mkdtemp(prefix=prefix)
    port = free_port()
    log_path = os.path.join(profile, "chromedriver.log")
    with open(log_path, "w") as log:
        proc = subprocess.Popen([chromedriver, "--port=%d" % port], stdout=log,
                                stderr=subprocess.STDOUT)
    return WebDriver(port), proc, profile, log_path


def open_session(driver, proc, chromium, profile, window):
    """A headless Chromium session (CHROMIUM_FLAGS, the profile, window "W,H", the browser log
    kept) once chromedriver answers."""
    wait_ready(driver, proc)
    caps = {
        "browserName": "chrome",
        "goog:chromeOptions": {
            "binary": chromium,
            "args": CHROMIUM_FLAGS + ["--user-data-dir=" + os.path.join(profile, "user"),
                                      "--window-size=" + window],
        },
        "goog:loggingPrefs": {"browser": "ALL"},
    }
    driver.session = driver.call("POST", "/session",
                                 {"capabilities": {"alwaysMatch": caps}}, timeout=120)["sessionId"]


def shut_down(driver, proc, profile):
    """Ends the browser session, chromedriver and the profile folder, whatever state they are in."""
    if driver.session:
        try:
            driver.call("DELETE", driver.s(""), timeout=30)
        except (RuntimeError, OSError):
            pass
    proc.terminate()
    try:
        proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
    shutil.rmtree(profile, ignore_errors=True)


def check(page, screenshot, width, chromium, chromedriver):
    page = pathlib.Path(page).resolve()
    if not page.is_file():
        return ["%s: no such file" % page], None
    report_dir = page.parent.as_uri() + "/"
    driver, proc, profile, log_path = launch(chromedriver, "fragsim-chromium-")
    problems = []
    facts = None
    try:
        open_session(driver, proc, chromium, profile, "%d,900" % width)
        driver.call("POST", driver.s("/url"), {"url": page.as_uri()}, timeout=120)
        facts = driver.call("POST", driver.s("/execute/sync"), {"script": PAGE_PROBE, "args": []})

        if facts["readyState"] != "complete":
            problems.append("page: readyState is %s after load" % facts["readyState"])
        for entry in browser_log(driver):
            if entry.get("level") == "SEVERE":
                problems.append("console error: %s" % entry.get("message", "").strip())
        for img in facts["images"]:
            if not img["complete"] or img["naturalWidth"] <= 0 or img["naturalHeight"] <= 0:
                problems.append("image did not load: %s" % img["src"])
            elif img["src"].endswith(".png") and "://" not in img["src"]:
                # A cut-off PNG still shows its top rows without an error: check the file ends.
                with open(page.parent / img["src"], "rb") as f:
                    data = f.read()
                if not (data.startswith(PNG_SIGNATURE) and data.endswith(PNG_END)):
                    problems.append("image file is not a whole PNG: %s" % img["src"])
        for svg in facts["svgs"]:
            if svg["width"] <= 0 or svg["height"] <= 0:
                problems.append("svg has no size: %s" % svg["label"])
        for name in facts["resources"]:
            if not (name.startswith(report_dir) or name.startswith("data:")):
                problems.append("resource outside the report's folder: %s" % name)
        for link in facts["links"]:
            if "://" in link or link.startswith("//"):
                problems.append("link with a scheme or host (the page must be self-contained): "
                                + link)
        if not facts["images"] and not facts["svgs"]:
            problems.append("page: no image and no chart")

        problems += check_viewer(driver, screenshot)
        # Errors the 3D view logged while it drew.
        for entry in browser_log(driver):
            if entry.get("level") == "SEVERE":
                problems.append("console error: %s" % entry.get("message", "").strip())

        png = full_page_png(driver, min(facts["width"], width), facts["height"])
        with open(screenshot, "wb") as out:
            out.write(png)
        problems += png_problems(png)
    except (RuntimeError, OSError, KeyError, TypeError) as e:
        problems.append("browser: %s" % e)
        with open(log_path, errors="replace") as log:
            tail = log.read().strip().splitlines()[-5:]
        problems += ["chromedriver: " + line for line in tail]
    finally:
        shut_down(driver, proc, profile)
    return problems, facts


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("page")
    ap.add_argument("screenshot")
    ap.add_argument("--width", type=int, default=1200)
    ap.add_argument("--chromium", default="/usr/bin/chromium")
    ap.add_argument("--chromedriver", default=shutil.which("chromedriver") or
                    "/usr/bin/chromedriver")
    args = ap.parse_args()
    problems, facts = check(args.page, args.screenshot, args.width, args.chromium,
                            args.chromedriver)
    for p in problems:
        print("check_report: " + p, file=sys.stderr)
    if problems:
        return 1
    print("check_report: %s loaded: %d image(s), %d chart(s), no console error; screenshot %s "
          "(%dx%d)" % (facts["title"], len(facts["images"]), len(facts["svgs"]), args.screenshot,
                       min(facts["width"], args.width), facts["height"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
