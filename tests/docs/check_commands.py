#!/usr/bin/env python3
"""The commands check (ctest Docs.Commands, label docs): every shell command the docs show works.

Usage: check_commands.py [--verbose] ROOT BUILD_DIR
  --verbose  also print each command line and how it was checked (run, static, exception, skip)
  ROOT       the repository's root
  BUILD_DIR  the release build folder: fragsim, bench/worst_frame, tests/fragsim_tests and the
             CTestTestfile that `ctest -N` reads

Reads every line of the ```sh and ```bash blocks of README.md, docs/*.md and data/scenes/README.md
(a line that ends in \\ goes on on the next; `# ...` ends it with a comment), splits it at `&&`,
takes off `NAME=value`, `taskset`, `nice`, `perf record` and `valgrind` in front, and then:
  fragsim      runs it, the commands of a block in order in one fresh folder whose data, scripts
               and examples lead into ROOT and whose build/release/fragsim is BUILD_DIR's, made
               short (FAST below) without changing its options; a synopsis (`[...]`, `...`, a
               placeholder in capitals such as FILE or DIR) and `play` without --bench-frames
               (it waits for a player) are not run: their options must be in the command's
               --help or be scene keys;
  scripts/X    exists, parses (`bash -n`, or py_compile for Python), is executable when run as a
               program, and names every --option of the line in its text (scripts are never run:
               README's first two are what CI runs, and they build everything);
  build/...    other built programs: exist in BUILD_DIR (no bench folder: one skip line), name
               every --option of the line in their --help, `key=value` keys are scene keys, a
               --gtest_filter matches tests, a SCENE is a file and a STRATEGY a strategy;
  cmake/ctest  a --preset is in CMakePresets.json (configure, build or test, as used), a --target
               is a target of a CMakeLists.txt, -S is a folder with a CMakeLists.txt, an -L label
               has tests in BUILD_DIR;
  others       gnuplot: the .gp file exists and uses every variable -e sets; sbatch: the script
               exists and parses, and the fragsim command it wraps is checked as a synopsis;
               pkg-config: the package's .pc file is made by ROOT; a program under /tmp is a
               target of ROOT.
Everywhere: a NAME=value in front is read by ROOT's sources, a path into ROOT or BUILD_DIR (also
in a comment) exists, and a `[--option]` in a comment is an option of the command.

Fails (exit 1, one line per finding, `file:line: ...`) on any of the above, on a command no rule
knows, on an exception (EXCEPTIONS) that matches no command, and when no command was found at all
(an extractor that finds nothing checks nothing). Python standard library only, like
check_docs.py beside it.
"""

import json
import os
import py_compile
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

# Appended to a fragsim command that takes scene keys and does not set the key itself: the run
# gets short (a tenth of a second, 8 pieces) while every option, file and value of the documented
# line is still read and used.
FAST = [("simulation.duration_s", "0.1"), ("object.splits", "2")]
JOBS = "2"          # --jobs, where the command has it and the line does not set it
SUITE_LIMIT = "1"   # suite --limit: the first run of the selection (a run is every strategy)
BENCH_REPEATS = "1"  # bench --repeats
PLAY_FRAMES = "5"   # play --bench-frames
# One documented command, made short; more is a finding. The longest, the suite's one run, takes
# about 10 s in release on a busy two-core machine and several times that under AddressSanitizer.
TIMEOUT_S = 90

# Commands whose input nothing in the docs makes: checked like a synopsis, never run. Keep short.
EXCEPTIONS = [
    # The replay scene an interactive `fragsim play` flight writes; no flight here.
    (r"--scene play-[0-9]+\.ini", "its scene is written by an interactive fragsim play flight"),
]

# Top folders of the repository: a word that starts with one of them is a path into ROOT.
ROOT_PATH = re.compile(r"^(?:\./)?((?:data|scripts|docs|src|tests|bench|examples|cmake|\.ci)/"
                       r"[\w./-]*[\w])$")
BUILD_PREFIX = "build/release/"
# A placeholder a reader fills in: FILE, DIR, J, S, FILE.glb, OUT.
PLACEHOLDER = re.compile(r"^[A-Z][A-Z0-9_]*(?:\.[A-Za-z0-9]+)?$")
# Options whose value is a file or folder the command writes.
OUTPUTS = {"out", "csv", "report", "bake", "sheet", "record", "dump-control"}
OUTSIDE_TOOLS = {"cc", "gcc", "clang", "c++", "perf"}

