#!/usr/bin/env python3
"""Compares the coverage table a run of idim_coverage.py made with the one docs/coverage.md
publishes, cell by cell: the published figures are the ones the command prints.

The cases are seeded, so a cell run with the page's number of cases gives the page's row exactly;
a cell run with fewer (make test's 20 cases of the effects cell) is not comparable and is skipped,
said so. `make coverage` runs every cell and also asks that every row of the page was made;
ctest python.idim_coverage compares the rows of the fast cells it runs anyway, at no extra cost.

Usage: coverage_table.py --self-test   (ctest docs.coverage_table_checked: a changed cell, a row
                                        not on the page and a row the run did not make are refused)
"""
import re
import sys

HEADER_START = "| cell | cases | coverage of value"


def table(text):
    """(header cells, {cell name: row cells}, the line after the table) of the coverage table in
    Markdown `text` (the first table whose header starts HEADER_START). ValueError when none."""
    lines = text.split("\n")
    for i, line in enumerate(lines):
        if line.startswith(HEADER_START):
            break
    else:
        raise ValueError(f"no table whose header starts '{HEADER_START}'")
    header = [c.strip() for c in lines[i].strip().strip("|").split("|")]
    rows, j = {}, i + 2
    while j < len(lines) and lines[j].startswith("|"):
        cells = [c.strip() for c in lines[j].strip().strip("|").split("|")]
        rows[cells[0]] = cells
        j += 1
    while j < len(lines) and not lines[j].strip():
        j += 1
    return header, rows, lines[j] if j < len(lines) else ""


def compare(made, page, page_name, complete):
    """(failures, rows compared, notes) of the table `made` (idim_coverage.markdown's text)
    against the page's text `page`. A row of `made` must be on the page with the same cells; one
    whose case count differs from the page's is skipped (a note says so). `complete` (every cell
    was run): every row of the page must have been made. (The line under the page's table, the
    measurement's cell count and time, records when and where it was measured: not compared.)"""
    failures, notes, compared = [], [], 0
    try:
        header, page_rows, _ = table(page)
        _, made_rows, _ = table(made)
    except ValueError as e:
        return [f"{page_name}: {e}"], 0, notes
    for name, cells in made_rows.items():
        if name not in page_rows:
            failures.append(f"{page_name}: cell '{name}': made by the run, not in the table")
            continue
        published = page_rows[name]
        if published[1] != cells[1]:
            notes.append(f"cell '{name}': {cells[1]} cases here, {published[1]} on the page: not compared")
            continue
        compared += 1
        for col, (want, got) in enumerate(zip(published, cells)):
            if want != got:
                failures.append(f"{page_name}: cell '{name}', column '{header[col]}':\n"
                                f"-   {want}\n+   {got}")
        if len(published) != len(cells):
            failures.append(f"{page_name}: cell '{name}': {len(published)} columns on the page, {len(cells)} made")
    if complete:
        for name in page_rows:
            if name not in made_rows:
                failures.append(f"{page_name}: cell '{name}': in the table, not made by the run")
    return failures, compared, notes


def self_test():
    head = (f"{HEADER_START} ± 1.96 std (std_ols), per parameter | mean bias / std | adequacy finding | "
            "bandwidth | verdict |\n|---|---|---|---|---|---|---|\n")
    a = "| cv, white, 100 Hz | 100 | M 97 (98), Fc 96 (95) | M +0.2, Fc -0.1 | 1 % | 0 | covers |\n"
    b = "| effects | 100 | M 99 (88) | M -0.1 | 0 % | 4.5 | covers |\n"
    page = "# t\n\n" + head + a + b + "\n2 cells, 100 cases each, 577 s.\n"
    problems = []

    def expect(made, complete, ok, needle=""):
        failures, _, _ = compare(made, page, "page.md", complete)
        text = "\n".join(failures)
        if ok != (not failures) or (needle and needle not in text):
            problems.append(f"made {made!r} (complete {complete}): expected {'no failure' if ok else needle!r}, "
                            f"got {text or 'none'}")

    expect(head + a, False, True)                                   # the fast rows alone
    expect(head + a + b.replace("| 100 |", "| 20 |", 1), False, True)  # fewer cases: skipped
    expect(head + a.replace("Fc 96 (95)", "Fc 95 (95)"), False, False,
           "cell 'cv, white, 100 Hz', column 'coverage of value ± 1.96 std (std_ols), per parameter'")
    expect(head + a.replace("| 1 % |", "| 2 % |"), False, False, "column 'adequacy finding'")
    expect(head + "| new cell | 100 | M 1 (1) | M +0.0 | 0 % | 0 | covers |\n", False, False,
           "cell 'new cell': made by the run, not in the table")
    expect(head + a + b, True, True)
    expect(head + a, True, False, "cell 'effects': in the table, not made by the run")
    for p in problems:
        print("FAIL", p)
    print("PASS the coverage table is compared cell by cell" if not problems else f"{len(problems)} failures")
    return 1 if problems else 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    print(__doc__)
    sys.exit(2)
