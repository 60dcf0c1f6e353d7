#!/usr/bin/env python3
"""Prints the table of docs/reliability.md from tests/reliability/cases.txt (the corpus ctest runs), so the
document and the tests cannot drift apart: `scripts/reliability_table.py > /tmp/t.md` and paste, or
`--check docs/reliability.md` (exit 1 when the document's table differs)."""
import pathlib
import sys

root = pathlib.Path(__file__).resolve().parent.parent


def rows():
    section = ""
    for line in (root / "tests/reliability/cases.txt").read_text(encoding="utf-8").splitlines():
        if line.startswith("# ") and "|" not in line and not line.startswith("# name"):
            section = line[2:].strip()
            continue
        if not line or line.startswith("#"):
            continue
        name, status, fragment, command = (p.strip() for p in line.split("|", 3))
        yield section, name, status, fragment, command


def table():
    out = ["| case | command (in a fresh directory) | status | the message contains |", "| --- | --- | --- | --- |"]
    last = None
    for section, name, status, fragment, command in rows():
        if section != last:
            out.append("| **%s** | | | |" % section)
            last = section
        out.append("| `%s` | `%s` | %s | %s |" % (name, command.replace("|", "\\|"), status,
                                              fragment.replace("|", "\\|")))
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--check":
        sys.exit(0 if table() in pathlib.Path(sys.argv[2]).read_text(encoding="utf-8") else 1)
    sys.stdout.write(table())