failures = []
skips = []


def fail(where, message):
    failures.append(f"{where}: {message}")


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def output_of(argv, cwd=None, env=None, timeout=60):
    """stdout and stderr of argv together ('' if it cannot start), and its exit status."""
    try:
        p = subprocess.run(argv, cwd=cwd, env=env, capture_output=True, text=True,
                           timeout=timeout)
        return p.stdout + p.stderr, p.returncode
    except (OSError, subprocess.SubprocessError) as e:
        return str(e), None


# --- the docs' command lines ----------------------------------------------------------------

def markdown_files(root):
    files = [os.path.join(root, "README.md"), os.path.join(root, "data", "scenes", "README.md")]
    docs = os.path.join(root, "docs")
    files += sorted(os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
    return [f for f in files if os.path.exists(f)]


def blocks(path):
    """The ```sh and ```bash blocks of a page: lists of (line number, line), a line that ends in
    a backslash joined with the next."""
    out, block, pending, start = [], None, "", 0
    for n, line in enumerate(read(path).split("\n"), 1):
        fence = line.strip()
        if fence.startswith("```"):
            if block is not None:
                out.append(block)
                block = None
            elif fence[3:].strip() in ("sh", "bash"):
                block = []
            continue
        if block is None:
            continue
        if not pending:
            start = n
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1] + " "
            continue
        text = pending + line
        pending = ""
        if text.strip() and not text.strip().startswith("#"):
            block.append((start, text.strip()))
    return out


def split_comment(line):
    """(code, comment): a # that starts a word outside quotes starts the comment."""
    quote = None
    for i, c in enumerate(line):
        if quote:
            if c == quote:
                quote = None
        elif c in "'\"":
            quote = c
        elif c == "#" and (i == 0 or line[i - 1].isspace()):
            return line[:i].rstrip(), line[i + 1:].strip()
    return line, ""


def commands_of(code):
    """The commands of a line as word lists: `$( )` inside are commands of their own (their place
    takes the word $SUBST), `&&`, `||`, `;` and `|` separate."""
    inner = []

    def take(m):
        inner.append(m.group(1))
        return "$SUBST"

    code = re.sub(r"\$\(([^()]*)\)", take, code)
    words = shlex.split(code)
    out, current = [], []
    for w in words:
        if w in ("&&", "||", ";", "|"):
            out.append(current)
            current = []
        else:
            current.append(w)
    out.append(current)
    for text in inner:
        out += commands_of(text)
    return [c for c in out if c]


def strip_front(words):
    """(env, valgrind's options, words): NAME=value assignments and the wrappers taskset, nice,
    time, perf record and valgrind taken off the front."""
    env, tool_options = {}, []
    while words:
        w = words[0]
        m = re.match(r"^([A-Za-z_][A-Za-z0-9_]*)=(.*)$", w)
        if m:
            env[m.group(1)] = m.group(2)
            words = words[1:]
        elif w == "taskset":
            words = words[3:] if len(words) > 1 and words[1] in ("-c", "--cpu-list") \
                else words[2:]
        elif w == "nice":
            if len(words) > 1 and words[1] == "-n":
                words = words[3:]
            elif len(words) > 1 and re.match(r"^-[0-9]+$", words[1]):
                words = words[2:]
            else:
                words = words[1:]
        elif w == "time":
            words = words[1:]
        elif w == "valgrind":
            i = 1
            while i < len(words) and words[i].startswith("-"):
                tool_options.append(words[i])
                i += 1
            words = words[i:]
        elif w == "perf" and len(words) > 1 and words[1] in ("record", "stat"):
            rest = words[2:]
            if "--" in rest:
                words = rest[rest.index("--") + 1:]
                continue
            i = 0
            while i < len(rest) and rest[i].startswith("-"):
                # perf's options with a separate value
                i += 2 if rest[i] in ("-F", "-e", "-o", "-c", "-p", "-t", "-m", "-C") else 1
            words = rest[i:]
        else:
            break
    return env, tool_options, words


def bare(word):
    """A word with a synopsis's brackets taken off."""
    return word.strip("[]")


