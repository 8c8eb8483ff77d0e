# Sphinx configuration of the documentation site (make docs; tests/docs/build_site.py).
# The pages are the Markdown files of docs/, read by MyST; the reference pages (the command line,
# the identification methods, Python, C++) are generated into the build's copy of docs/ by
# tests/docs/build_site.py, which also runs Doxygen for the C++ reference (cpp/ beside the pages).
# No network: no intersphinx.
project = "frictionlab"
author = "the frictionlab authors"
extensions = ["myst_parser"]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build"]
# Headings become link targets (#the-axis-as-a-mujoco-model) the way GitHub makes them, so the
# pages' links work on GitHub and on the site alike.
myst_heading_anchors = 4
highlight_language = "none"
html_theme = "alabaster"
html_title = "frictionlab"
html_theme_options = {"nosidebar": False}
html_static_path = []
