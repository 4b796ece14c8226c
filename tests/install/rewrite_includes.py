#!/usr/bin/env python3
"""tests/install/rewrite_includes.py [--check] [ROOT] -- the engine's includes in the installed form.

Every `#include "<part>/x.h"` of a file under ROOT/engine (ROOT: the source tree, default: two
folders up from this script), where <part> is a folder of engine/, becomes
`#include "symrep/<part>/x.h"`: the spelling that resolves both in the build tree (include root
build/include, where include/symrep/<part> links to engine/<part>) and installed (PREFIX/include,
headers in PREFIX/include/symrep/<part>; docs/library.md). Nothing else changes; running it again
changes nothing. With --check it changes nothing and exits with 1 when a file would change (and
lists them). tests/test_architecture.cpp refuses the old form in engine/.
"""
import pathlib
import re
import sys


def rewrite(text, parts):
    def fix(m):
        return m.group(1) + "symrep/" + m.group(2) if m.group(3) in parts else m.group(0)

    return re.sub(r'^(\s*#\s*include\s*")(([a-z_]+)/[^"]*")', fix, text, flags=re.M)


def main(argv):
    check = "--check" in argv
    args = [a for a in argv if a != "--check"]
    root = pathlib.Path(args[0]) if args else pathlib.Path(__file__).resolve().parents[2]
    engine = root / "engine"
    parts = {p.name for p in engine.iterdir() if p.is_dir()}
    changed = []
    for f in sorted(engine.rglob("*")):
        if f.suffix not in (".h", ".cpp") or not f.is_file():
            continue
        text = f.read_text()
        new = rewrite(text, parts)
        if new != text:
            changed.append(f.relative_to(root))
            if not check:
                f.write_text(new)
    for f in changed:
        print(("would rewrite " if check else "rewrote ") + str(f))
    return 1 if check and changed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
