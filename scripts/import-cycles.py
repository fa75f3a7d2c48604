#!/usr/bin/env python3
"""Find the files of a crate that import each other in a loop.

Usage: scripts/import-cycles.py [SRC_DIR] [--why FILE] [--all]

SRC_DIR defaults to crates/essl-gl/src. Every `crate::…`, `super::…` and `self::…` path of a
file (in `use` declarations and inline), and every `use child::…` of a module's own children,
is an edge from that file to the file that *defines* the named item: a name re-exported by a
`mod.rs` (`pub(crate) use link::Linker`, `pub(crate) use format::*`) is followed to the file
where it is written, so a re-export is no dependency of its own. Comments and string literals
are ignored, and so are `mod` declarations (a parent declaring a child imports nothing) and
re-exports the file does not use itself (`pub use context::Context` in `lib.rs`).

Prints the strongly connected components of more than one file, largest first (the files of
each component import each other in a loop), then the sizes. `--why FILE` lists the edges out
of one file, with the paths that make them; `--all` lists every component's files.
"""
import argparse
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
ITEM = re.compile(
    r"^\s*(?:pub(?:\([^)]*\))?\s+)?(?:const\s+|unsafe\s+|async\s+)*"
    r"(?:struct|enum|fn|const|static|type|trait|union|mod)\s+(\w+)"
)
MACRO = re.compile(r"^\s*macro_rules!\s*(\w+)")
# An item a macro defines at the top level: `handle! { Buffer }` defines `Buffer`.
MACRO_ITEM = re.compile(r"^(?!macro_rules)\w+!\s*[{(]\s*(?:#\[[^\]]*\]\s*)*(\w+)", re.M)
USE = re.compile(r"^\s*(?:pub(?:\([^)]*\))?\s+)?use\s+([^;]*);", re.S | re.M)
INLINE = re.compile(r"(?<![\w:])((?:crate|super|self)(?:::\w+)+)")


def strip(text):
    """The text without comments and string/char literals (kept as blanks)."""
    out, i, n = [], 0, len(text)
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            i = n if j < 0 else j + 2
        elif re.match(r'b?r#*"', text[i:]) and (i == 0 or not text[i - 1].isalnum()):
            m = re.match(r'b?r(#*)"', text[i:])
            close = '"' + m.group(1)
            j = text.find(close, i + m.end())
            i = n if j < 0 else j + len(close)
            out.append('""')
        elif text[i] == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            i = j + 1
            out.append('""')
        elif re.match(r"'(\\.|[^\\'])'", text[i:]):
            i += re.match(r"'(\\.|[^\\'])+'", text[i:]).end()
            out.append("' '")
        else:
            out.append(text[i])
            i += 1
    return "".join(out)


def expand(tree):
    """The paths of a `use` tree: `a::{b, c::{d, e}}` → a::b, a::c::d, a::c::e."""
    tree = re.sub(r"\s+", "", re.sub(r"\s+as\s+\w+", "", tree))
    depth, start = 0, None
    for k, ch in enumerate(tree):
        if ch == "{":
            if depth == 0:
                start = k
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth == 0:
                prefix, inner, rest = tree[:start], tree[start + 1 : k], tree[k + 1 :]
                parts, d, s = [], 0, 0
                for q, c in enumerate(inner):
                    d += c == "{"
                    d -= c == "}"
                    if c == "," and d == 0:
                        parts.append(inner[s:q])
                        s = q + 1
                parts.append(inner[s:])
                paths = []
                for p in parts:
                    if not p:
                        continue
                    for e in expand(p):
                        paths.append(prefix + e if e != "self" else prefix.rstrip(":"))
                return paths + (expand(rest) if rest else [])
    return [tree]


def inline_modules(text, pos):
    """The names of the inline modules (`mod tests { … }`) around position `pos`."""
    names = []
    for hit in re.finditer(r"\bmod\s+(\w+)\s*\{", text[:pos]):
        depth, k = 1, hit.end()
        while k < pos and depth:
            depth += (text[k] == "{") - (text[k] == "}")
            k += 1
        if depth:
            names.append(hit.group(1))
    return tuple(names)


