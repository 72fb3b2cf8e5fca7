#!/usr/bin/env python3
"""Writes a raven_bench run into the pages: every row into docs/benchmarks.md (between its
bench:begin / bench:end markers), the rows with a target into README.md (bench-headline:begin /
end), under a line saying when and where they were measured. Sections left out of the run
(raven_bench --only) keep their rows from earlier runs, each group under its own such line (rows
measured the same day on the same machine as this run join its table).

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
    """(caption, rows) for each table of a block: each table follows its "Measured" line (read
    without the suffix a kept table's line carries)."""
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

    page, readme = f"{root}/docs/benchmarks.md", f"{root}/README.md"
    texts = {path: open(path).read() for path in (page, readme)}
    # Both pages' markers are checked before either page is written.
    spans = {page: between(texts[page], "bench", page),
             readme: between(texts[readme], "bench-headline", readme)}
    start, stop = spans[page]
    # Kept rows under a line the same as this run's (same day, same machine) join its table; kept
    # rows under one older line share one table.
    tables = {caption: list(fresh)}
    for old_caption, rows in groups(texts[page][start:stop]):
        tables.setdefault(old_caption, []).extend(row for row in rows if section(row) not in run)
    fresh = tables.pop(caption)
    older = [(old_caption, rows) for old_caption, rows in tables.items() if rows]

    def block():
        """Every table under its own line (docs/benchmarks.md)."""
        tables = [(caption, fresh)] + [(c + KEPT, rows) for c, rows in older]
        return "\n\n".join("\n".join([c, "", *header, *rows]) for c, rows in tables)

    def headline():
        """One table of the rows with a target, the older ones' line under it (README.md)."""
        targets = [(c, kept) for c, rows in older if (kept := [r for r in rows if has_target(r)])]
        rows = [r for r in fresh if has_target(r)] + [r for _, kept in targets for r in kept]
        notes = [f"- Rows of {', '.join(sorted({section(r) for r in kept}))}: "
                 + c.replace("Measured", "measured", 1) for c, kept in targets]
        return "\n".join([caption, "", *header, *rows] + (["", *notes] if notes else []))

    for path, write in ((page, block), (readme, headline)):
        start, stop = spans[path]
        open(path, "w").write(texts[path][:start] + write() + "\n" + texts[path][stop:])
    kept = sorted({section(r) for _, rows in older for r in rows})
    print(f"docs/benchmarks.md and README.md: results of {m['date']} written"
          + (f"; earlier rows kept for {', '.join(kept)}" if kept else ""))


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
