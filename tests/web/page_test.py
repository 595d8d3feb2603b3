#!/usr/bin/env python3
"""Opens fragsim's web demo (examples/web, built by build_page.py) from disk in headless Chromium,
in its test mode (index.html?test=1), and checks what the page claims with the real simulation:

- without the controller (strategy none) the scripted blast cuts the near plane in at least 8 of
  10 seeds, and with edge-min in none of them (the page's own swept-sphere check);
- the same seed and strategy give the same counts and the same final state twice (determinism);
- no run warns of what would be the page's bug (a camera over its declared speed, a field of view
  in radians, a fragment skipped);
- the console has no error, and the canvas is drawn (pixels other than the sky in a screenshot);
- opened as a visitor opens it (no ?test=1), the page starts and its animation loop steps the
  world, with no console error either.

Saves a full-page screenshot. Prints one line per seed per strategy and a summary; exits 0 if
every check passed, 1 otherwise. Drives chromedriver over WebDriver with the standard library
only, through tests/browser/check_report.py's helpers and Chromium flags (no GPU: SwiftShader;
every host name unresolvable, so nothing reaches the network).

Usage: page_test.py PAGE.html SCREENSHOT.png [--seeds N] [--pieces N] [--steps N]
       [--chromium PATH] [--chromedriver PATH]
"""

import argparse
import pathlib
import shutil
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "browser"))
import check_report as cr  # noqa: E402  (the WebDriver helpers of the report's browser test)

STRATEGIES = ("none", "edge-min")
NONE_CUT_SEEDS_MIN = 8  # of 10: the blast really threatens the lens
# The page's sky (scene.background) and the stage behind the canvas: pixels of neither are drawn.
SKY = {(0xa9, 0xc8, 0xe8)}
# Controller warnings that would be the page's bug (fragsim's Warning bits).
PAGE_BUG_WARNINGS = {1: "CAMERA_OVER_SPEED", 2: "FOVY_IN_RADIANS", 16: "SKIPPED"}
COMPARED = ("cuts", "cutPieces", "pushes", "pushedPieces", "stateHash")

WAIT_READY = """
const state = document.body.dataset.state;
const status = document.getElementById('status');
return {state: state, ready: !!(window.fragsimDemo && window.fragsimDemo.ready),
        status: status ? status.textContent : ''};
"""

RUN_SCRIPTED = """
const [options, done] = arguments;
window.fragsimDemo.runScripted(options).then(
  result => done({result: result}),
  error => done({error: String(error && error.stack || error)}));
"""


def wait_for_page(driver, seconds=180):
    deadline = time.monotonic() + seconds
    while True:
        state = driver.call("POST", driver.s("/execute/sync"), {"script": WAIT_READY, "args": []})
        if state["ready"]:
            return
        if state["state"] == "failed":
            raise RuntimeError("the page failed to start: " + state["status"])
        if time.monotonic() > deadline:
            raise RuntimeError("the page was not ready after %d s (%s)" % (seconds, state["status"]))
        time.sleep(0.2)


def run_scripted(driver, options):
    answer = driver.call("POST", driver.s("/execute/async"),
                         {"script": RUN_SCRIPTED, "args": [options]}, timeout=600)
    if "error" in answer:
        raise RuntimeError("runScripted(%s) failed: %s" % (options, answer["error"]))
    return answer["result"]


def describe(r):
    return ("%-8s seed %2d: %4d piece(s) cut, %4d event(s); %5d pushes on %4d piece(s); "
            "controller %.3f ms/step; run %.0f ms; warnings %d; state %s"
            % (r["strategy"], r["seed"], r["cutPieces"], r["cuts"], r["pushes"], r["pushedPieces"],
               r["controllerMsMean"], r["runMs"], r["warnings"], r["stateHash"]))


