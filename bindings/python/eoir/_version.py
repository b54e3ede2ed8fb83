"""The version of the eoir package, the engine's one version.

Written by CMake from project(eoir VERSION ...) in the top-level
CMakeLists.txt (the number to bump) through eoir/_version.py.in; do not edit
eoir/_version.py by hand.
"""

__version__ = "1.7.0"
