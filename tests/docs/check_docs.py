#!/usr/bin/env python3
"""The docs check (ctest Docs.Check, label docs): the documentation must match the tree.

Usage: check_docs.py ROOT FRAGSIM [--only CHECK,...]
  ROOT     the repository's root
  FRAGSIM  the built fragsim binary (its `compare --help` is the program's key table)
  --only   run only these checks: readme, outside, links, keys, folders, includes, mirror,
           pages, issues, changelog, offline, hooks, roots, comments

Fails (exit 1, one line per finding) when:
  readme    README.md is over 200 lines or holds a date or a commit hash;
  outside   a tracked file refers to the shared folder beside the repository (OUTSIDE below);
  links     a relative link in README.md, docs/*.md or data/scenes/README.md points to a missing
            file or heading;
  keys      the scene keys in docs/guide.md ("## Scene keys") and `fragsim compare --help`
            differ in a key or a default;
  folders   a folder listed in docs/architecture.md ("## Folders") does not exist, or a folder
            under src/ is not listed;
  includes  a file under src/ includes a folder of its own layer or a higher one (the "## Layers"
            table of docs/architecture.md), or ODE or SDL outside the folder that owns it;
  roots     an include names a file another way than by its path from an include root (src/,
            src/control/include/, and tests/ for the tests): a path relative to the including
            file, or the library's files without control/; or a relative path exists under two
            roots; or a CMake file makes src/control an include root again;
  comments  the comments of the C and C++ files under src/ average more than COMMENT_MAX_COLONS
            ": " a line (sentences that say why, not "X: Y" chains; Box2D's average 0.06), or a
            comment tells history (HISTORY_WORDS: the changelog holds it);
  mirror    a source src/D/X.cpp has no test named after it, tests/D/X_test.cpp or
            tests/D/X_<aspect>_test.cpp (src/control/D/ is tested in tests/D/, its api/ in
            tests/control/ or, as C programs, tests/control/api/), unless MIRROR_UNTESTED lists it
            with a reason; or a GoogleTest suite (the first argument of TEST, TEST_F, TEST_P) is
            named neither after its file (world_skip_test.cpp: WorldSkip) nor after the source the
            file tests (World), unless MIRROR_SUITES lists the file with a reason; or an entry of
            either list is no longer needed. Prints how many sources have such a test;
  pages     a page with a length limit (PAGE_MAX_LINES below: docs/benchmarks.md, 400 lines) is
            over it: the pages hold the present, the history goes to the changelog;
  issues    a tracked text file under README.md, docs/, src/, tests/, scripts/, bench/, examples/
            or data/ names an issue or pull request by its number (the word followed by a number,
            with or without a hash; a hash and a number in parentheses; "fixes", "closes", "see"
            and the like before a hash and a number): a reader has no tracker;
  changelog docs/CHANGELOG.md is not in the Keep a Changelog shape: "## [Unreleased]" first, then
            releases "## [library X.Y.Z] - YYYY-MM-DD" or "## [tool X.Y.Z] - YYYY-MM-DD", newest
            first, each with at least one subsection, and subsections "### " only among Added,
            Changed, Deprecated, Removed, Fixed and Security, each at most once a section;
  offline   a CMake file (CMakeLists.txt, cmake/*.cmake) could reach the network when configuring:
            file(DOWNLOAD), FetchContent, ExternalProject, or execute_process running npm, npx,
            pip, curl, wget or git. Configuring a fresh clone works offline; the set-up scripts
            fetch what is needed;
  hooks     a file under src/ holds a test hook: reads an environment variable named FRAGSIM_TEST_*
            or declares a name starting g_test_. The shipped tool carries no test code; tests
            build their own variant (tests/support/signal_at_step.cpp).
Python standard library only.
"""

import datetime
import os
import re
import subprocess
import sys

README_MAX_LINES = 200
DATE = re.compile(r"20[0-9]{2}-[01][0-9]-[0-3][0-9]")
HEX_TOKEN = re.compile(r"(?<![0-9A-Za-z_])[0-9a-f]{7,40}(?![0-9A-Za-z_])")
# Spelled in two parts so that this file does not match itself.
OUTSIDE = ".." + "/shared"
PAGE_MAX_LINES = {"docs/benchmarks.md": 400}
# The word spelled in two parts, and no digit after a hash in the patterns' text, so that this
# file does not match itself.
ISSUE_WORD = "iss" + "ue"
ISSUE_NUMBER = re.compile(
    r"\b(?:" + ISSUE_WORD + r"s?|pull request|PR)(?:\s*#\s*|\s+)[0-9]+\b"
    r"|\(#[0-9]+\)"
    r"|\b(?:fix(?:e[sd])?|close[sd]?|resolve[sd]?|see|refs?)\s+#[0-9]+\b",
    re.IGNORECASE)
