#!/usr/bin/env python3
"""Every relative link of README.md, CHANGELOG.md and docs/*.md points at a file of the checkout.

Links to the web are not followed (there is no network in the tests); a link to a heading of
another page ("page.md#heading") must name a heading that page has. Usage:
    check_links.py [SOURCE_DIR]
"""
import os
import re
import sys

LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
FENCE = re.compile(r"^(```|~~~)")


def anchors(path):
    """GitHub-style anchors of a Markdown file's headings."""
    out = set()
    in_code = False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if FENCE.match(line):
                in_code = not in_code
            if in_code or not line.startswith("#"):
                continue
            title = line.lstrip("#").strip().lower()
            title = re.sub(r"[^\w\- ]", "", title).replace(" ", "-")
            out.add(title)
    return out


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
    pages = [os.path.join(root, p) for p in ("README.md", "CHANGELOG.md") if os.path.exists(os.path.join(root, p))]
    docs = os.path.join(root, "docs")
    for folder, _, names in os.walk(docs):
        pages += [os.path.join(folder, n) for n in sorted(names) if n.endswith(".md")]
    problems = []
    links = 0
    for page in pages:
        in_code = False
        with open(page, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                if FENCE.match(line):
                    in_code = not in_code
                if in_code:
                    continue
                for target in LINK.findall(line):
                    if re.match(r"^[a-z]+:", target):
                        continue  # a web or mail address: not followed here
                    links += 1
                    file_part, _, anchor = target.partition("#")
                    dest = os.path.normpath(os.path.join(os.path.dirname(page), file_part)) if file_part else page
                    where = f"{os.path.relpath(page, root)}:{number}"
                    if not os.path.exists(dest):
                        problems.append(f"{where}: link to '{target}': no such file")
                    elif anchor and dest.endswith(".md") and anchor not in anchors(dest):
                        problems.append(f"{where}: link to '{target}': no heading '{anchor}' there")
    for p in problems:
        print(p, file=sys.stderr)
    print(f"check_links: {len(pages)} pages, {links} relative links, {len(problems)} broken")
    return 1 if problems or not pages else 0


if __name__ == "__main__":
    sys.exit(main())