def option_name(word):
    """'--csv' -> 'csv', '--gtest_filter=X' -> 'gtest_filter', anything else -> None."""
    w = bare(word)
    m = re.match(r"^--([A-Za-z0-9][A-Za-z0-9_.-]*)(?:=.*)?$", w)
    return m.group(1) if m else None


def is_synopsis(words):
    return any("[" in w or "]" in w or "..." in w or PLACEHOLDER.match(w) for w in words)


# --- what the program and the tree offer ------------------------------------------------------

class Tree:
    def __init__(self, root, build):
        self.root, self.build = root, build
        self.fragsim = os.path.join(build, "fragsim")
        self._help = {}
        self._targets = None
        self._presets = None
        self._sources = None
        top, _ = output_of([self.fragsim, "--help"])
        listed = top.split("commands:", 1)[1] if "commands:" in top else ""
        self.commands = set(re.findall(r"(?m)^  ([a-z]+) ", listed))
        text = self.help("compare")
        keys = text.split("Scene keys", 1)[1] if "Scene keys" in text else ""
        self.scene_keys = set(re.findall(r"(?m)^  --([A-Za-z0-9_.-]+)", keys))
        strategies = text.split("\nStrategies", 1)[1] if "\nStrategies" in text else ""
        self.strategies = set(re.findall(r"(?m)^  ([a-z][a-z-]*)\s{2,}", strategies))
        if not self.commands or not self.scene_keys or not self.strategies:
            fail("check_commands.py", f"could not read the commands, scene keys and strategies "
                                      f"of '{self.fragsim} --help' and 'compare --help'")

    def help(self, command):
        if command not in self._help:
            text, _ = output_of([self.fragsim, command, "--help"])
            if "usage:" not in text:
                # one finding, not one per option of every line that names the command
                fail("check_commands.py", f"could not read `fragsim {command} --help`: "
                                          f"{text.strip()[:200] or 'no output'}")
            self._help[command] = text
        return self._help[command]

    def options(self, command):
        """A fragsim command's own options (its --help before the scene keys)."""
        text = self.help(command).split("Scene keys", 1)[0]
        found = set(re.findall(r"(?m)^\s+(?:-[A-Za-z] \[ )?--([A-Za-z0-9][A-Za-z0-9_.-]*)",
                               text))
        found |= set(re.findall(r"\[--([A-Za-z0-9][A-Za-z0-9_.-]*)", text.split("\n", 1)[0]))
        return found | {"help"}

    def takes_scene_keys(self, command):
        return "Scene keys" in self.help(command)

    def targets(self):
        if self._targets is None:
            self._targets = set()
            for d, dirs, names in os.walk(self.root):
                dirs[:] = [x for x in dirs if not x.startswith(".") and x != "build"]
                if "CMakeLists.txt" in names:
                    text = read(os.path.join(d, "CMakeLists.txt"))
                    self._targets |= set(re.findall(
                        r"add_(?:executable|library|custom_target)\(\s*([A-Za-z0-9_.:+-]+)", text))
        return self._targets

    def presets(self):
        if self._presets is None:
            try:
                data = json.loads(read(os.path.join(self.root, "CMakePresets.json")))
            except (OSError, ValueError):
                data = {}
            self._presets = {kind: {p.get("name") for p in data.get(f"{kind}Presets", [])}
                             for kind in ("configure", "build", "test")}
        return self._presets

    def sources(self):
        """The text of the tree's source, build and script files (not its pages, not this
        file): where an environment variable is read."""
        if self._sources is None:
            parts = []
            me = os.path.realpath(__file__)
            for top in ("src", "bench", "tests", "scripts", "examples", "cmake", ".ci"):
                for d, dirs, names in os.walk(os.path.join(self.root, top)):
                    dirs[:] = [x for x in dirs if not x.startswith(".")]
                    for name in names:
                        path = os.path.join(d, name)
                        if name.endswith(".md") or os.path.realpath(path) == me:
                            continue
                        try:
                            with open(path, "rb") as f:
                                data = f.read()
                        except OSError:
                            continue
                        if b"\0" not in data[:8192]:
                            parts.append(data.decode("utf-8", "replace"))
            self._sources = "\n".join(parts)
        return self._sources

    def path_of(self, word):
        """The file a word names in ROOT or BUILD_DIR, or None if it names neither."""
        w = bare(word).strip("'\"(),")
        if w.startswith(BUILD_PREFIX):
            return os.path.join(self.build, w[len(BUILD_PREFIX):])
        m = ROOT_PATH.match(w)
        return os.path.join(self.root, m.group(1)) if m else None


