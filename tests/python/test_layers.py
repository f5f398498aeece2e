"""The module layers of src/tangle point only down (docs/architecture.md).

Every `#include "tangle/<module>/..."` in a module's sources must name the module itself or a module of a
lower layer in LAYERS. A new module must be placed in LAYERS (the test fails on an unknown module), and an
include that points up or sideways within a layer fails with the file, the line and the two modules.
"""

import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2] / "src" / "tangle"

# Lowest first; modules in one tuple are peers and may not include each other.
LAYERS = [
    ("core",),
    ("geometry", "element", "section", "seabed", "catenary"),
    ("model",),
    ("solver",),
    ("hydro", "contact", "time"),
    ("vessel",),
    ("analysis",),
    ("io",),
    ("results",),
    ("app", "python", "capi"),
]

INCLUDE = re.compile(r'^\s*#\s*include\s+"tangle/(\w+)/')


def layer_of(module):
    for level, modules in enumerate(LAYERS):
        if module in modules:
            return level
    raise AssertionError(f"module '{module}' is not in LAYERS of {__file__}: place it in a layer")


def test_every_module_has_a_layer():
    for folder in sorted(p for p in ROOT.iterdir() if p.is_dir()):
        layer_of(folder.name)


def test_includes_point_down():
    offences = []
    for source in sorted(ROOT.rglob("*.[ch]pp")):
        module = source.relative_to(ROOT).parts[0]
        level = layer_of(module)
        for number, line in enumerate(source.read_text().splitlines(), start=1):
            match = INCLUDE.match(line)
            if not match or match.group(1) == module:
                continue
            if layer_of(match.group(1)) >= level:
                offences.append(f"{source.relative_to(ROOT.parent.parent)}:{number}: {module} includes "
                                f"{match.group(1)} (layer {layer_of(match.group(1))} >= {level})")
    assert not offences, "includes that point up or sideways:\n" + "\n".join(offences)


def test_the_rule_catches_an_upward_include(tmp_path):
    # Test the test: the pattern recognises an include, and an upward one is ranked as such.
    assert INCLUDE.match('#include "tangle/io/HtmlReport.hpp"').group(1) == "io"
    assert layer_of("io") > layer_of("contact")
