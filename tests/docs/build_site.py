#!/usr/bin/env python3
"""Builds the documentation site (Sphinx + MyST, Breathe over Doxygen) with warnings as errors.

Usage: build_site.py SOURCE_DIR BUILD_DIR [OUT_DIR]
  SOURCE_DIR  the checkout (its docs/ and include/frictionlab/)
  BUILD_DIR   a build tree with app/frictionlab and python/frictionlab (for the generated pages)
  OUT_DIR     where the HTML goes (default BUILD_DIR/docs/html)

docs/ is copied to BUILD_DIR/docs/src and the reference pages are generated beside the copy:
  reference/cli.md         every command's --help, from the built tool
  reference/methods.md     one page per identification method, from `frictionlab help --markdown`
  reference/python-api.md  the Python package, from its docstrings (autodoc of the built module)
  reference/cpp-api.md     the public headers, one section per layer, linking Doxygen's pages (cpp/)
Every warning fails the build except the known third-party ones of KNOWN_WARNINGS, each with the
reason it is not ours; a page of docs/ that is not in a table of contents is such a warning.
Exit status 0 when the site was built without other warnings, 1 otherwise.
"""
import json
import os
import re
import shutil
import subprocess
import sys

# Warnings of the tools themselves, not of our pages, matched by their text.
# None yet: Sphinx 5.3 and MyST 0.18 of Debian 12 build these pages without a warning of their own.
# An entry is a name and a regular expression, with a comment saying why the warning is not ours.
KNOWN_WARNINGS = {}


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, text=True, capture_output=True, **kw).stdout


def help_tree(exe, path=()):
    """Each command path with its --help text, depth first (CLI11's SUBCOMMANDS sections)."""
    text = run([exe, *path, "--help"])
    out = [(path, text)]
    subs = []
    in_subs = False
    for line in text.splitlines():
        if line.strip().upper().startswith("SUBCOMMANDS"):
            in_subs = True
            continue
        if in_subs:
            m = re.match(r"^  (\S+)", line)
            if m:
                subs.append(m.group(1))
            elif line.strip() and not line.startswith("  "):
                in_subs = False
    for s in subs:
        if s == "help":
            out.append(((*path, s), run([exe, *path, s, "--help"])))
        else:
            out += help_tree(exe, (*path, s))
    return out


def cli_page(exe):
    lines = ["# Command-line reference", "",
             "Every command's `--help`, as the built `frictionlab` prints it (generated; the options of the",
             "identification methods with units and defaults are also in [the methods' reference](methods.md)).", ""]
    for path, text in help_tree(exe):
        title = " ".join(("frictionlab", *path))
        lines += [f"## {title}", "", "```text", text.rstrip(), "```", ""]
    return "\n".join(lines)


