#!/usr/bin/env python3
"""The JavaScript API's step in headless Chromium on a control dump: the median over REPEATS
replays of the time per fragment and step (tests/web/control_dump.mjs, as bench/web/api_bench.mjs
measures it in Node), printed as tests/control/replay.c --time prints it, for scripts/web_bench.sh.

Writes a page holding the package's modules, the dump reader and the dump (base64), opens it from
disk (Chromium imports the modules from data: URLs, as the demo page does) and reads the result.

Usage: browser_bench.py PACKAGE_DIR DUMP REPEATS [--floats] [--chromium PATH] [--chromedriver PATH]
"""

import argparse
import base64
import pathlib
import shutil
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(ROOT / "tests" / "browser"))
import check_report as cr  # noqa: E402  (the WebDriver helpers of the report's browser test)

PAGE = """<!doctype html><meta charset="utf-8"><title>fragsim: the step in Chromium</title>
<script type="text/plain" id="glue">%(glue)s</script>
<script type="text/plain" id="api">%(api)s</script>
<script type="text/plain" id="reader">%(reader)s</script>
<script type="text/plain" id="dump">%(dump)s</script>
<script type="module">
const bytes = (id) => Uint8Array.from(atob(document.getElementById(id).textContent), (c) => c.charCodeAt(0));
const text = (id) => new TextDecoder().decode(bytes(id));
const url = (source) => 'data:text/javascript;charset=utf-8,' + encodeURIComponent(source);
try {
  const api = await import(url(text('api').replace("'./fragsim_control_wasm.mjs'", JSON.stringify(url(text('glue'))))));
  const reader = await import(url(text('reader')));
  const fragsim = await api.default();
  const dump = reader.readControlDump(bytes('dump').buffer, fragsim, %(float)s);
  window.benchResult = { ns: reader.timeControlDump(fragsim, dump, %(repeats)d) };
} catch (error) {
  window.benchResult = { error: String(error) };
}
</script>
"""


def b64(path):
    return base64.b64encode(pathlib.Path(path).read_bytes()).decode("ascii")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("package")
    ap.add_argument("dump")
    ap.add_argument("repeats", type=int)
    ap.add_argument("--floats", action="store_true")
    ap.add_argument("--chromium", default=shutil.which("chromium") or "/usr/bin/chromium")
    ap.add_argument("--chromedriver", default=shutil.which("chromedriver") or "/usr/bin/chromedriver")
    args = ap.parse_args()
    package = pathlib.Path(args.package)
    page_html = PAGE % {
        "glue": b64(package / "fragsim_control_wasm.mjs"),
        "api": b64(package / "fragsim.mjs"),
        "reader": b64(ROOT / "tests" / "web" / "control_dump.mjs"),
        "dump": b64(args.dump),
        "float": "Float32Array" if args.floats else "Float64Array",
        "repeats": args.repeats,
    }
    driver, proc, profile, _ = cr.launch(args.chromedriver, "fragsim-bench-")
    try:
        page = pathlib.Path(profile) / "bench.html"
        page.write_text(page_html, encoding="ascii")
        cr.open_session(driver, proc, args.chromium, profile, "800,600")
        driver.call("POST", driver.s("/url"), {"url": page.as_uri()}, timeout=300)
        deadline = time.monotonic() + 600
        result = None
        while result is None and time.monotonic() < deadline:
            result = driver.call("POST", driver.s("/execute/sync"),
                                 {"script": "return window.benchResult || null;", "args": []})
            if result is None:
                time.sleep(0.5)
    finally:
        cr.shut_down(driver, proc, profile)
    if result is None or "error" in result:
        print("browser_bench: %s" % (result or {}).get("error", "no result in 600 s"),
              file=sys.stderr)
        return 1
    print("replay: time: %.1f ns per fragment and step, the median of %d replays"
          % (result["ns"], args.repeats))
    return 0


if __name__ == "__main__":
    sys.exit(main())