def canvas_drawn_share(driver):
    found = driver.call("POST", driver.s("/element"), {"using": "css selector", "value": "#view"})
    png = cr.base64.b64decode(driver.call(
        "GET", driver.s("/element/%s/screenshot" % found[cr.WEBDRIVER_ELEMENT])))
    width, height, rows = cr.png_pixels(png)
    total = sum(len(r) for r in rows)
    drawn = sum(1 for r in rows for px in r if px not in SKY)
    return width, height, drawn / max(total, 1)


LIVE_STATE = """
const text = id => (document.getElementById(id) || {}).textContent || '';
return {state: document.body.dataset.state, status: text('status'), time: text('stat-time'),
        cuts: text('stat-cuts'), fps: text('stat-fps'), ms: text('stat-ms')};
"""


def check_live_page(driver, page, seconds=4.0):
    """The page as a visitor opens it (no ?test=1): it starts, its animation loop blows the crate
    and steps the world (the clock after the blast advances), with nothing logged as an error."""
    driver.call("POST", driver.s("/url"), {"url": page.as_uri()}, timeout=120)
    deadline = time.monotonic() + 120
    state = driver.call("POST", driver.s("/execute/sync"), {"script": LIVE_STATE, "args": []})
    while state["state"] == "loading" and time.monotonic() < deadline:
        time.sleep(0.2)
        state = driver.call("POST", driver.s("/execute/sync"), {"script": LIVE_STATE, "args": []})
    if state["state"] != "ready":
        return ["live page: %s: %s" % (state["state"], state["status"])]
    time.sleep(seconds)
    first = driver.call("POST", driver.s("/execute/sync"), {"script": LIVE_STATE, "args": []})
    time.sleep(1.5)
    second = driver.call("POST", driver.s("/execute/sync"), {"script": LIVE_STATE, "args": []})
    print("page_test: live page after %.0f s: %s; cuts %s; controller %s a step; fps %s"
          % (seconds + 1.5, second["time"], second["cuts"], second["ms"], second["fps"]))
    if "after the blast" not in second["time"] or first["time"] == second["time"]:
        return ["live page: the world does not step (%r, then %r)" % (first["time"], second["time"])]
    return []


def check_runs(runs, seeds):
    """The counts' checks; returns the problems found."""
    problems = []
    cut_seeds = {s: sum(1 for r in runs[s] if r["cutPieces"] > 0) for s in STRATEGIES}
    if cut_seeds["none"] < min(NONE_CUT_SEEDS_MIN, seeds):
        problems.append("none: the blast cut the near plane in %d of %d seeds (want >= %d)"
                        % (cut_seeds["none"], seeds, min(NONE_CUT_SEEDS_MIN, seeds)))
    if cut_seeds["edge-min"] != 0:
        problems.append("edge-min: the near plane was cut in %d of %d seeds (want 0)"
                        % (cut_seeds["edge-min"], seeds))
    for strategy in STRATEGIES:
        for r in runs[strategy]:
            for bit, name in PAGE_BUG_WARNINGS.items():
                if r["warnings"] & bit:
                    problems.append("%s seed %d: the controller warned %s" % (strategy, r["seed"], name))
            if r["pieces"] <= 0 or r["steps"] <= 0:
                problems.append("%s seed %d: an empty run" % (strategy, r["seed"]))
    if any(r["pushes"] for r in runs["none"]):
        problems.append("none: pushes counted without a controller")
    return problems, cut_seeds


def check_determinism(runs, again):
    problems = []
    for strategy in STRATEGIES:
        for first, second in zip(runs[strategy], again[strategy]):
            differing = [k for k in COMPARED if first[k] != second[k]]
            if differing:
                problems.append("%s seed %d: a second run differs in %s (%s against %s)" % (
                    strategy, first["seed"], ", ".join(differing),
                    [first[k] for k in differing], [second[k] for k in differing]))
    return problems


def console_errors(driver, where):
    return ["console error (%s): %s" % (where, entry.get("message", "").strip())
            for entry in cr.browser_log(driver) if entry.get("level") == "SEVERE"]


