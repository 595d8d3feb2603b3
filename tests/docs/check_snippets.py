#!/usr/bin/env python3
"""Compiles every ```c block of the library's pages against the library, so a stale snippet fails.

    check_snippets.py --cc CC --include DIR --library LIB [--run] MARKDOWN...

For each ```c block of each page:
  - a whole program (it defines `int main(`) is compiled, linked against LIB (the shared library,
    with an rpath to its folder, or the static archive, with the C++ runtime) and run: it must
    exit 0;
  - a block that defines a function at file scope (a line at column 0 that starts with a type, a
    name and a parenthesis) is compiled as a translation unit of its own (-c);
  - any other block is a fragment of a function: it is compiled inside a block of a function whose
    parameters are the names the pages use without declaring them (CONTEXT below). A fragment may
    declare any of them itself: its own declaration shadows the parameter.
Every block is compiled as C99 with -Wall -Wextra -Wpedantic -Werror and the library's public
header folder only. Prints one line per block and exits 1 if any failed, or if no block was found
(an extractor that finds nothing checks nothing).

Python standard library only, like check_docs.py beside it.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

# The names a fragment may use without declaring them: what the page's running text has set up.
CONTEXT = [
    ("fragsim_controller_id", "ctl"),
    ("fragsim_controller_def", "def"),
    ("fragsim_step_input", "in"),
    ("fragsim_step_stats", "stats"),
    ("fragsim_fragment*", "fragments"),
    ("int32_t", "fragment_count"),
    ("fragsim_vec3*", "forces_N"),
]
PRELUDE = "#include <fragsim/control.h>\n#include <math.h>\n#include <stdio.h>\n" \
          "#include <stdlib.h>\n#include <string.h>\n"
FLAGS = ["-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Werror"]


def blocks(path):
    """(line number, code) of every ```c block of a Markdown file."""
    found, code, start = [], None, 0
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            stripped = line.strip()
            if code is None and re.fullmatch(r"```c", stripped):
                code, start = [], n + 1
            elif code is not None and stripped == "```":
                found.append((start, "".join(code)))
                code = None
            elif code is not None:
                code.append(line)
    return found


def kind(code):
    if re.search(r"\bint\s+main\s*\(", code):
        return "program"
    # A definition at file scope: a line at column 0 that starts with a type and a name and an
    # opening parenthesis (not a call, an assignment or a statement).
    if re.search(r"^(?!(?:if|for|while|switch|else|do|return|case)\b)(?:static\s+|inline\s+)*"
                 r"[A-Za-z_]\w*[\s*]+\**\w+\s*\(", code, re.M):
        return "unit"
    return "fragment"


def source(code, what, name, origin):
    line = f'#line {origin[1]} "{origin[0]}"\n'
    if what in ("program", "unit"):
        return PRELUDE + line + code
    params = ", ".join(f"{t} {n}" for t, n in CONTEXT)
    unused = " ".join(f"(void){n};" for _, n in CONTEXT)
    return (f"{PRELUDE}void {name}({params});\nvoid {name}({params}) {{\n  {unused}\n  {{\n"
            f"{line}{code}\n  }}\n}}\n")


def link_flags(library):
    folder = os.path.dirname(os.path.abspath(library))
    if library.endswith(".a"):
        return [library, "-lstdc++", "-lm"]
    return [library, f"-Wl,-rpath,{folder}", "-lm"]


def check(args, page, start, code, work, index):
    what = kind(code)
    name = f"snippet_{index}"
    origin = (os.path.relpath(page, args.root) if args.root else page, start)
    c_file = os.path.join(work, name + ".c")
    with open(c_file, "w", encoding="utf-8") as f:
        f.write(source(code, what, name, origin))
    flags = FLAGS + [f"-I{d}" for d in args.include]
    if what == "program":
        exe = os.path.join(work, name)
        command = [args.cc] + flags + ["-o", exe, c_file] + link_flags(args.library)
    else:
        command = [args.cc] + flags + ["-c", "-o", os.path.join(work, name + ".o"), c_file]
    result = subprocess.run(command, capture_output=True, text=True)
    where = f"{origin[0]}:{start}"
    if result.returncode != 0:
        print(f"FAIL {where} ({what}): does not compile\n{result.stderr}", end="")
        return False
    if what == "program" and args.run:
        run = subprocess.run([exe], capture_output=True, text=True, timeout=60)
        if run.returncode != 0:
            print(f"FAIL {where} (program): exits {run.returncode}\n{run.stdout}{run.stderr}")
            return False
    print(f"ok   {where} ({what})")
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cc", default=os.environ.get("CC", "cc"))
    parser.add_argument("--include", action="append", required=True,
                        help="the public headers' folder (the one holding fragsim/)")
    parser.add_argument("--library", required=True, help="libfragsim_control.so or .a")
    parser.add_argument("--run", action="store_true", help="run the whole programs too")
    parser.add_argument("--root", help="paths are printed relative to it")
    parser.add_argument("pages", nargs="+")
    args = parser.parse_args()
    failed, total = 0, 0
    with tempfile.TemporaryDirectory() as work:
        for page in args.pages:
            for start, code in blocks(page):
                total += 1
                if not check(args, page, start, code, work, total):
                    failed += 1
    if total == 0:
        print("no ```c block found in " + " ".join(args.pages))
        return 1
    print(f"{total - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