def methods_pages(exe, out_dir):
    """One page per method from `frictionlab help --markdown`, and their index."""
    text = run([exe, "help", "--markdown"])
    parts = re.split(r"^## ", text, flags=re.M)
    intro, sections = parts[0], parts[1:]
    intro_body = "\n".join(l for l in intro.splitlines() if not l.startswith("# ")).strip()
    names = []
    os.makedirs(os.path.join(out_dir, "methods"), exist_ok=True)
    for sec in sections:
        name = sec.splitlines()[0].strip()
        names.append(name)
        body = sec[len(sec.splitlines()[0]):].strip()
        cmd = "frictionlab validate" if name == "validate" else f"frictionlab identify {name}"
        with open(os.path.join(out_dir, "methods", f"{name}.md"), "w", encoding="utf-8") as f:
            f.write(f"# {name}\n\n`{cmd}`; in Python, the keywords of the Python column.\n\n{body}\n")
    index = ["# Identification methods", "", intro_body, "", "```{toctree}", ":maxdepth: 1", ""]
    index += [f"methods/{n}" for n in names] + ["```", ""]
    with open(os.path.join(out_dir, "methods.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(index))


PYTHON_DUMP = r"""
import inspect, json, sys
import frictionlab as fl
names = getattr(fl, "__all__", None) or [n for n in dir(fl) if not n.startswith("_")]
out = []
for name in sorted(set(names)):
    obj = getattr(fl, name, None)
    if inspect.ismodule(obj) or obj is None:
        continue
    doc = inspect.getdoc(obj) or ""
    if inspect.isclass(obj):
        members = []
        for m, v in sorted(vars(obj).items()):
            if m.startswith("_") and m not in ("__init__", "__repr__"):
                continue
            d = inspect.getdoc(v) or ""
            if m in ("__init__", "__repr__") and not d:
                continue
            members.append((m, d))
        out.append({"name": name, "kind": "class", "doc": doc, "members": members})
    elif callable(obj):
        try:
            sig = name + str(inspect.signature(obj))
        except (TypeError, ValueError):
            sig = ""
        out.append({"name": name, "kind": "function", "sig": sig, "doc": doc})
json.dump(out, sys.stdout)
"""


def python_page(build):
    """The package's public names with their docstrings, as the built module has them.

    The docstrings are plain text with units and shapes (not reStructuredText), so they are shown
    as text blocks, not read by autodoc."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.path.join(build, "python") + os.pathsep + env.get("PYTHONPATH", "")
    items = json.loads(run([sys.executable, "-c", PYTHON_DUMP], env=env))
    fence = "`" * 3
    lines = ["# Python reference", "",
             "The public names of the `frictionlab` package (`import frictionlab as fl`) with their",
             "docstrings, from the built module (generated). The keyword options of each identification",
             "method are in [the methods' reference](methods.md); [Python](../python.md) shows it at work.", ""]
    for kind, title in (("function", "Functions"), ("class", "Classes")):
        lines += [f"## {title}", ""]
        for it in (i for i in items if i["kind"] == kind):
            lines += [f"### {it['name']}", ""]
            if it.get("sig") and not it["doc"].startswith(it["name"] + "("):  # pybind11 starts with it
                lines += [fence + "text", it["sig"], fence, ""]
            if it["doc"]:
                lines += [fence + "text", it["doc"].replace(fence, "'''"), fence, ""]
            members = it.get("members", [])
            for m, d in members:
                lines.append(f"- `{m}`" + (f": {d.splitlines()[0]}" if d else ""))
            if members:
                lines.append("")
    return "\n".join(lines)


def header_summary(path):
    """The first sentence of a header's opening comment (its first // lines up to a blank one)."""
    words = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#pragma"):
                continue
            if not line.startswith("//") or not line[2:].strip():
                break
            words.append(line[2:].strip())
    text = " ".join(words)
    m = re.match(r"(.+?[.:;])(\s|$)", text)
    return (m.group(1) if m else text).rstrip(":;") + ("" if not text or text.endswith(".") else "")


def cpp_page(src, pages):
    """The public headers, one section per layer, each with its opening comment and a link to its
    Doxygen page (cpp/ beside the site's pages)."""
    inc = os.path.join(src, "include", "frictionlab")
    lines = ["# C++ API", "",
             "The public headers of `include/frictionlab/` (`#include \"frictionlab/...\"`, CMake target",
             "`frictionlab::frictionlab`), one section per layer; [architecture](../architecture.md) says what each",
             "layer may use. Each header's classes and functions, with the units, shapes and exceptions their",
             'comments give, are on its page of <a href="../cpp/files.html">the Doxygen reference</a> (generated).', ""]
    layers = {}
    for folder, _, names in os.walk(inc):
        for n in sorted(names):
            if n.endswith(".hpp"):
                rel = os.path.relpath(os.path.join(folder, n), inc).replace(os.sep, "/")
                layer = rel.split("/")[0] if "/" in rel else "(root)"
                layers.setdefault(layer, []).append(rel)
    for layer in sorted(layers):
        lines += [f"## {layer}", ""]
        for rel in sorted(layers[layer]):
            page = pages.get("frictionlab/" + rel)
            if page is None:
                raise SystemExit(f"FAIL docs site: Doxygen made no page for include/frictionlab/{rel}")
            summary = header_summary(os.path.join(inc, rel)).replace("<", "&lt;")
            lines.append(f'- <a href="../cpp/{page}"><code>frictionlab/{rel}</code></a>' + (f": {summary}" if summary else ""))
        lines.append("")
    return "\n".join(lines)


def doxygen_file_pages(cpp):
    """{"frictionlab/identify/lugre.hpp": its Doxygen page} from the pages' titles (Doxygen names a
    page by the header's base name, with the folders only where two headers share it)."""
    pages = {}
    for n in os.listdir(cpp):
        if n.endswith("_8hpp.html"):
            m = re.search(r"<title>[^<]*?(frictionlab/\S+\.hpp) File Reference", open(os.path.join(cpp, n), encoding="utf-8").read())
            if m:
                pages[m.group(1)] = n
    return pages


def doxygen(src, out):
    """The C++ reference as Doxygen HTML in OUT (its own warnings are not checked: the headers'
    comments are written for readers of the headers, not in Doxygen's markup)."""
    os.makedirs(out, exist_ok=True)
    conf = "\n".join([
        "PROJECT_NAME = frictionlab",
        f"INPUT = {os.path.join(src, 'include')}",
        "RECURSIVE = YES", "FILE_PATTERNS = *.hpp",
        f"STRIP_FROM_PATH = {os.path.join(src, 'include')}",
        f"STRIP_FROM_INC_PATH = {os.path.join(src, 'include')}",
        "FULL_PATH_NAMES = YES",
        f"HTML_OUTPUT = {out}", f"OUTPUT_DIRECTORY = {out}",
        "GENERATE_XML = NO", "GENERATE_HTML = YES", "GENERATE_LATEX = NO", "SEARCHENGINE = NO",
        "EXTRACT_ALL = YES", "QUIET = YES", "WARNINGS = NO", "HAVE_DOT = NO",
        "ENABLE_PREPROCESSING = YES", "MACRO_EXPANSION = YES", "EXPAND_ONLY_PREDEF = YES",
        "PREDEFINED = FRICTIONLAB_API=", "EXCLUDE_SYMBOLS = detail internal",
    ])
    subprocess.run(["doxygen", "-"], input=conf, text=True, check=True, capture_output=True)


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    src, build = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    out = os.path.abspath(sys.argv[3]) if len(sys.argv) > 3 else os.path.join(build, "docs", "html")
    exe = os.path.join(build, "app", "frictionlab")
    try:
        import myst_parser  # noqa: F401
        import sphinx  # noqa: F401
    except ImportError as e:
        print(f"FAIL docs site: {e.name} is not installed: run scripts/setup.sh (python3-sphinx, python3-myst-parser, doxygen)")
        return 1
    if shutil.which("doxygen") is None:
        print("FAIL docs site: doxygen is not installed: run scripts/setup.sh (Debian package doxygen)")
        return 1
    work = os.path.join(build, "docs")
    page_src = os.path.join(work, "src")
    shutil.rmtree(page_src, ignore_errors=True)
    shutil.copytree(os.path.join(src, "docs"), page_src)
    ref = os.path.join(page_src, "reference")
    os.makedirs(ref, exist_ok=True)
    with open(os.path.join(ref, "cli.md"), "w", encoding="utf-8") as f:
        f.write(cli_page(exe))
    methods_pages(exe, ref)
    with open(os.path.join(ref, "python-api.md"), "w", encoding="utf-8") as f:
        f.write(python_page(build))
    doxygen(src, os.path.join(out, "cpp"))
    with open(os.path.join(ref, "cpp-api.md"), "w", encoding="utf-8") as f:
        f.write(cpp_page(src, doxygen_file_pages(os.path.join(out, "cpp"))))
    env = dict(os.environ)
    log = os.path.join(work, "warnings.txt")
    proc = subprocess.run([sys.executable, "-m", "sphinx", "-b", "html", "-q", "-E", "-j", "1", "-w", log,
                           page_src, out], env=env, text=True, capture_output=True)
    # A warning is its first line (PATH:LINE: WARNING: ...) and the indented lines that follow it.
    records = []
    for line in (open(log, encoding="utf-8").read().splitlines() if os.path.exists(log) else []):
        if re.search(r"(WARNING|ERROR|CRITICAL|SEVERE):", line) or not records:
            records.append(line)
        else:
            records[-1] += "\n" + line
    ours, known = [], {}
    for w in records:
        if not w.strip():
            continue
        name = next((n for n, rx in KNOWN_WARNINGS.items() if rx.search(w)), None)
        if name:
            known[name] = known.get(name, 0) + 1
        else:
            ours.append(w)
    for name, count in sorted(known.items()):
        print(f"filtered {count} known warning(s): {name}")
    if proc.returncode != 0 and not ours:
        ours.append(f"sphinx-build exited {proc.returncode}: {proc.stderr.strip()[-2000:]}")
    for w in ours:
        print(w)
    if ours:
        print(f"FAIL docs site: {len(ours)} warning(s) (full log: {log})")
        return 1
    pages = sum(1 for _, _, ns in os.walk(out) for n in ns if n.endswith(".html"))
    print(f"PASS docs site: {pages} HTML pages in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