def run(args):
    page = pathlib.Path(args.page).resolve()
    if not page.is_file():
        return ["%s: no such file" % page]
    driver, proc, profile, log_path = cr.launch(args.chromedriver, "fragsim-page-")
    problems = []
    try:
        cr.open_session(driver, proc, args.chromium, profile, "1100,1000")
        driver.call("POST", driver.s("/timeouts"), {"script": 600000})
        driver.call("POST", driver.s("/url"), {"url": page.as_uri() + "?test=1"}, timeout=120)
        wait_for_page(driver)

        seeds = list(range(1, args.seeds + 1))
        options = lambda strategy, seed: {"seed": seed, "strategy": strategy,
                                          "pieces": args.pieces, "steps": args.steps}
        runs = {s: [] for s in STRATEGIES}
        for strategy in STRATEGIES:
            for seed in seeds:
                r = run_scripted(driver, options(strategy, seed))
                runs[strategy].append(r)
                print("page_test: " + describe(r), flush=True)
        # The same seeds again, the seeds in the other order: a run must not depend on the runs
        # before it.
        again = {s: [] for s in STRATEGIES}
        for strategy in STRATEGIES:
            again[strategy] = [run_scripted(driver, options(strategy, seed))
                               for seed in reversed(seeds)][::-1]
        count_problems, cut_seeds = check_runs(runs, len(seeds))
        problems += count_problems
        problems += check_determinism(runs, again)
        mean_ms = [r["controllerMsMean"] for r in runs["edge-min"]]
        print("page_test: %d pieces, %d steps: none cut the near plane in %d of %d seeds "
              "(%d pieces in all), edge-min in %d of %d (%d pushes in all, controller %.3f ms/step "
              "on average); the %d runs repeated gave the same counts and states: %s"
              % (runs["none"][0]["pieces"], args.steps, cut_seeds["none"], len(seeds),
                 sum(r["cutPieces"] for r in runs["none"]), cut_seeds["edge-min"], len(seeds),
                 sum(r["pushes"] for r in runs["edge-min"]), sum(mean_ms) / len(mean_ms),
                 2 * len(seeds), "yes" if not check_determinism(runs, again) else "no"))

        width, height, share = canvas_drawn_share(driver)
        if width < 100 or height < 100:
            problems.append("canvas: %dx%d" % (width, height))
        elif share < 0.05:
            problems.append("canvas: only %.4f of its pixels differ from the sky" % share)
        else:
            print("page_test: canvas %dx%d drawn (%.0f%% of its pixels not sky)"
                  % (width, height, 100 * share))
        png = cr.full_page_png(driver, 1100, 1000)
        with open(args.screenshot, "wb") as out:
            out.write(png)
        problems += cr.png_problems(png)
        problems += console_errors(driver, "test mode")
        problems += check_live_page(driver, page)
        problems += console_errors(driver, "live page")
    except (RuntimeError, OSError, KeyError, TypeError) as e:
        problems.append("browser: %s" % e)
        with open(log_path, errors="replace") as log:
            problems += ["chromedriver: " + line for line in log.read().strip().splitlines()[-5:]]
    finally:
        cr.shut_down(driver, proc, profile)
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("page")
    ap.add_argument("screenshot")
    ap.add_argument("--seeds", type=int, default=10)
    ap.add_argument("--pieces", type=int, default=512)
    ap.add_argument("--steps", type=int, default=150)
    ap.add_argument("--chromium", default="/usr/bin/chromium")
    ap.add_argument("--chromedriver", default=shutil.which("chromedriver") or "/usr/bin/chromedriver")
    args = ap.parse_args()
    started = time.monotonic()
    problems = run(args)
    for p in problems:
        print("page_test: FAILED: " + p, file=sys.stderr)
    print("page_test: %s in %.0f s; screenshot %s" % ("failed" if problems else "passed",
                                                     time.monotonic() - started, args.screenshot))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
