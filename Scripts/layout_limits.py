"""The layout's limits: the longest chain of the project's own includes,
the largest product files and the largest classes.

    python3 Scripts/layout_limits.py [--max-chain N] [--max-lines N] [--max-class N]

Follows every quoted include of the product code (Core, FileFormats,
Filters, IO, Plugin) that names a file of the project, from each
source or header, and prints the longest chain (counted in includes: a
file that includes a header that includes nothing of ours is a chain of
1). A class is counted from its "class" or "struct" line to its closing
brace. With --max-chain, --max-lines or --max-class, exits with 1 when a
chain, a product file or a class is longer (the LayoutLimits test).
"""

import argparse
import functools
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PRODUCT = ["Core", "FileFormats", "Filters", "IO", "Plugin"]
# The include roots, as the build has them: Core/ for the core's folders,
# the repository for FileFormats/, and each VTK folder for its own headers.
INCLUDE_ROOTS = [os.path.join(ROOT, "Core"), ROOT]
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)


def product_files():
    for top in PRODUCT:
        for folder, _, names in os.walk(os.path.join(ROOT, top)):
            for name in sorted(names):
                if name.endswith((".h", ".cxx", ".inc")):
                    yield os.path.join(folder, name)


def resolve(including, name):
    for root in [os.path.dirname(including)] + INCLUDE_ROOTS:
        path = os.path.normpath(os.path.join(root, name))
        if os.path.isfile(path):
            return path
    return None


@functools.lru_cache(maxsize=None)
def includes(path):
    with open(path, encoding="utf-8") as handle:
        text = handle.read()
    found = (resolve(path, name) for name in INCLUDE.findall(text))
    return tuple(sorted({p for p in found if p and p != path}))


@functools.lru_cache(maxsize=None)
def longest_chain(path):
    """The longest chain of includes from `path`, as the list of files."""
    best = [path]
    for included in includes(path):
        chain = [path] + longest_chain(included)
        if len(chain) > len(best):
            best = chain
    return best


def line_count(path):
    with open(path, encoding="utf-8") as handle:
        return sum(1 for _ in handle)


CLASS = re.compile(r"^(\s*)(?:template\s*<[^>]*>\s*)?(?:class|struct)\s+(?:\w+_EXPORT\s+)?(\w+)[^;]*$")


def classes(path):
    """(lines, name) of every class or struct defined in `path`."""
    with open(path, encoding="utf-8") as handle:
        lines = handle.read().split("\n")
    found = []
    for i, line in enumerate(lines):
        match = CLASS.match(line)
        if not match:
            continue
        indent = match.group(1)
        for j in range(i + 1, len(lines)):
            if lines[j].startswith(indent + "};"):
                found.append((j - i + 1, match.group(2)))
                break
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--max-chain", type=int)
    parser.add_argument("--max-lines", type=int)
    parser.add_argument("--max-class", type=int)
    arguments = parser.parse_args()
    files = list(product_files())
    chains = sorted((longest_chain(f) for f in files), key=len, reverse=True)
    longest = chains[0]
    print("longest chain of includes: %d" % (len(longest) - 1))
    print("  " + " -> ".join(os.path.relpath(p, ROOT) for p in longest))
    sizes = sorted(((line_count(f), os.path.relpath(f, ROOT)) for f in files), reverse=True)
    print("largest product files:")
    for lines, name in sizes[:5]:
        print("  %5d %s" % (lines, name))
    sized = sorted(((lines, name, os.path.relpath(f, ROOT)) for f in files for lines, name in classes(f)),
                   reverse=True)
    print("largest classes:")
    for lines, name, where in sized[:5]:
        print("  %5d %s (%s)" % (lines, name, where))
    failed = False
    if arguments.max_chain is not None and len(longest) - 1 > arguments.max_chain:
        print("FAILED: a chain of %d includes, more than %d" % (len(longest) - 1, arguments.max_chain))
        failed = True
    if arguments.max_lines is not None and sizes[0][0] > arguments.max_lines:
        over = [name for lines, name in sizes if lines > arguments.max_lines]
        print("FAILED: %s longer than %d lines" % (", ".join(over), arguments.max_lines))
        failed = True
    if arguments.max_class is not None and sized and sized[0][0] > arguments.max_class:
        over = ["%s (%d)" % (name, lines) for lines, name, _ in sized if lines > arguments.max_class]
        print("FAILED: %s longer than %d lines" % (", ".join(over), arguments.max_class))
        failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
