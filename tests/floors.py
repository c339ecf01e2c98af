#!/usr/bin/env python3
"""The floors of lib/ (lib/README.md "The house"): every include keeps their order.

A library folder may include only itself and the folders below it in FLOORS; inside
gears/ a room may include only itself and the rooms before it in ROOMS. The numerics
(core, hb, fe, gears) never print, write files or read JSON. The CMake links of the
targets (lib/CMakeLists.txt) must allow no more than FLOORS does. Every module (header)
of lib/ is named in lib/README.md's table, so the drawing shows the whole house. Exit 1
listing each broken rule; 0 otherwise.

usage: floors.py SOURCE_DIR
"""
import pathlib
import re
import sys

# folder -> the folders it may include (besides itself)
FLOORS = {
    "core": set(),
    "hb": {"core"},
    "fe": {"core"},
    "gears": {"core", "hb", "fe"},
    "experiments": {"core", "hb"},
    "app": {"core", "hb"},
    "tools": {"core", "hb", "fe", "gears", "app"},
}
ROOMS = ["geometry", "tooth", "rating", "pair", "dynamics", "sets"]   # gears/, lowest first
NUMERICS = {"core", "hb", "fe", "gears"}
SPEAKING = re.compile(r"std::(cout|cerr|clog|ofstream|fstream)\b|\bprintf\s*\(|\bfopen\s*\(|nlohmann")
INCLUDE = re.compile(r'^\s*#\s*include\s+"gearhb/([a-z_]+)/(?:([a-z_]+)/)?[a-z0-9_]+\.hpp"', re.M)


def check_sources(lib):
    broken = []
    for path in sorted(lib.rglob("*.[ch]pp")):
        rel = path.relative_to(lib)
        floor = rel.parts[0]
        room = rel.parts[1] if floor == "gears" and len(rel.parts) > 2 else None
        if floor not in FLOORS:
            broken.append(f"{rel}: folder '{floor}' is no floor of lib/ (tests/floors.py FLOORS)")
            continue
        if floor == "gears" and room not in ROOMS:
            broken.append(f"{rel}: gears/ holds its models in rooms {ROOMS}")
        text = path.read_text()
        for m in INCLUDE.finditer(text):
            inc_floor, inc_room = m.group(1), m.group(2)
            if inc_floor != floor and inc_floor not in FLOORS[floor]:
                broken.append(f"{rel}: {floor}/ includes {inc_floor}/ ({m.group(0).strip()})")
            if floor == "gears" and inc_floor == "gears" and room in ROOMS:
                if inc_room not in ROOMS or ROOMS.index(inc_room) > ROOMS.index(room):
                    broken.append(f"{rel}: gears/{room} includes gears/{inc_room}")
        if floor in NUMERICS:
            code = re.sub(r"//.*", "", text)
            for m in SPEAKING.finditer(code):
                broken.append(f"{rel}: numerics speak ({m.group(0)})")
    return broken


def check_links(cmake):
    broken = []
    for target, deps in re.findall(r"target_link_libraries\(gearhb_([a-z]+)\s+PUBLIC([^)]*)\)", cmake.read_text()):
        for dep in re.findall(r"gearhb_([a-z]+)", deps.split("PRIVATE")[0]):
            if target in FLOORS and dep not in FLOORS[target]:
                broken.append(f"lib/CMakeLists.txt: gearhb_{target} links gearhb_{dep}")
    return broken


def check_drawn(lib, readme):
    """Every header's module name appears in lib/README.md's table (its rows start with |) as `name`."""
    text = "\n".join(line for line in readme.read_text().splitlines() if line.startswith("|"))
    return [f"{p.relative_to(lib)}: module `{p.stem}` is not in lib/README.md's table"
            for p in sorted(lib.rglob("*.hpp")) if f"`{p.stem}`" not in text]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    root = pathlib.Path(sys.argv[1])
    lib = root / "lib" / "gearhb"
    broken = (check_sources(lib) + check_links(root / "lib" / "CMakeLists.txt") +
              check_drawn(lib, root / "lib" / "README.md"))
    for b in broken:
        print(b)
    print(f"floors.py: {len(broken)} broken rule(s)")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