ISSUE_ROOTS = ("README.md", "docs/", "src/", "tests/", "scripts/", "bench/", "examples/", "data/")
CHANGELOG_RELEASE = re.compile(
    r"^## \[(?:(tool|library) )?([0-9]+)\.([0-9]+)\.([0-9]+)\] - ([0-9]{4}-[0-9]{2}-[0-9]{2})$")
CHANGELOG_KINDS = ("Added", "Changed", "Deprecated", "Removed", "Fixed", "Security")

failures = []


def fail(check, message):
    failures.append(f"docs check ({check}): {message}")


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def section(text, heading):
    """The lines of `text` under the `## heading` line, up to the next `## ` heading."""
    lines = text.split("\n")
    out, inside = [], False
    for line in lines:
        if line.startswith("## "):
            if inside:
                break
            inside = line[3:].strip() == heading
            continue
        if inside:
            out.append(line)
    if not inside and not out:
        return None
    return out


def without_code(text, inline=True):
    """`text` with fenced code blocks blanked (line numbers kept) and, when `inline`, inline
    code removed."""
    out, fenced = [], False
    for line in text.split("\n"):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            out.append("")
            continue
        out.append("" if fenced else re.sub(r"`[^`]*`", "", line) if inline else line)
    return out


# --- readme ---------------------------------------------------------------------------------

def check_readme(root):
    text = read(os.path.join(root, "README.md"))
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    if len(lines) > README_MAX_LINES:
        fail("readme", f"README.md has {len(lines)} lines, at most {README_MAX_LINES} allowed")
    for n, line in enumerate(lines, 1):
        for m in DATE.finditer(line):
            fail("readme", f"README.md:{n}: a date, '{m.group(0)}' (history goes to docs/CHANGELOG.md)")
        for m in HEX_TOKEN.finditer(line):
            token = m.group(0)
            if re.search(r"[0-9]", token) and re.search(r"[a-f]", token):
                fail("readme", f"README.md:{n}: a commit hash, '{token}'")


# --- outside --------------------------------------------------------------------------------

def tracked_files(root):
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], check=True,
                             capture_output=True).stdout
        return [p for p in out.decode().split("\0") if p]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for d, dirs, names in os.walk(root):
            dirs[:] = [x for x in dirs if not x.startswith(".") and x != "build"]
            files += [os.path.relpath(os.path.join(d, n), root) for n in names]
        return files


def check_outside(root):
    for rel in tracked_files(root):
        path = os.path.join(root, rel)
        try:
            with open(path, "rb") as f:
                data = f.read()
        except OSError:
            continue
        if b"\0" in data[:8192]:
            continue  # binary
        for n, line in enumerate(data.decode("utf-8", "replace").split("\n"), 1):
            if OUTSIDE in line:
                fail("outside", f"{rel}:{n}: refers to {OUTSIDE}, outside the repository")


# --- links ----------------------------------------------------------------------------------

def slug(heading):
    """GitHub's anchor for a heading: lower case, code marks and punctuation dropped, spaces to -."""
    s = heading.strip().lower().replace("`", "")
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        found, counts = set(), {}
        for line in without_code(read(path), inline=False):
            m = re.match(r"^(#{1,6})\s+(.*?)\s*#*\s*$", line)
            if not m:
                continue
            base = slug(m.group(2))
            n = counts.get(base, 0)
            counts[base] = n + 1
            found.add(base if n == 0 else f"{base}-{n}")
        cache[path] = found
    return cache[path]


