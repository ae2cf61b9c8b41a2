#!/usr/bin/env python3
"""The editor's include graph by layer (issue 31): every `#include "core/..."`, `"ui/..."` in ui/ and
app/editor, counted per pair of layers, printed as a Mermaid graph (docs/architecture.md shows it)
with the number of includes on each arrow. Layers, bottom to top:

    core < scale, probe, audio < session < render < widgets < panels < window < app/editor

(scale: ui/UiScale.h, the interface's content scale, a constant every drawing layer reads.)

Exits 1, naming each file and include, when an arrow points up (a layer including one above it) or
sideways (between scale, probe and audio); scripts/check-ui-layering.cmake is the ctest that enforces the
finer per-layer rules.

    python3 scripts/ui-include-graph.py <source tree>
"""
import collections
import pathlib
import re
import sys

RANK = {"core": 0, "scale": 1, "probe": 1, "audio": 1, "session": 2, "render": 3, "widgets": 4, "panels": 5,
        "window": 6, "app/editor": 7}
INCLUDE = re.compile(r'^\s*#\s*include\s+"((?:core|ui)/[^"]+)"')


def layer_of(relative):
    """The layer a path of the tree (or an include) belongs to."""
    parts = relative.split("/")
    if parts[0] == "core":
        return "core"
    if parts[0] == "app":
        return "app/editor"
    if relative == "ui/UiScale.h":
        return "scale"
    if len(parts) > 2 and parts[1] in RANK:
        return parts[1]
    return "window"  # ui/*.h, ui/*.cpp: the frame loop, views, menus (ui/UiScale.h: a constant)


def main(root):
    root = pathlib.Path(root)
    edges = collections.Counter()
    upward = []
    files = sorted(list((root / "ui").rglob("*.[hc]*")) + list((root / "app/editor").rglob("*.[hc]*")))
    for path in files:
        relative = path.relative_to(root).as_posix()
        source = layer_of(relative)
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            target = layer_of(match.group(1))
            if target == source:
                continue
            edges[(source, target)] += 1
            if RANK[target] >= RANK[source]:
                upward.append(f"{relative}:{number}: {source} includes {match.group(1)} ({target})")
    print("```mermaid")
    print("graph BT")
    for (source, target), count in sorted(edges.items(), key=lambda e: (-RANK[e[0][0]], e[0])):
        print(f'  {source.replace("/", "_")}["{source}"] -->|{count}| {target.replace("/", "_")}["{target}"]')
    print("```")
    for line in upward:
        print(line, file=sys.stderr)
    return 1 if upward else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
