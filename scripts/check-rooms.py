#!/usr/bin/env python3
"""Checks the house's floors: every quoted #include stays in its room or goes down to a room the
room's README allows ("May include: ..."), no include climbs with "..", and the allowed rooms
form no cycle (no two rooms include each other, directly or around a loop); an arm's place in a
PerArm is raven::slot(arm), never an index cast by hand; every room's README lists each of its
source files (a table row's first column: names, `name.*` or `adf_*_reader.cpp`) and lists none
that is not there; and the README stays a door (at most README_LINES lines: topics go to docs/).

  scripts/check-rooms.py [--graph] [--root DIR]
      --graph prints the includes as found, room by room; --root checks another tree (a test's
      small house: rooms it has no folder for are left out)
Exit status 1 with one line per breach, naming file and line."""

import fnmatch
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# Code rooms, each a folder with a README.md. A file belongs to the deepest room holding it.
ROOMS = [
    "common", "harness", "ambf_like", "ambf_like/model", "ambf_like/loading", "ambf_like/dynamics",
    "ambf_like/world", "ambf_like_cli", "raven_description", "bridge", "bridge/ros", "twin",
    "twin/ros", "recording", "controller", "analysis", "calibration", "viewer", "scenario",
    "study", "python", "bench", "tests", "fuzz",
]
# Include prefixes of rooms whose public headers sit under <room>/include/<prefix>.
PREFIXES = {
    "common/": "common", "harness/": "harness", "ambf_like/dynamics/": "ambf_like/dynamics",
    "raven/": "raven_description", "bridge/ros/": "bridge/ros", "bridge/": "bridge",
    "twin/ros/": "twin/ros", "twin/": "twin", "recording/": "recording",
    "controller/": "controller", "analysis/": "analysis", "calibration/": "calibration",
    "viewer/": "viewer", "scenario/": "scenario", "study/": "study",
}
README_LINES = 200
ENGINE_STAGES = ["ambf_like/model", "ambf_like/loading", "ambf_like/world"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
MAY_INCLUDE = re.compile(r"^May include:\s*(.*)$", re.MULTILINE)
FILE_ROW = re.compile(r"^\|([^|]*)\|", re.MULTILINE)
SOURCE_SUFFIXES = (".hpp", ".cpp", ".h", ".py")
# An arm's place in a PerArm cast by hand, or the other arm's place counted by hand.
HAND_CAST_SLOT = re.compile(r"static_cast<std::size_t>\(\s*(1\s*-\s*)?(raven::)?index\("
                            r"|\b1\s*-\s*(raven::)?slot\(")


def room_of_file(path):
    rel = path.relative_to(ROOT).as_posix()
    owners = [room for room in ROOMS if rel.startswith(room + "/")]
    return max(owners, key=len) if owners else None


def room_of_include(target):
    """The room an include names, or None for a room's own (unprefixed) file."""
    if target.startswith("ambf_like/") and not target.startswith("ambf_like/dynamics/"):
        for stage in ENGINE_STAGES:
            if (ROOT / stage / "include" / target).exists():
                return stage
        return "ambf_like"
    for prefix in sorted(PREFIXES, key=len, reverse=True):
        if target.startswith(prefix):
            return PREFIXES[prefix]
    return None


def allowed_rooms(room, problems):
    readme = ROOT / room / "README.md"
    if not readme.exists():
        problems.append(f"{room}/: no README.md (each room says what it is for and may include)")
        return set()
    match = MAY_INCLUDE.search(readme.read_text())
    if not match:
        problems.append(f"{room}/README.md: no 'May include:' line")
        return set()
    text = match.group(1).strip().rstrip(".")
    if text.startswith("nothing"):
        return set()
    if text.startswith("any room"):
        return {"*"}
    return {name.strip().strip("`") for name in text.split(",") if name.strip()}


def listed_names(room):
    """The file names and patterns in the first column of the room README's tables."""
    names = []
    readme = ROOT / room / "README.md"
    for cell in FILE_ROW.findall(readme.read_text() if readme.exists() else ""):
        names += [Path(n).name for n in re.findall(r"`([^`\s]+)`", cell) if not n.endswith("/")]
    return names


def lists(name, path):
    """True when the README entry `name` names `path`: its file name; its stem when the entry has
    no suffix (`run_watcher`); a header's entry names its source too."""
    if fnmatch.fnmatch(path.name, name) or ("." not in name and path.stem == name):
        return True
    return path.suffix == ".cpp" and Path(name).suffix in (".hpp", ".h") and \
        fnmatch.fnmatch(path.stem, Path(name).stem)


def check_listings(sources, problems):
    by_room = {}
    for path in sources:
        room = room_of_file(path)
        if room not in (None, "tests", "fuzz") and path.suffix in SOURCE_SUFFIXES:
            by_room.setdefault(room, []).append(path)
    for room, paths in sorted(by_room.items()):
        names = listed_names(room)
        for path in paths:
            if not any(lists(name, path) for name in names):
                problems.append(f"{path.relative_to(ROOT)}: not listed in {room}/README.md")
        for name in names:
            if Path(name).suffix in SOURCE_SUFFIXES + (".*",) and \
                    not any(lists(name, path) for path in paths):
                problems.append(f"{room}/README.md: lists `{name}`, which is not in the room")


def find_cycle(graph):
    """A loop of rooms (its first room repeated at the end), or None. Depth first: a room met
    again while still on the path closes a loop."""
    done = set()

    def visit(path):
        for nxt in sorted(graph.get(path[-1], ())):
            if nxt in path:
                return path[path.index(nxt):] + [nxt]
            if nxt not in done:
                found = visit(path + [nxt])
                if found:
                    return found
        done.add(path[-1])
        return None

    for node in sorted(graph):
        if node not in done:
            found = visit([node])
            if found:
                return found
    return None


def main():
    global ROOT, ROOMS
    if "--root" in sys.argv:
        ROOT = Path(sys.argv[sys.argv.index("--root") + 1]).resolve()
        ROOMS = [room for room in ROOMS if (ROOT / room).is_dir()]
    problems = []
    declared = {room: allowed_rooms(room, problems) for room in ROOMS}
    found = {room: set() for room in ROOMS}
    sources = [p for p in ROOT.rglob("*") if p.suffix in SOURCE_SUFFIXES
               and not any(part.startswith("build") or part.startswith(".") for part in
                           p.relative_to(ROOT).parts)]
    for path in sorted(sources):
        room = room_of_file(path)
        if room is None:
            continue
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            if HAND_CAST_SLOT.search(line):
                problems.append(f"{path.relative_to(ROOT)}:{number}: an arm's place cast by hand: "
                                "raven::slot(arm) (or slot(raven::other(arm)))")
            match = INCLUDE.match(line)
            if not match:
                continue
            target = match.group(1)
            where = f"{path.relative_to(ROOT)}:{number}"
            if ".." in Path(target).parts:
                problems.append(f'{where}: "{target}" climbs a floor with ".."')
                continue
            other = room_of_include(target)
            if other is None or other == room:
                continue
            found[room].add(other)
            allowed = declared[room]
            if "*" not in allowed and other not in allowed:
                problems.append(f'{where}: {room} includes "{target}" of {other}, which '
                                f"{room}/README.md does not allow")
    check_listings(sources, problems)
    for room, allowed in declared.items():
        for name in allowed - {"*"}:
            if name not in ROOMS:
                problems.append(f"{room}/README.md: may include '{name}', which is no room")
            elif name not in found[room]:
                problems.append(f"{room}/README.md: allows {name}, which it does not include")
    lines = len((ROOT / "README.md").read_text().splitlines())
    if lines > README_LINES:
        problems.append(f"README.md: {lines} lines, more than {README_LINES} (a door: quick start, "
                        "rooms, links; topics go to docs/)")
    cycle = find_cycle(found)
    if cycle:
        problems.append("rooms include each other: " + " -> ".join(cycle))
    if "--graph" in sys.argv:
        for room in ROOMS:
            print(f"{room}: {', '.join(sorted(found[room])) or 'nothing'}")
    for problem in problems:
        print(problem)
    if not problems:
        print(f"rooms: {len(ROOMS)} rooms, {len(sources)} files, every include goes down")
    return 1 if problems else 0

if __name__ == "__main__":
    sys.exit(main())
