# Sphinx configuration of the EOIR engine's manual (docs/README.md says how to build it).
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "_ext"))

project = "EOIR engine"
author = "the EOIR engine's authors"
copyright = "the EOIR engine's authors, Apache License 2.0"
# The one version: the CMake project's (tests/version/check_versions.py).
with open(os.path.join(os.path.dirname(__file__), "..", "CMakeLists.txt")) as cmake_lists:
    release = re.search(r"^project\(eoir VERSION ([0-9.]+)", cmake_lists.read(), re.M).group(1)
version = release

extensions = ["myst_parser", "breathe", "eoir_docs"]
myst_enable_extensions = ["colon_fence"]
myst_heading_anchors = 3
source_suffix = {".md": "markdown"}
root_doc = "index"
# docs/pending holds notes other branches drop for merging into these pages;
# tutorials/out holds what the tutorials write when run by hand.
exclude_patterns = ["_build", "pending", "tutorials/out", "tools"]
nitpicky = True
html_theme = "alabaster"
html_theme_options = {"description": "headless EO/IR scene generator and sensor model", "fixed_sidebar": True}
html_static_path = []
html_show_sourcelink = False

# The C ABI through Doxygen's XML (run by eoir_docs at the start of the build).
breathe_projects = {"eoir": os.environ.get("EOIR_DOXYGEN_XML", os.path.join(os.path.dirname(__file__), "_build", "doxygen", "xml"))}
breathe_default_project = "eoir"
breathe_domain_by_extension = {"h": "c"}
breathe_show_define_initializer = True
breathe_show_include = False

# The C standard library's types are not ours to document.
nitpick_ignore = [("c:identifier", t) for t in ("int8_t", "uint8_t", "int16_t", "uint16_t", "int32_t", "uint32_t",
                                                "int64_t", "uint64_t", "size_t", "FILE")]
nitpick_ignore.append(("c:identifier", "eoir_engine_s"))  # opaque: only its handle is public