# --- checks -----------------------------------------------------------------------------------

def check_paths(tree, where, words, outputs=()):
    """Every word that names a path into ROOT or BUILD_DIR names one that exists (a written
    file: its folder)."""
    skip_next = False
    for w in words:
        if skip_next:
            skip_next = False
            path = tree.path_of(w)
            if path and not os.path.isdir(os.path.dirname(path)):
                fail(where, f"'{w}': no folder {os.path.relpath(os.path.dirname(path), tree.root)}")
            continue
        if option_name(w) in outputs:
            skip_next = True
            continue
        path = tree.path_of(w)
        if path and not os.path.exists(path):
            fail(where, f"'{bare(w)}': no such file")


def check_front(tree, where, env, tool_options):
    """What stood in front of the program: a variable it is given is read by the tree; a function
    valgrind is told to watch still exists."""
    for option in tool_options:
        # valgrind --toggle-collect=ns::Class::function(...): the function is still in the tree
        m = re.match(r"^--(?:toggle-collect|collect-only|fn-skip)=([A-Za-z0-9_:]+)", option)
        if m:
            for part in m.group(1).split("::"):
                if part and not re.search(r"(?<![A-Za-z0-9_])" + part + r"(?![A-Za-z0-9_])",
                                          tree.sources()):
                    fail(where, f"{option}: {part} is nowhere in the tree's sources")
    for name in env:
        if name.isupper() and not re.search(r"(?<![A-Za-z0-9_])" + name + r"(?![A-Za-z0-9_])",
                                            tree.sources()):
            fail(where, f"{name}: no source file of the tree reads this variable")


def check_fragsim_static(tree, where, words, why):
    """A fragsim command not run: its command exists, its options are in its --help or scene
    keys, its strategies are strategies, the files it reads exist."""
    if len(words) < 2 or words[1].startswith("-"):
        for w in words[1:]:
            name = option_name(w)
            if name and name != "help":
                fail(where, f"fragsim {w}: not an option of fragsim itself")
        return
    command = words[1]
    if command not in tree.commands:
        fail(where, f"'fragsim {command}': no such command ({why})")
        return
    check_fragsim_options(tree, where, command, words[2:], why)
    check_paths(tree, where, words[2:], OUTPUTS)


def check_fragsim_options(tree, where, command, words, why):
    if "usage:" not in tree.help(command):
        return  # reported once by Tree.help
    options = tree.options(command)
    keys = tree.scene_keys if tree.takes_scene_keys(command) else set()
    for i, w in enumerate(words):
        name = option_name(w)
        if name is None:
            continue
        # "--section.key value": a synopsis's stand-in for any scene key.
        if name in options or name in keys or (keys and name == "section.key"):
            if name in ("strategy", "strategies") and i + 1 < len(words) and \
                    not words[i + 1].startswith("-"):
                for s in bare(words[i + 1]).split(","):
                    if not PLACEHOLDER.match(s) and s not in tree.strategies:
                        fail(where, f"fragsim {command} --{name} {s}: no such strategy")
            continue
        fail(where, f"fragsim {command}: --{name} is not in `fragsim {command} --help` ({why})")


def comment_options(tree, where, words, comment):
    """`[--option ...]` in the comment of a fragsim line: options of the same command."""
    if len(words) < 2 or words[1] not in tree.commands or "[--" not in comment:
        return
    check_fragsim_options(tree, where, words[1],
                          re.findall(r"\[(--[A-Za-z0-9][A-Za-z0-9_.-]*)", comment),
                          "in the comment")


def given(words):
    """The options and scene keys a fragsim line sets itself (a swept key counts)."""
    names = set()
    for i, w in enumerate(words):
        name = option_name(w)
        if name:
            names.add(name)
            if name == "vary" and i + 1 < len(words):
                names.add(words[i + 1].split("=", 1)[0])
    return names


