#!/usr/bin/env python3
"""Builds fragsim's web demo: one self-contained HTML page that opens offline from file://.

Usage: build_page.py PACKAGE_DIR NPM_PREFIX OUT_DIR

PACKAGE_DIR is the fragsim-control npm package folder (scripts/web_build.sh writes it to
build/web/package); NPM_PREFIX holds node_modules/three and node_modules/@dimforge/rapier3d-compat
(npm install --prefix NPM_PREFIX ...). Writes OUT_DIR/index.html: page.html with demo.js, three.js,
Rapier and the fragsim package inside it, and the three licences.

Chromium refuses module scripts from file:// URLs but imports data: URLs, so each module travels
in the page as the text of a <script type="text/plain"> (base64 when its text could end the
element early) and demo.js imports it from a data: URL it makes. A module imported from a data:
URL cannot import relatively, so fragsim.mjs's import of its emscripten glue is named here
(data-glue-specifier) and demo.js replaces it with the glue's own data: URL.
"""

import base64
import html
import json
import pathlib
import re
import sys

HERE = pathlib.Path(__file__).resolve().parent
THREE_DIR = "node_modules/three"
RAPIER_DIR = "node_modules/@dimforge/rapier3d-compat"
GLUE_IMPORT = re.compile(r"""import\s+createModule\s+from\s+('\./fragsim_control_wasm\.mjs')\s*;""")
# Rapier 0.19's npm package carries no LICENSE file (later ones do: the Apache License 2.0 with
# "Copyright 2020 Dimforge EURL" in its appendix); then the licence text comes from Debian.
APACHE_FALLBACK = pathlib.Path("/usr/share/common-licenses/Apache-2.0")
RAPIER_COPYRIGHT = "Copyright 2020 Dimforge EURL"
# A source map comment would make DevTools look for a file beside a data: URL.
SOURCE_MAP_COMMENT = re.compile(r"\n//# sourceMappingURL=\S+\s*$")


class MissingInput(Exception):
    pass


def read_text(path):
    if not path.is_file():
        raise MissingInput(str(path))
    return path.read_text(encoding="utf-8")


def package_version(package_dir):
    return json.loads(read_text(package_dir / "package.json"))["version"]


def embeddable_as_text(source):
    """Whether `source` can sit as it is inside <script type="text/plain">: nothing that ends the
    element or starts the parser's escaped states, and no character the parser would change."""
    lowered = source.lower()
    return ("</script" not in lowered and "<!--" not in lowered and "\r" not in source
            and "\0" not in source)


def module_element(element_id, source, extra=""):
    if embeddable_as_text(source):
        return '<script type="text/plain" id="%s"%s>%s</script>\n' % (element_id, extra, source)
    encoded = base64.b64encode(source.encode("utf-8")).decode("ascii")
    return '<script type="text/plain" id="%s" data-encoding="base64"%s>%s</script>\n' % (
        element_id, extra, encoded)


def licence_element(name, licence_name, text, note=""):
    note_html = "<p>%s</p>" % html.escape(note) if note else ""
    return ("<details><summary>%s &mdash; %s licence</summary>%s<pre>%s</pre></details>\n"
            % (html.escape(name), html.escape(licence_name), note_html, html.escape(text)))


def rapier_licence(rapier_dir):
    own = rapier_dir / "LICENSE"
    if own.is_file():
        return own.read_text(encoding="utf-8"), ""
    if not APACHE_FALLBACK.is_file():
        raise MissingInput("%s (or %s)" % (own, APACHE_FALLBACK))
    note = ("This Rapier package states its licence in package.json (\"Apache-2.0\") and ships no "
            "LICENSE file; %s. The text below is the Apache License 2.0 as Debian ships it (%s)."
            % (RAPIER_COPYRIGHT, APACHE_FALLBACK))
    return APACHE_FALLBACK.read_text(encoding="utf-8"), note


def build(package_dir, npm_prefix, out_dir):
    three_dir = npm_prefix / THREE_DIR
    rapier_dir = npm_prefix / RAPIER_DIR
    template = read_text(HERE / "page.html")
    demo = read_text(HERE / "demo.js")
    three = read_text(three_dir / "build/three.module.min.js")
    rapier = SOURCE_MAP_COMMENT.sub("\n", read_text(rapier_dir / "rapier.mjs"))
    api = read_text(package_dir / "fragsim.mjs")
    glue = read_text(package_dir / "fragsim_control_wasm.mjs")
    fragsim_licence = read_text(package_dir / "LICENSE")
    three_licence = read_text(three_dir / "LICENSE")
    rapier_text, rapier_note = rapier_licence(rapier_dir)
    versions = {name: package_version(d) for name, d in
                (("three", three_dir), ("rapier", rapier_dir), ("fragsim", package_dir))}

    glue_imports = GLUE_IMPORT.findall(api)
    if len(glue_imports) != 1:
        raise ValueError("%s: expected one `import createModule from './fragsim_control_wasm.mjs'`,"
                         " found %d" % (package_dir / "fragsim.mjs", len(glue_imports)))
    if not embeddable_as_text(demo):
        raise ValueError("%s: holds </script, <!-- or a CR and cannot be inlined" % (HERE / "demo.js"))
    for marker in ("@@MODULES@@", "@@LICENCES@@", "@@DEMO@@"):
        if template.count(marker) != 1:
            raise ValueError("%s: expected %s once" % (HERE / "page.html", marker))

    modules = (module_element("module-three", three)
               + module_element("module-rapier", rapier)
               + module_element("module-fragsim", api,
                                ' data-glue-specifier="%s"' % html.escape(glue_imports[0]))
               + module_element("module-fragsim-glue", glue))
    licences = (
        licence_element("three.js %s (draws the view)" % versions["three"], "MIT", three_licence)
        + licence_element("Rapier (@dimforge/rapier3d-compat) %s (the physics)" % versions["rapier"],
                          "Apache-2.0", rapier_text, rapier_note)
        + licence_element("fragsim-control %s (the controller)" % versions["fragsim"], "MIT",
                          fragsim_licence))
    # One pass over the template, so that no inserted text is searched for a marker.
    parts = {"MODULES": modules, "LICENCES": licences, "DEMO": demo}
    page = re.sub(r"@@(MODULES|LICENCES|DEMO)@@", lambda m: parts[m.group(1)].rstrip("\n"),
                  template)
    out_dir.mkdir(parents=True, exist_ok=True)
    out = out_dir / "index.html"
    out.write_text(page, encoding="utf-8")
    return out, versions


def main(argv):
    if len(argv) != 4:
        print("usage: build_page.py PACKAGE_DIR NPM_PREFIX OUT_DIR", file=sys.stderr)
        return 2
    package_dir, npm_prefix, out_dir = (pathlib.Path(a).resolve() for a in argv[1:])
    try:
        out, versions = build(package_dir, npm_prefix, out_dir)
    except MissingInput as e:
        print("build_page: missing input: %s" % e, file=sys.stderr)
        return 1
    except ValueError as e:
        print("build_page: %s" % e, file=sys.stderr)
        return 1
    print("build_page: %s (%.1f MB; three.js %s, Rapier %s, fragsim-control %s)" % (
        out, out.stat().st_size / 1e6, versions["three"], versions["rapier"], versions["fragsim"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