class Crate:
    """The modules of a crate's source folder: their files, items, `use`s and children."""

    def __init__(self, src):
        self.src = src
        self.files = {}  # module path (tuple) → file
        for f in sorted(src.rglob("*.rs")):
            rel = f.relative_to(src).with_suffix("").parts
            if rel in (("lib",), ("main",)):
                mod = ()
            elif rel[-1] == "mod":
                mod = rel[:-1]
            else:
                mod = rel
            self.files[mod] = f
        self.text = {m: strip(f.read_text()) for m, f in self.files.items()}
        self.items = {}
        self.uses = {}  # module → [(full path tuple, is_pub)]
        for m, text in self.text.items():
            names = set()
            for line in text.splitlines():
                for rx in (ITEM, MACRO):
                    hit = rx.match(line)
                    if hit:
                        names.add(hit.group(1))
            names.update(MACRO_ITEM.findall(text))
            self.items[m] = names
            uses = []
            for hit in USE.finditer(text):
                is_pub = hit.group(0).lstrip().startswith("pub")
                inner = m + inline_modules(text, hit.start())
                for p in expand(hit.group(1)):
                    full = self.absolute(inner, p.split("::"))
                    if full is not None:
                        uses.append((full, is_pub, p))
            self.uses[m] = uses

    def absolute(self, mod, segs):
        """A path written in module `mod`, as a path from the crate root (`None`: another
        crate's)."""
        segs = [s for s in segs if s]
        if not segs:
            return None
        here = list(mod)
        if segs[0] == "crate":
            return tuple(segs[1:])
        if segs[0] in ("self", "super"):
            while segs and segs[0] in ("self", "super"):
                if segs[0] == "super":
                    here = here[:-1]
                segs = segs[1:]
            return tuple(here + segs)
        if tuple(here + [segs[0]]) in self.files:  # a child module
            return tuple(here + segs)
        return None

    def resolve(self, path):
        """The file defining what an absolute path names (its module's file when unknown)."""
        return self.find(path, set()) or self.files[self.module_of(path)]

    def module_of(self, path):
        """The longest prefix of `path` that is a module with a file."""
        k = len(path)
        while k > 0 and path[:k] not in self.files:
            k -= 1
        return path[:k]

    def find(self, path, seen):
        """The file that defines `path`'s item, following re-exports; `None` if not found."""
        if path in seen:
            return None
        seen.add(path)
        mod = self.module_of(path)
        k = len(mod)
        if k == len(path) or path[k] in self.items[mod]:
            return self.files[mod]
        for full, _, _ in self.uses[mod]:
            if full[-1] == path[k]:
                found = self.find(full + path[k + 1 :], seen)
                if found is not None:
                    return found
        for full, _, _ in self.uses[mod]:
            if full[-1] == "*":
                found = self.find(full[:-1] + path[k:], seen)
                if found is not None:
                    return found
        return None

    def edges(self):
        """file → {file it imports: [the paths that make the edge]}."""
        out = {f: {} for f in self.files.values()}
        for m, f in self.files.items():
            body = USE.sub("", self.text[m])
            paths = [
                (full, p)
                for full, is_pub, p in self.uses[m]
                if not is_pub or full[-1] == "*" or re.search(rf"\b{full[-1]}\b", body)
            ]
            for hit in INLINE.finditer(body):
                inner = m + inline_modules(body, hit.start())
                full = self.absolute(inner, hit.group(1).split("::"))
                paths.append((full, hit.group(1)))
            for full, written in paths:
                if full is None:
                    continue
                if full and full[-1] == "*":
                    full = full[:-1]
                target = self.resolve(full)
                if target is not None and target != f:
                    out[f].setdefault(target, []).append(written)
        return out


def components(graph):
    """Tarjan's strongly connected components of `graph` (node → iterable of nodes)."""
    index, low, stack, on, result, counter = {}, {}, [], set(), [], [0]
    sys.setrecursionlimit(10000)

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            result.append(comp)

    for v in graph:
        if v not in index:
            visit(v)
    return result


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("src", nargs="?", default="crates/essl-gl/src")
    ap.add_argument("--why", help="list the edges out of this file (relative to SRC)")
    ap.add_argument("--all", action="store_true", help="list every component's files")
    args = ap.parse_args()
    src = pathlib.Path(args.src).resolve() if pathlib.Path(args.src).is_absolute() else (ROOT / args.src).resolve()
    crate = Crate(src)
    edges = crate.edges()
    name = lambda f: str(f.relative_to(src))
    if args.why:
        for target, paths in sorted(edges[src / args.why].items()):
            print(f"{name(target)}: {', '.join(sorted(set(paths)))}")
        return
    comps = sorted((c for c in components(edges) if len(c) > 1), key=len, reverse=True)
    for i, comp in enumerate(comps):
        if i == 0 or args.all:
            print(f"{len(comp)} files import each other in a loop:")
            for f in sorted(comp, key=name):
                print(f"  {name(f)}")
    sizes = [len(c) for c in comps]
    print(f"{len(edges)} files; components of more than one file: {sizes or 'none'}")


if __name__ == "__main__":
    main()