def scene_dt(tree, cwd, words):
    """The step of the scene a fragsim line runs: its own --simulation.dt_s, its scene file's
    dt_s, else the program's default."""
    for i, w in enumerate(words[:-1]):
        if w == "--simulation.dt_s":
            return float(words[i + 1])
    for i, w in enumerate(words[:-1]):
        if w == "--scene":
            try:
                m = re.search(r"(?m)^\s*dt_s\s*=\s*([0-9.eE+-]+)",
                              read(os.path.join(cwd, words[i + 1])))
                if m:
                    return float(m.group(1))
            except (OSError, ValueError):
                pass
    m = re.search(r"--simulation\.dt_s V.*?\[([0-9.eE+-]+)\]", tree.help("compare"), re.S)
    return float(m.group(1)) if m else 1.0 / 60


def duration(tree, cwd, words, short):
    """`short`, or long enough for the last step a --steps or --sheet-steps names."""
    last = None
    for i, w in enumerate(words[:-1]):
        if w in ("--steps", "--sheet-steps"):
            numbers = [int(x) for x in re.findall(r"[0-9]+", words[i + 1].split(":")[1]
                                                   if w == "--steps" and ":" in words[i + 1]
                                                   else words[i + 1])]
            if numbers:
                last = max(numbers + ([last] if last is not None else []))
    if last is None:
        return short
    return f"{max(float(short), (last + 2) * scene_dt(tree, cwd, words)):.6g}"


