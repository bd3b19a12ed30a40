"""Sphinx configuration of polyccd's reference (`make docs`: warnings are errors).

The Python reference comes from the package's docstrings (autodoc, importing the built
package of the checkout's .venv); the C reference from include/polyccd.h's comments
(_ext/c_header.py); the other pages are the Markdown files of docs/ (MyST)."""
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "_ext"))

project = "polyccd"
author = "the polyccd authors"
copyright = "2026, the polyccd authors"
extensions = ["sphinx.ext.autodoc", "myst_parser", "c_header"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
exclude_patterns = ["_build"]
root_doc = "index"
html_theme = "alabaster"
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False}
myst_heading_anchors = 3
# Links from the Markdown pages to files of the repository outside docs/ (sources, the
# corpus) are not documents: MyST leaves them as plain links.
suppress_warnings = ["myst.xref_missing"]