def markdown_files(root):
    files = [os.path.join(root, "README.md"), os.path.join(root, "data", "scenes", "README.md")]
    docs = os.path.join(root, "docs")
    files += sorted(os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
    return [f for f in files if os.path.exists(f)]


def check_links(root):
    link = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
    for path in markdown_files(root):
        rel = os.path.relpath(path, root)
        for n, line in enumerate(without_code(read(path)), 1):
            for m in link.finditer(line):
                target = m.group(1)
                if re.match(r"^[a-z][a-z0-9+.-]*:", target):
                    continue  # http:, https:, mailto:
                file_part, _, anchor = target.partition("#")
                dest = path if not file_part else os.path.normpath(
                    os.path.join(os.path.dirname(path), file_part))
                if not os.path.exists(dest):
                    fail("links", f"{rel}:{n}: '{target}': no such file")
                    continue
                if anchor and dest.endswith(".md") and anchor not in anchors(dest):
                    fail("links", f"{rel}:{n}: '{target}': no such heading in "
                                  f"{os.path.relpath(dest, root)}")


# --- keys -----------------------------------------------------------------------------------

def documented_keys(root):
    lines = section(read(os.path.join(root, "docs", "guide.md")), "Scene keys")
    if lines is None:
        fail("keys", "docs/guide.md has no '## Scene keys' section")
        return {}
    keys, current = {}, None
    for line in lines:
        m = re.match(r"^### (.*)$", line)
        if m:
            title = m.group(1).strip()
            if title.startswith("top level"):
                current = ""
            else:
                s = re.match(r"^\[([^\]]+)\]$", title)
                current = s.group(1) if s else None
            continue
        if current is None:
            continue
        row = re.match(r"^\|\s*`([^`]+)`\s*\|.*\|\s*(.*?)\s*\|\s*$", line)
        if not row:
            continue
        name = row.group(1) if current == "" else f"{current}.{row.group(1)}"
        cell = row.group(2)
        code = re.fullmatch(r"`([^`]*)`", cell)
        if code:
            default = code.group(1)
        elif cell in ("(none)", "(empty)"):
            default = ""
        else:
            fail("keys", f"docs/guide.md: {name}: default '{cell}' is neither `value`, (none) "
                         "nor (empty)")
            default = cell
        if name in keys:
            fail("keys", f"docs/guide.md: {name} is documented twice")
        keys[name] = default
    return keys


def program_keys(fragsim):
    try:
        out = subprocess.run([fragsim, "compare", "--help"], check=True, capture_output=True,
                             text=True, timeout=60).stdout
    except (OSError, subprocess.SubprocessError) as e:
        fail("keys", f"could not run '{fragsim} compare --help': {e}")
        return {}
    lines = out.split("\n")
    start = next((i for i, l in enumerate(lines) if l.startswith("Scene keys")), None)
    if start is None:
        fail("keys", "`fragsim compare --help` prints no 'Scene keys' section")
        return {}
    entries, name, text = [], None, []
    for line in lines[start + 1:]:
        m = re.match(r"^  --([A-Za-z0-9_.-]+)(?: V)?(?:\s+(.*))?$", line)
        if m:
            if name:
                entries.append((name, " ".join(text)))
            name, text = m.group(1), [m.group(2) or ""]
        elif line.startswith("   ") and name:
            text.append(line.strip())
        else:
            break  # the end of boost's options block
    if name:
        entries.append((name, " ".join(text)))
    keys = {}
    for name, help_text in entries:
        m = re.search(r"\[([^\[\]]*)\]\s*$", help_text)
        if not m:
            fail("keys", f"`fragsim compare --help`: --{name} shows no [default]")
        keys[name] = m.group(1) if m else None
    return keys


def check_keys(root, fragsim):
    doc = documented_keys(root)
    prog = program_keys(fragsim)
    if not prog:
        return
    for name in sorted(set(prog) - set(doc)):
        fail("keys", f"{name} (default '{prog[name]}') is a scene key of the program but not in "
                     "docs/guide.md's scene keys")
    for name in sorted(set(doc) - set(prog)):
        fail("keys", f"{name} is in docs/guide.md's scene keys but not a key of the program")
    for name in sorted(set(doc) & set(prog)):
        if prog[name] is not None and doc[name] != prog[name]:
            fail("keys", f"{name}: docs/guide.md gives the default '{doc[name]}', the program "
                         f"'{prog[name]}'")


# --- folders and includes -------------------------------------------------------------------

def table_folders(lines):
    """Backticked src/ folders in the first cells of a table's rows, in order."""
    out = []
    for line in lines:
        first = re.match(r"^\|([^|]*)\|", line)
        if first:
            out += re.findall(r"`(src(?:/[A-Za-z0-9_.-]+)*)`", first.group(1))
    return out


def check_folders(root):
    lines = section(read(os.path.join(root, "docs", "architecture.md")), "Folders")
    if lines is None:
        fail("folders", "docs/architecture.md has no '## Folders' section")
        return
    listed = table_folders(lines)
    if not listed:
        fail("folders", "docs/architecture.md's '## Folders' table lists no src/ folder")
    actual = set()
    for d, dirs, _ in os.walk(os.path.join(root, "src")):
        dirs[:] = [x for x in dirs if not x.startswith(".")]
        rel = os.path.relpath(d, root).replace(os.sep, "/")
        if rel != "src":
            actual.add(rel)
    for folder in listed:
        if folder not in actual:
            fail("folders", f"{folder} is listed in docs/architecture.md but does not exist")
    for folder in sorted(actual - set(listed)):
        fail("folders", f"{folder} exists but is not listed in docs/architecture.md's Folders")
    for folder in sorted({f for f in listed if listed.count(f) > 1}):
        fail("folders", f"{folder} is listed twice in docs/architecture.md")


def layers(root):
    lines = section(read(os.path.join(root, "docs", "architecture.md")), "Layers")
    if lines is None:
        fail("includes", "docs/architecture.md has no '## Layers' section")
        return {}
    out = {}
    for line in lines:
        m = re.match(r"^\|\s*([0-9]+)\s*\|(.*)\|\s*$", line)
        if m:
            for folder in re.findall(r"`(src/[A-Za-z0-9_.-]+)`", m.group(2)):
                out[folder] = int(m.group(1))
    return out


def unit_of(root, path):
    """The layer unit a path under src/ belongs to: src/<top folder>."""
    parts = os.path.relpath(path, os.path.join(root, "src")).split(os.sep)
    return "src/" + parts[0]


INCLUDE_ROOTS = ("src", "src/control/include")


def resolve(root, including_dir, target):
    """The file an #include "target" names, as the compiler finds it: beside the including file
    first, then under the include roots."""
    for base in (including_dir,) + tuple(os.path.join(root, r) for r in INCLUDE_ROOTS):
        p = os.path.normpath(os.path.join(base, target))
        if os.path.isfile(p):
            return p
    return None


def tracked_under(root, *folders):
    """The tracked files under these folders (tracked_files, filtered)."""
    return [f for f in tracked_files(root) if f.startswith(tuple(d + "/" for d in folders))
            and os.path.isfile(os.path.join(root, f))]


COMMENT_MAX_COLONS = 0.06
HISTORY_WORDS = re.compile(r"\b(has always|have always|used to|no longer|any ?more|since 0\.\d|"
                           r"the old (?:one|way|code|check|sum)|before the fix|this round)\b",
                           re.I)


def comment_lines(text):
    """The comment text of each line of a C or C++ file: // to the line's end, and /* ... */."""
    out, block = [], False
    for n, line in enumerate(text.split("\n"), 1):
        if block:
            end = line.find("*/")
            out.append((n, line if end < 0 else line[:end]))
            block = end < 0
            continue
        code = re.sub(r'"(?:\\.|[^"\\])*"', '""', line)  # no // inside a string
        at = code.find("//")
        start = code.find("/*")
        if at >= 0 and (start < 0 or at < start):
            out.append((n, code[at + 2:]))
        elif start >= 0:
            end = code.find("*/", start + 2)
            out.append((n, code[start + 2:] if end < 0 else code[start + 2:end]))
            block = end < 0
    return out


def check_comments(root):
    lines = colons = 0
    for f in tracked_under(root, "src"):
        if not f.endswith((".cpp", ".hpp", ".h", ".c")):
            continue
        for n, text in comment_lines(read(os.path.join(root, f))):
            lines += 1
            colons += text.count(": ")
            m = HISTORY_WORDS.search(text)
            if m:
                fail("comments", f"{f}:{n}: '{m.group(0)}' tells history; say what holds now "
                                 "(the changelog keeps the history)")
    if lines and colons / lines > COMMENT_MAX_COLONS:
        fail("comments", f"src/ comments average {colons / lines:.3f} ': ' a line, over "
                         f"{COMMENT_MAX_COLONS}: write sentences, not 'X: Y' chains")


def check_roots(root):
    """One spelling per file: every include is the file's path from an include root."""
    quoted = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
    sources = [f for f in tracked_under(root, "src", "tests", "bench")
               if f.endswith((".cpp", ".hpp", ".h", ".c"))
               and not f.startswith(("tests/control/include_check/", "tests/control/api/"))]
    for f in sources:
        roots = INCLUDE_ROOTS + (("tests",) if f.startswith(("tests/", "bench/")) else ())
        here = os.path.dirname(os.path.join(root, f))
        for n, line in enumerate(read(os.path.join(root, f)).split("\n"), 1):
            m = quoted.match(line)
            if not m:
                continue
            name = m.group(1)
            found = [r for r in roots if os.path.isfile(os.path.join(root, r, name))]
            beside = os.path.normpath(os.path.join(here, name))
            if len(found) > 1:
                fail("roots", f"{f}:{n}: \"{name}\" is under {' and '.join(found)}")
            elif found:
                if os.path.isfile(beside) and beside != os.path.normpath(
                        os.path.join(root, found[0], name)):
                    fail("roots", f"{f}:{n}: \"{name}\" is also a file beside {f}")
            elif os.path.isfile(beside):
                inside_src = os.path.commonpath([beside, os.path.join(root, "src")]) == \
                    os.path.join(root, "src")
                if inside_src or not f.startswith(("tests/", "bench/")):
                    spelled = os.path.relpath(beside, os.path.join(root, "src"))
                    fail("roots", f"{f}:{n}: \"{name}\" is relative to its file; write "
                                  f"\"{spelled}\"")
            else:
                fail("roots", f"{f}:{n}: \"{name}\" is under no include root")
    names = {}
    for r in INCLUDE_ROOTS + ("tests",):
        for f in tracked_under(root, r):
            if not f.endswith((".hpp", ".h")):
                continue
            rel = os.path.relpath(f, r)
            names.setdefault(rel, []).append(r)
    for rel, rs in sorted(names.items()):
        if len(rs) > 1:
            fail("roots", f"{rel} is a path under {' and '.join(rs)}: one include path, two files")
    cmake_files = [f for f in tracked_files(root) if f.endswith(("CMakeLists.txt", ".cmake"))]
    block = re.compile(r"target_include_directories\(([^)]*)\)", re.S)
    for f in cmake_files:
        text = read(os.path.join(root, f))
        for m in block.finditer(text):
            n = text[:m.start()].count("\n") + 1
            args = m.group(1)
            if re.search(r"src/control(?![/\w])", args) or (
                    f == "src/control/CMakeLists.txt" and
                    re.search(r"\$\{CMAKE_CURRENT_SOURCE_DIR\}(?![/\w])", args)):
                fail("roots", f"{f}:{n}: makes src/control an include root; its files are "
                              "included as control/... from src/")


def check_includes(root):
    layer = layers(root)
    if not layer:
        return
    src = os.path.join(root, "src")
    quoted = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
    angled = re.compile(r"^\s*#\s*include\s*<([^>]+)>")
    owners = {"ode/": "src/sim", "SDL": "src/window"}
    reported = set()
    for d, dirs, names in os.walk(src):
        dirs[:] = [x for x in dirs if not x.startswith(".")]
        for name in sorted(names):
            if not name.endswith((".cpp", ".hpp", ".h")):
                continue
            path = os.path.join(d, name)
            rel = os.path.relpath(path, root).replace(os.sep, "/")
            unit = unit_of(root, path)
            if unit not in layer:
                if unit not in reported:
                    fail("includes", f"{unit} is in no layer of docs/architecture.md's Layers")
                    reported.add(unit)
                continue
            for n, line in enumerate(read(path).split("\n"), 1):
                m = angled.match(line)
                if m:
                    for prefix, owner in owners.items():
                        if m.group(1).startswith(prefix) and unit != owner:
                            fail("includes", f"{rel}:{n}: includes <{m.group(1)}>; only {owner} "
                                             "may")
                    continue
                m = quoted.match(line)
                if not m:
                    continue
                target = resolve(root, d, m.group(1))
                if target is None:
                    fail("includes", f"{rel}:{n}: \"{m.group(1)}\" resolves to no file")
                    continue
                if os.path.commonpath([target, src]) != src:
                    to = "src/control"  # the C header's place before the library had a folder
                else:
                    to = unit_of(root, target)
                if to == unit:
                    continue
                if to not in layer:
                    fail("includes", f"{rel}:{n}: includes {to}, which is in no layer")
                elif layer[to] >= layer[unit]:
                    fail("includes", f"{rel}:{n}: {unit} (layer {layer[unit]}) includes {to} "
                                     f"(layer {layer[to]}): only lower layers may be included")


# --- pages ----------------------------------------------------------------------------------

def check_pages(root):
    for rel, limit in sorted(PAGE_MAX_LINES.items()):
        path = os.path.join(root, rel)
        if not os.path.exists(path):
            fail("pages", f"{rel} does not exist")
            continue
        lines = read(path).split("\n")
        if lines and lines[-1] == "":
            lines.pop()
        if len(lines) > limit:
            fail("pages", f"{rel} has {len(lines)} lines, at most {limit} allowed (the present "
                          "only: history goes to docs/CHANGELOG.md)")


# --- issues ---------------------------------------------------------------------------------

def check_issues(root):
    for rel in tracked_files(root):
        if not (rel == ISSUE_ROOTS[0] or rel.startswith(ISSUE_ROOTS[1:])):
            continue
        try:
            with open(os.path.join(root, rel), "rb") as f:
                data = f.read()
        except OSError:
            continue
        if b"\0" in data[:8192]:
            continue  # binary
        for n, line in enumerate(data.decode("utf-8", "replace").split("\n"), 1):
            for m in ISSUE_NUMBER.finditer(line):
                fail("issues", f"{rel}:{n}: '{m.group(0)}': an issue number (a reader has no "
                               "tracker: say what the change is)")


# --- changelog ------------------------------------------------------------------------------

def check_changelog(root):
    rel = "docs/CHANGELOG.md"
    path = os.path.join(root, rel)
    if not os.path.exists(path):
        fail("changelog", f"{rel} does not exist")
        return
    sections = []  # [heading line number, heading, subsection names]
    for n, line in enumerate(without_code(read(path), inline=False), 1):
        m = re.match(r"^(#{2,6}) (.*)$", line)
        if not m:
            continue
        level, title = len(m.group(1)), m.group(2).strip()
        if level == 2:
            sections.append([n, title, []])
        elif level > 3:
            fail("changelog", f"{rel}:{n}: '{line}': no headings below '### ' (Added, Changed, ...)")
        elif not sections:
            fail("changelog", f"{rel}:{n}: '{line}' comes before the first '## ' section")
        elif title not in CHANGELOG_KINDS:
            fail("changelog", f"{rel}:{n}: '{line}': a subsection is one of "
                              f"{', '.join(CHANGELOG_KINDS)}")
        elif title in sections[-1][2]:
            fail("changelog", f"{rel}:{n}: '{line}' twice in '{sections[-1][1]}'")
        else:
            sections[-1][2].append(title)
    unreleased = bool(sections) and sections[0][1] == "[Unreleased]"
    if not unreleased:
        fail("changelog", f"{rel}: the first section must be '## [Unreleased]'")
    last_date, last_version = None, {}
    for n, title, kinds in sections[1:] if unreleased else sections:
        m = CHANGELOG_RELEASE.match("## " + title)
        if not m:
            fail("changelog", f"{rel}:{n}: '## {title}': a release is '## [library X.Y.Z] - "
                              "YYYY-MM-DD' or '## [tool X.Y.Z] - YYYY-MM-DD'")
            continue
        kind = m.group(1) or ""
        version = tuple(int(m.group(i)) for i in (2, 3, 4))
        try:
            date = datetime.date.fromisoformat(m.group(5))
        except ValueError:
            fail("changelog", f"{rel}:{n}: '{m.group(5)}' is not a date")
            continue
        if last_date is not None and date > last_date:
            fail("changelog", f"{rel}:{n}: {m.group(5)} is later than the release above it "
                              "(newest first)")
        if kind in last_version and version >= last_version[kind]:
            fail("changelog", f"{rel}:{n}: {kind} {'.'.join(map(str, version))} is not older than "
                              "the release of the same kind above it (newest first)")
        if not kinds:
            fail("changelog", f"{rel}:{n}: '## {title}' has no subsection (Added, Changed, ...)")
        last_date, last_version[kind] = date, version


# --- offline --------------------------------------------------------------------------------

NETWORK_TOOLS = ("npm", "npx", "pip", "pip3", "curl", "wget", "git")


def cmake_files(root):
    out = []
    for d, dirs, names in os.walk(root):
        dirs[:] = [x for x in dirs if not x.startswith(".") and x not in ("build", "node_modules")]
        for name in names:
            if name == "CMakeLists.txt" or name.endswith(".cmake"):
                out.append(os.path.join(d, name))
    return sorted(out)


def check_offline(root):
    direct = re.compile(r"\b(file\s*\(\s*DOWNLOAD|FetchContent_\w+|ExternalProject_Add)\b", re.I)
    for path in cmake_files(root):
        rel = os.path.relpath(path, root)
        text = read(path)
        # Comments out, line numbers kept.
        code = "\n".join(re.sub(r"#.*$", "", line) for line in text.split("\n"))
        for m in direct.finditer(code):
            n = code.count("\n", 0, m.start()) + 1
            fail("offline", f"{rel}:{n}: {m.group(1)}: configuring must not reach the network")
        for m in re.finditer(r"execute_process\s*\(", code):
            depth, i = 1, m.end()
            while i < len(code) and depth:
                depth += {"(": 1, ")": -1}.get(code[i], 0)
                i += 1
            call = code[m.end():i]
            for tool in NETWORK_TOOLS:
                if re.search(r"(^|[\s/{}])" + tool + r"(\}|\s|$)", call, re.I) or \
                        re.search(r"\$\{FRAGSIM_" + tool + r"\}", call, re.I):
                    n = code.count("\n", 0, m.start()) + 1
                    fail("offline", f"{rel}:{n}: execute_process runs {tool} when configuring "
                                    "(put it in a set-up script)")
# --- mirror ---------------------------------------------------------------------------------

# Sources without a test named after them, each with the reason and where it is tested instead.
MIRROR_UNTESTED = {
    # One call, results_text(results_table(...)).
    "src/cli/report_table.cpp": "tested as the results table (tests/report/results_table_test.cpp) "
                                "and as `run`'s printed row (tests/cli/main_test.cpp)",
    # Two one-line forwards.
    "src/cli/table.cpp": "forwards to report/text_table.cpp and io/number_format.cpp, tested in "
                         "their own tests",
    "src/control/strategies/occlusion_bound.cpp": "edge-min's cover_max, tested through edge-min "
                                                  "(tests/strategies/edge_min_visibility_test.cpp, "
                                                  "edge_min_parallel_test.cpp)",
    "src/experiments/control_dump.cpp": "its files are what the differential replay reads: ctest "
                                        "Control.Dump.* writes them, Control.Replay.* "
                                        "(tests/control/replay.c) must match them bit for bit",
    "src/report/bundled_three_js.cpp": "what the build embedded (FRAGSIM_THREE_JS); tested through "
                                       "the report that carries it (report_viewer_test.cpp, "
                                       "html_report_test.cpp) and in Chromium (Browser.ReportLoads)",
    # Key tables of the library's strategies: one prober checks all three against the library.
    "src/strategies/deflect_all_keys.cpp": "checked against the library's ranges by "
                                           "tests/strategies/range_keys_test.cpp",
    "src/strategies/edge_keys.cpp": "checked against the library's ranges by "
                                    "tests/strategies/range_keys_test.cpp",
    "src/strategies/edge_min_keys.cpp": "checked against the library's ranges by "
                                        "tests/strategies/range_keys_test.cpp",
    "src/window/sdl_window.cpp": "needs a display: Play.WindowFlightReplays flies it under Xvfb "
                                 "(tests/play/play_window_test.sh)",
}

# Test files whose suites are not named after them, each with the reason.
MIRROR_SUITES = {
    "tests/stress/stress_test.cpp": "its own program (ctest Stress.shard0/1): StressMatrix, "
                                    "LongRun and WallIsland are the parts of its matrix, each "
                                    "with its own fixture",
}

SUITE = re.compile(r"^\s*(?:TEST|TEST_F|TEST_P|TYPED_TEST|TYPED_TEST_P)\(\s*([A-Za-z0-9_]+)\s*,",
                   re.M)


def camel(snake):
    return "".join(part[:1].upper() + part[1:] for part in snake.split("_"))


def mirror_test_dirs(source_dir):
    """The folders under tests/ where the sources of source_dir (a path under src/) are tested."""
    parts = source_dir.split("/")[1:]
    if parts[:2] == ["control", "api"]:
        return ["tests/control", "tests/control/api"]
    if parts[:1] == ["control"]:
        parts = parts[1:]  # the library's strategies/ and geometry/ beside the tool's
    return ["/".join(["tests"] + parts)]


def check_mirror(root):
    def files(top, ext):
        out = []
        for d, dirs, names in os.walk(os.path.join(root, top)):
            dirs[:] = [x for x in dirs if not x.startswith(".")]
            out += [os.path.relpath(os.path.join(d, n), root).replace(os.sep, "/")
                    for n in names if n.endswith(ext)]
        return sorted(out)

    sources = [s for s in files("src", ".cpp") if not s.startswith("src/web/")]
    tests = [t for t in files("tests", "_test.cpp") + files("tests", "_test.c")]
    # Each test file tests the source whose name is the longest that starts its own, in the folder
    # that source is tested in: evaluation_codec_test.cpp is evaluation_codec.cpp's, not
    # evaluation.cpp's.
    names_in = {}
    for s in sources:
        for d in mirror_test_dirs(os.path.dirname(s)):
            names_in.setdefault(d, []).append((os.path.basename(s)[:-len(".cpp")], s))
    tested_by = {}
    for t in tests:
        d, name = os.path.split(t)
        stem = name[:name.rindex("_test.")]
        best = None
        for x, s in names_in.get(d, []):
            if (stem == x or stem.startswith(x + "_")) and (best is None or len(x) > len(best[0])):
                best = (x, s)
        tested_by[t] = best
    mirrored = {b[1] for b in tested_by.values() if b}

    for s in sources:
        if s in mirrored:
            if s in MIRROR_UNTESTED:
                fail("mirror", f"{s} has a test named after it now: take it out of MIRROR_UNTESTED")
        elif s not in MIRROR_UNTESTED:
            where = " or ".join(f"{d}/{os.path.basename(s)[:-4]}_test.cpp"
                                for d in mirror_test_dirs(os.path.dirname(s)))
            fail("mirror", f"{s} has no test named after it ({where}, or _<aspect>_test.cpp)")
    for s in sorted(set(MIRROR_UNTESTED) - set(sources)):
        fail("mirror", f"MIRROR_UNTESTED lists {s}, which is not a source")

    for t in tests:
        stem = os.path.basename(t)[:os.path.basename(t).rindex("_test.")]
        allowed = {camel(stem)}
        if tested_by[t]:
            allowed.add(camel(tested_by[t][0]))
        suites = sorted(set(SUITE.findall(read(os.path.join(root, t)))))
        wrong = [x for x in suites if x not in allowed]
        if wrong and t not in MIRROR_SUITES:
            fail("mirror", f"{t}: suite {', '.join(wrong)} is not named after the file "
                           f"({' or '.join(sorted(allowed))})")
        elif not wrong and t in MIRROR_SUITES:
            fail("mirror", f"{t}: its suites are named after it now: take it out of MIRROR_SUITES")
    for t in sorted(set(MIRROR_SUITES) - set(tests)):
        fail("mirror", f"MIRROR_SUITES lists {t}, which is not a test file")

    print(f"mirror: {len(mirrored)} of {len(sources)} sources under src/ have a test named after "
          f"them; {len(MIRROR_UNTESTED)} are tested under other names (MIRROR_UNTESTED)")


# --- hooks ----------------------------------------------------------------------------------

def check_hooks(root):
    # Spelled in parts so that this file's own text does not match.
    hook = re.compile(r"\b(" + "FRAGSIM_" + "TEST_" + r"\w*|" + "g_" + "test_" + r"\w*)")
    for d, dirs, names in os.walk(os.path.join(root, "src")):
        dirs[:] = [x for x in dirs if not x.startswith(".")]
        for name in sorted(names):
            if not name.endswith((".cpp", ".hpp", ".h", ".c", ".mjs", ".js")):
                continue
            path = os.path.join(d, name)
            rel = os.path.relpath(path, root)
            for n, line in enumerate(read(path).split("\n"), 1):
                m = hook.search(line)
                if m:
                    fail("hooks", f"{rel}:{n}: '{m.group(1)}': a test hook in the shipped code "
                                  "(test through an observer or a test-only build)")


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--only")]
    only = None
    for i, a in enumerate(argv):
        if a.startswith("--only="):
            only = a.split("=", 1)[1].split(",")
        elif a == "--only" and i + 1 < len(argv):
            only = argv[i + 1].split(",")
            args.remove(argv[i + 1])
    if len(args) != 2:
        print(__doc__.strip().split("\n\n")[1], file=sys.stderr)
        return 2
    root, fragsim = os.path.abspath(args[0]), args[1]
    checks = {
        "readme": lambda: check_readme(root),
        "outside": lambda: check_outside(root),
        "links": lambda: check_links(root),
        "keys": lambda: check_keys(root, fragsim),
        "folders": lambda: check_folders(root),
        "includes": lambda: check_includes(root),
        "pages": lambda: check_pages(root),
        "issues": lambda: check_issues(root),
        "changelog": lambda: check_changelog(root),
        "offline": lambda: check_offline(root),
        "hooks": lambda: check_hooks(root),
        "mirror": lambda: check_mirror(root),
        "roots": lambda: check_roots(root),
        "comments": lambda: check_comments(root),
    }
    for name in only or checks:
        if name not in checks:
            print(f"check_docs.py: unknown check '{name}'", file=sys.stderr)
            return 2
        checks[name]()
    for line in failures:
        print(line)
    if failures:
        print(f"docs check: {len(failures)} finding(s)")
        return 1
    print(f"docs check: {', '.join(only or checks)}: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
