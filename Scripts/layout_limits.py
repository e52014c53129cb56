"""The layout's limits: the longest chain of the project's own includes,
the largest product files, the largest classes and the longest functions.

    python3 Scripts/layout_limits.py [--max-chain N] [--max-lines N] [--max-class N]
        [--max-function N]

Follows every quoted include of the product code (Core, FileFormats,
Filters, IO, Plugin) that names a file of the project, from each
source or header, and prints the longest chain (counted in includes: a
file that includes a header that includes nothing of ours is a chain of
1). A class is counted from its "class" or "struct" line to its closing
brace. A function is counted from the first line of its signature to its
closing brace (clang-format puts a function's braces on lines of their
own); a function whose signature is preceded by a comment holding
"long function:" and the reason (a SIMD kernel that one loop must keep
whole) is listed but not held to the limit. With --max-chain,
--max-lines, --max-class or --max-function, exits with 1 when a chain, a
product file, a class or a function is longer (the LayoutLimits test).
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


OPENING = re.compile(r"(namespace|class|struct|enum|union|extern)\b")
CONTROL = re.compile(r"(if|for|while|switch|else|do|try|catch|return)\b")
NAME = re.compile(r"([~\w:]+)\s*\(")
EXEMPT = "long function:"


def indentation(line):
    return len(line) - len(line.lstrip())


def function_at(lines, brace):
    """(first line, name) of the function whose body opens with the lone
    brace at `brace`, or None when that brace opens something else."""
    before = brace - 1
    while before >= 0 and not lines[before].strip():
        before -= 1
    if before < 0:
        return None
    last = lines[before].strip()
    if OPENING.match(last) or last.endswith(("=", ",", "(")):
        return None
    first = before
    while first > 0 and indentation(lines[first]) > indentation(lines[brace]):
        first -= 1
    signature = " ".join(line.strip() for line in lines[first:before + 1])
    names = [n for n in NAME.findall(signature) if n not in ("__attribute__", "target", "decltype")]
    if not names or CONTROL.match(signature) or "[" in signature.split("(")[0]:
        return None
    return first, names[0]


def functions(path):
    """(lines, name, exempt) of every function defined in `path`."""
    with open(path, encoding="utf-8") as handle:
        lines = handle.read().split("\n")
    found = []
    for i, line in enumerate(lines):
        if line.strip() != "{":
            continue
        start = function_at(lines, i)
        if start is None:
            continue
        first, name = start
        close = " " * indentation(line) + "}"
        end = next((j for j in range(i + 1, len(lines))
                    if lines[j].startswith(close) and indentation(lines[j]) == indentation(line)),
                   len(lines) - 1)
        exempt = any(EXEMPT in lines[k] for k in range(max(0, first - 4), first))
        found.append((end - first + 1, name, exempt))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--max-chain", type=int)
    parser.add_argument("--max-lines", type=int)
    parser.add_argument("--max-class", type=int)
    parser.add_argument("--max-function", type=int)
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
    lengths = sorted(((lines, name, exempt, os.path.relpath(f, ROOT)) for f in files
                      for lines, name, exempt in functions(f)), reverse=True)
    print("longest functions:")
    for lines, name, exempt, where in lengths[:5]:
        print("  %5d %s (%s)%s" % (lines, name, where, " (exempt: says why)" if exempt else ""))
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
    if arguments.max_function is not None:
        over = ["%s in %s (%d)" % (name, where, lines) for lines, name, exempt, where in lengths
                if lines > arguments.max_function and not exempt]
        if over:
            print("FAILED: %s longer than %d lines" % (", ".join(over), arguments.max_function))
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
