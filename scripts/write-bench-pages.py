#!/usr/bin/env python3
"""Writes a raven_bench run into the pages: every row into docs/benchmarks.md (between its
bench:begin / bench:end markers), the rows with a target into README.md (bench-headline:begin /
end), under a line saying when and where they were measured. Sections left out of the run
(raven_bench --only) keep their rows from earlier runs, each group under its own such line.

    write-bench-pages.py ROOT RESULTS_JSON RESULTS_MARKDOWN
"""
import json
import re
import sys

KEPT = " Sections not in the run above:"


def section(row):
    return row.split("|")[1].strip()


def has_target(row):
    return bool(re.search(r"\d", row.split("|")[4]))


def groups(block):
    """(caption, rows) for each table of a block: each table follows its "Measured" line."""
    found = []
    for line in block.split("\n"):
        if line.startswith("Measured "):
            found.append((line.removesuffix(KEPT), []))
        elif line.startswith("| ") and not line.startswith("| section") and found:
            found[-1][1].append(line)
    return found


def between(text, marker, path):
    begin, end = f"<!-- {marker}:begin -->\n", f"<!-- {marker}:end -->"
    if begin not in text or end not in text:
        sys.exit(f"{path} has no {begin.strip()} / {end} markers")
    return text.index(begin) + len(begin), text.index(end)


def main(root, results, table):
    m = json.load(open(results))["machine"]
    caption = (f"Measured {m['date']} on {m['cpu']}, {m['cores']} cores, {m['kernel']}, {m['compiler']}, "
               "Release build (RAVEN_NATIVE on, the default: -march=native), with `scripts/bench.sh` "
               "(medians of 3 runs, range in brackets).")
    lines = [line for line in open(table).read().split("\n") if line.startswith("|")]
    header, fresh = lines[:2], lines[2:]
    run = {section(row) for row in fresh}

    page = f"{root}/docs/benchmarks.md"
    text = open(page).read()
    start, stop = between(text, "bench", page)
    tables = [(caption, fresh)]
    for old_caption, rows in groups(text[start:stop]):
        kept = [row for row in rows if section(row) not in run]
        if kept:
            tables.append((old_caption + KEPT, kept))

    def block():
        """Every table under its own line (docs/benchmarks.md)."""
        return "\n\n".join("\n".join([c, "", *header, *rows]) for c, rows in tables)

    def headline():
        """One table of the rows with a target, the older ones' line under it (README.md)."""
        older = [(c, [r for r in rows if has_target(r)]) for c, rows in tables[1:]]
        older = [(c, rows) for c, rows in older if rows]
        rows = [r for r in fresh if has_target(r)] + [r for _, kept in older for r in kept]
        notes = [f"- Rows of {', '.join(sorted({section(r) for r in kept}))}: "
                 + c.removesuffix(KEPT).replace("Measured", "measured", 1) for c, kept in older]
        return "\n".join([caption, "", *header, *rows] + (["", *notes] if notes else []))

    # Both pages' markers are checked before either page is written.
    readme = f"{root}/README.md"
    pages = [(path, open(path).read(), marker, write) for path, marker, write in
             ((page, "bench", block), (readme, "bench-headline", headline))]
    edits = [(path, text, between(text, marker, path), write) for path, text, marker, write in pages]
    for path, text, (start, stop), write in edits:
        open(path, "w").write(text[:start] + write() + "\n" + text[stop:])
    kept = sorted({section(r) for _, rows in tables[1:] for r in rows})
    print(f"docs/benchmarks.md and README.md: results of {m['date']} written"
          + (f"; earlier rows kept for {', '.join(kept)}" if kept else ""))


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