def run_fragsim(tree, where, words, env, cwd):
    """Runs a fragsim line (short) in the block's folder. False if it cannot run headless."""
    argv = [tree.fragsim] + words[1:]
    command = words[1] if len(words) > 1 and not words[1].startswith("-") else None
    if command is not None and command not in tree.commands:
        fail(where, f"'fragsim {command}': no such command")
        return True
    if command is not None and "--help" not in words and "-h" not in words:
        options, names = tree.options(command), given(words[2:])
        if command == "play":
            # Without --bench-frames play opens a window and waits for a player to fly and quit:
            # it cannot run here, so its options are checked against `play --help` instead.
            if "bench-frames" not in names:
                return False
            i = argv.index("--bench-frames")
            argv[i + 1] = PLAY_FRAMES
        for i, w in enumerate(argv):
            if option_name(w) in OUTPUTS and i + 1 < len(argv):
                dest = os.path.realpath(os.path.join(cwd, argv[i + 1]))
                if os.path.commonpath([dest, tree.root]) == tree.root:
                    fail(where, f"{w} {argv[i + 1]}: writes into the repository")
                    return True
        if "jobs" in options and "jobs" not in names:
            argv += ["--jobs", JOBS]
        if tree.takes_scene_keys(command):
            for key, value in FAST:
                if key not in names:
                    if key == "simulation.duration_s":
                        value = duration(tree, cwd, words, value)
                    argv += [f"--{key}", value]
        if command == "suite" and "limit" not in names:
            argv += ["--limit", SUITE_LIMIT]
        if command == "bench" and "repeats" not in names:
            argv += ["--repeats", BENCH_REPEATS]
    full_env = dict(os.environ, SDL_VIDEODRIVER="dummy", **env)
    start = time.monotonic()
    try:
        p = subprocess.run(argv, cwd=cwd, env=full_env, capture_output=True, text=True,
                           timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        fail(where, f"did not finish in {TIMEOUT_S} s (run as: {shlex.join(argv[1:])})")
        return True
    except OSError as e:
        fail(where, f"could not run {tree.fragsim}: {e}")
        return True
    if p.returncode != 0:
        lines = [l for l in (p.stderr + p.stdout).split("\n") if l.strip()]
        last = lines[-1].strip() if lines else "no output"
        fail(where, f"exit status {p.returncode}: {last} (run as: fragsim "
                    f"{shlex.join(argv[1:])}; {time.monotonic() - start:.1f} s)")
    return True


def check_script(tree, where, path_word, args, direct):
    path = tree.path_of(path_word) or os.path.join(tree.root, path_word)
    rel = os.path.relpath(path, tree.root)
    if not os.path.isfile(path):
        fail(where, f"{path_word}: no such script")
        return
    if direct and not os.access(path, os.X_OK):
        fail(where, f"{rel}: not executable, but the line runs it as a program")
    if path.endswith(".py"):
        with tempfile.TemporaryDirectory() as scratch:
            try:
                py_compile.compile(path, cfile=os.path.join(scratch, "x.pyc"), doraise=True)
            except py_compile.PyCompileError as e:
                fail(where, f"{rel} does not compile: {e.msg.strip().splitlines()[-1]}")
    else:
        out, status = output_of(["bash", "-n", path])
        if status != 0:
            last = out.strip().splitlines()[-1] if out.strip() else f"exit status {status}"
            fail(where, f"{rel}: bash -n: {last}")
    text = read(path)
    for w in args:
        name = option_name(w)
        if name and not re.search(r"--" + re.escape(name) + r"(?![A-Za-z0-9_-])", text):
            fail(where, f"{rel} has no option --{name}")
    check_paths(tree, where, args)


def usage_of(path):
    out, _ = output_of([path, "--help"], timeout=20)
    return out


def check_built(tree, where, words):
    """A program of the build other than fragsim (the line is not run)."""
    rel = words[0][len(BUILD_PREFIX):]
    if rel.startswith("bench/") and not os.path.isdir(os.path.join(tree.build, "bench")):
        skips.append(where)
        return "skip"
    path = os.path.join(tree.build, rel)
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        fail(where, f"{words[0]}: no such program in the build")
        return "static"
    usage = usage_of(path)
    args = words[1:]
    value_options = set(re.findall(r"\[--([A-Za-z0-9_-]+) [^\]\-]", usage))
    positionals, skip_next = [], False
    for w in args:
        if skip_next:
            skip_next = False
            if "=" in w:
                check_override(tree, where, w)
            continue
        name = option_name(w)
        if name:
            if not re.search(r"--" + re.escape(name) + r"(?![A-Za-z0-9_-])", usage):
                fail(where, f"{os.path.basename(rel)} has no option --{name} (its --help)")
            if name == "gtest_filter":
                listed, _ = output_of([path, "--gtest_list_tests", bare(w)], timeout=20)
                if not re.search(r"(?m)^  \S", listed):
                    fail(where, f"{bare(w)}: matches no test of {os.path.basename(rel)}")
            skip_next = name in value_options and "=" not in w
        elif re.match(r"^\[?[a-z][a-z0-9_-]*\.[a-z0-9_.]+=", w):
            check_override(tree, where, w)
        else:
            positionals.append(w)
    # The usage's positional placeholders, in order, against the line's words.
    m = re.search(r"(?m)^usage: \S+ (.*)$", usage)
    if m and "..." not in args:
        names = [x for x in m.group(1).split() if re.match(r"^[A-Z][A-Z0-9_]*$", x)]
        for name, w in zip(names, positionals):
            if name == "STRATEGY" and bare(w) not in tree.strategies:
                fail(where, f"{os.path.basename(rel)}: '{w}' is not a strategy")
    check_paths(tree, where, positionals)
    return "static"


def check_override(tree, where, word):
    key = bare(word).split("=", 1)[0]
    if key not in tree.scene_keys:
        fail(where, f"'{bare(word)}': {key} is not a scene key (`fragsim compare --help`)")


def check_cmake(tree, where, words):
    presets = tree.presets()
    tool = words[0]
    kind = "test" if tool == "ctest" else "build" if "--build" in words else \
        "install" if "--install" in words else "configure"
    i = 1
    while i < len(words):
        w, value = words[i], words[i + 1] if i + 1 < len(words) else ""
        if w.startswith("--preset="):
            w, value = "--preset", w.split("=", 1)[1]
            i -= 1
        if w == "--preset":
            if value not in presets.get(kind, set()):
                fail(where, f"{tool}: no {kind} preset '{value}' in CMakePresets.json")
            i += 2
        elif w == "--target" or w == "-t":
            i += 1
            while i < len(words) and not words[i].startswith("-"):
                if words[i] not in tree.targets():
                    fail(where, f"--target {words[i]}: no such target in the CMakeLists.txt files")
                i += 1
        elif w == "-S" and tool == "cmake":
            if not os.path.isfile(os.path.join(tree.root, value, "CMakeLists.txt")):
                fail(where, f"-S {value}: no CMakeLists.txt there")
            i += 2
        elif w in ("-L", "--label-regex") and tool == "ctest":
            if not os.path.isfile(os.path.join(tree.build, "CTestTestfile.cmake")):
                fail(where, f"-L {value}: {tree.build} has no CTestTestfile.cmake")
            else:
                out, _ = output_of(["ctest", "--test-dir", tree.build, "-N", "-L", value])
                m = re.search(r"Total Tests:\s*([0-9]+)", out)
                if not m or m.group(1) == "0":
                    fail(where, f"-L {value}: no test has this label (ctest -N -L {value})")
            i += 2
        elif w == "--test-dir":
            if value.rstrip("/") + "/" != BUILD_PREFIX:
                fail(where, f"--test-dir {value}: not the release build")
            i += 2
        else:
            i += 1


def check_gnuplot(tree, where, words):
    scripts = [w for w in words if w.endswith(".gp")]
    sets = [words[i + 1] for i, w in enumerate(words[:-1]) if w == "-e"]
    if not scripts:
        fail(where, "gnuplot: no .gp file on the line")
        return
    for gp in scripts:
        path = tree.path_of(gp)
        if not path or not os.path.isfile(path):
            fail(where, f"{gp}: no such file")
            continue
        text = read(path)
        for s in sets:
            for name, value in re.findall(r"([A-Za-z_]\w*)\s*=\s*'([^']*)'", s):
                if not re.search(r"\b" + re.escape(name) + r"\b", text):
                    fail(where, f"{gp} does not use the variable {name} set by -e")
                # an input it reads from the tree exists, an output's folder does
                check_paths(tree, where, [value] if value.endswith(".csv") else
                            ["--out", value], {"out"})


def check_sbatch(tree, where, words):
    i = 1
    while i < len(words) and words[i].startswith("-"):
        i += 1
    if i == len(words):
        fail(where, "sbatch: no script on the line")
        return
    script, args = words[i], words[i + 1:]
    path = tree.path_of(script)
    if not path or not os.path.isfile(path):
        fail(where, f"{script}: no such script")
        return
    out, status = output_of(["bash", "-n", path])
    if status != 0:
        fail(where, f"{script}: bash -n: {out.strip()}")
    # A script that runs a slice of a fragsim command: SLICES_DIR COMMAND OPTIONS...
    at = next((k for k, w in enumerate(args) if w in tree.commands), None)
    if at is not None:
        check_fragsim_static(tree, where, ["fragsim"] + args[at:], f"run by {script}")
    else:
        check_paths(tree, where, args)


def check_pkg_config(tree, where, words):
    made = set()
    for d, dirs, names in os.walk(tree.root):
        dirs[:] = [x for x in dirs if not x.startswith(".") and x != "build"]
        made |= {n[:-len(".pc.in")] for n in names if n.endswith(".pc.in")}
        made |= {n[:-len(".pc")] for n in names if n.endswith(".pc")}
    for w in words[1:]:
        if not w.startswith("-") and w not in made:
            fail(where, f"pkg-config {w}: no {w}.pc(.in) in the tree")


def check_command(tree, where, words, comment, cwd_of, exception):
    """One command of a line; returns how it was checked: run, static, skip."""
    env, tool_options, words = strip_front(words)
    check_front(tree, where, env, tool_options)
    if not words:
        return "static"
    prog = words[0]
    if prog in ("fragsim", BUILD_PREFIX + "fragsim"):
        words = ["fragsim"] + words[1:]
        comment_options(tree, where, words, comment)
        if exception:
            check_fragsim_static(tree, where, words, "an exception")
            return "exception"
        if is_synopsis(words):
            check_fragsim_static(tree, where, words, "a synopsis")
            return "static"
        if run_fragsim(tree, where, words, env, cwd_of()):
            return "run"
        check_fragsim_static(tree, where, words, "play waits for a player: not run")
        return "static"
    if prog.startswith(BUILD_PREFIX):
        return check_built(tree, where, words)
    # Scripts are checked, never run: README's first two (compare.sh, test.sh) are what CI runs,
    # and they install packages and build the whole tree.
    if prog == "bash" and len(words) > 1:
        check_script(tree, where, words[1], words[2:], direct=False)
        return "static"
    if prog == "python3" and len(words) > 1:
        check_script(tree, where, words[1], words[2:], direct=False)
        return "static"
    if prog.startswith("scripts/") or prog.startswith("./scripts/"):
        check_script(tree, where, prog, words[1:], direct=True)
        return "static"
    if prog in ("cmake", "ctest"):
        check_cmake(tree, where, words)
        return "static"
    if prog == "gnuplot":
        check_gnuplot(tree, where, words)
        return "static"
    if prog == "sbatch":
        check_sbatch(tree, where, words)
        return "static"
    if prog == "pkg-config":
        check_pkg_config(tree, where, words)
        return "static"
    if prog in OUTSIDE_TOOLS:
        check_paths(tree, where, words[1:])
        return "static"
    if prog.startswith("/tmp/"):
        # a program of a build the line's block makes elsewhere: a target of the tree
        if os.path.basename(prog) not in tree.targets():
            fail(where, f"{prog}: {os.path.basename(prog)} is no target of the CMakeLists.txt "
                        "files")
        return "static"
    fail(where, f"'{prog}': no rule checks this command (add one to tests/docs/check_commands.py)")
    return "static"


# --- the whole -------------------------------------------------------------------------------

def block_folder(tree):
    """A fresh folder that looks like the repository to a documented command: data, scripts and
    examples lead into ROOT, build/release/fragsim is the build's, and docs is a real, empty
    folder, so a command that writes where the docs keep their results writes here."""
    folder = tempfile.mkdtemp(prefix="fragsim-commands-")
    for name in ("data", "scripts", "examples"):
        os.symlink(os.path.join(tree.root, name), os.path.join(folder, name))
    os.makedirs(os.path.join(folder, "build", "release"))
    os.symlink(tree.fragsim, os.path.join(folder, "build", "release", "fragsim"))
    os.makedirs(os.path.join(folder, "docs", "img"))
    return folder


def main(argv):
    verbose = "--verbose" in argv
    argv = [a for a in argv if a != "--verbose"]
    if len(argv) != 3:
        print(__doc__.strip().split("\n\n")[1], file=sys.stderr)
        return 2
    root, build = os.path.realpath(argv[1]), os.path.realpath(argv[2])
    started = time.monotonic()
    tree = Tree(root, build)
    counts = {"run": 0, "static": 0, "exception": 0, "skip": 0}
    used = set()
    lines = 0
    for page in markdown_files(root):
        rel = os.path.relpath(page, root)
        for block in blocks(page):
            folder = []

            def cwd_of():
                if not folder:
                    folder.append(block_folder(tree))
                return folder[0]

            try:
                for n, text in block:
                    where = f"{rel}:{n}"
                    lines += 1
                    code, comment = split_comment(text)
                    exception = None
                    for k, (pattern, _) in enumerate(EXCEPTIONS):
                        if re.search(pattern, code):
                            exception = k
                            used.add(k)
                    try:
                        commands = commands_of(code)
                    except ValueError as e:
                        fail(where, f"cannot split the line into words: {e}")
                        continue
                    line_start = time.monotonic()
                    how = [check_command(tree, where, words, comment, cwd_of,
                                         exception is not None) for words in commands]
                    for path in re.findall(r"(?<![\w/.-])((?:data|scripts|docs|src|tests|bench|"
                                           r"examples|cmake|\.ci|build/release)/[\w./-]*\w)",
                                           comment):
                        full = tree.path_of(path)
                        if full and not os.path.exists(full):
                            fail(where, f"'{path}' (in the comment): no such file")
                    kind = next((k for k in ("exception", "run", "skip") if k in how), "static")
                    counts[kind] += 1
                    if verbose:
                        print(f"{where}: {kind} ({time.monotonic() - line_start:.1f} s): "
                              f"{text}")
            finally:
                if folder:
                    shutil.rmtree(folder[0], ignore_errors=True)
    for k, (pattern, why) in enumerate(EXCEPTIONS):
        if k not in used:
            fail("tests/docs/check_commands.py", f"the exception '{pattern}' ({why}) matches no "
                                                 "documented command: remove it")
    if lines == 0:
        fail("check_commands.py", "no command found in the sh and bash blocks of the docs")
    if skips:
        print(f"skipped {len(skips)} command lines of programs under bench/ ({', '.join(skips)}): "
              f"{build} has no bench folder (a build without the benchmarks)")
    for line in failures:
        print(line)
    summary = (f"commands check: {lines} command lines: {counts['run']} run, {counts['static']} "
               f"verified statically, {counts['exception']} exceptions, {counts['skip']} "
               f"skipped; {time.monotonic() - started:.1f} s")
    if failures:
        print(f"{summary}; {len(failures)} finding(s)")
        return 1
    print(f"{summary}: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
