#!/usr/bin/env python3
"""The architecture check: every arrow in the code must be one that docs/ARCHITECTURE.md allows.

Reads the two tables of docs/ARCHITECTURE.md (after the markers ``<!-- arrows:kernel -->`` and
``<!-- arrows:python -->``: unit, what it holds, what it may use), then

- every ``use`` statement in kernel/src (*.f90, *.F90 and their *.in templates): a module belongs
  to the folder of the file that defines it (not to its name), and the using file's folder (or its
  own row, for files with one) must list that folder, unless both are the same unit;
- every module name in kernel/src: ``udmap_<folder>_<file>`` with ``/`` as ``_`` (udmap.f90:
  ``udmap``), and no procedures in a row marked "re-exports only";
- every ``import`` in wrappers/python/udmap: the importing unit must list the imported one; no
  import circles (function-local imports count, ``if TYPE_CHECKING:`` ones do not); no use of
  another module's private names (``from m import _x``, ``m._x``, a private module outside its
  package, ``obj._x`` where ``_x`` is not defined in the importing module).

Prints one line per violation (``file:line: what -> what: why``) and exits 1 if there are any,
0 otherwise. Standard library only; needs no build.

    python3 tests/arch/check_arrows.py [--root TREE] [--quiet]
"""
from __future__ import annotations

import argparse
import ast
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

PAGE = Path("docs") / "ARCHITECTURE.md"
KERNEL = Path("kernel") / "src"
PYTHON = Path("wrappers") / "python" / "udmap"
PACKAGE = "udmap"
FACE_MARK = "re-exports only"

# Private attributes of objects that belong to the standard library or numpy, not to udmap.
FOREIGN_PRIVATE = {"_asdict", "_replace", "_fields", "_make", "_field_defaults", "_exit",
                   "_getframe", "_current_frames", "_name", "_handle", "_obj"}  # ctypes


@dataclass
class Rules:
    """One table of ARCHITECTURE.md: unit -> units it may use; units whose row is a face."""
    allowed: dict[str, set[str]] = field(default_factory=dict)
    faces: set[str] = field(default_factory=set)
    line: dict[str, int] = field(default_factory=dict)


@dataclass
class Violation:
    path: str
    line: int
    message: str

    def __str__(self) -> str:
        return f"{self.path}:{self.line}: {self.message}"


# --------------------------------------------------------------------------- the page
def _cells(row: str) -> list[str]:
    return [c.strip() for c in row.strip().strip("|").split("|")]


def _ticked(cell: str) -> list[str]:
    return re.findall(r"`([^`]+)`", cell)


def parse_page(text: str, marker: str, page: str) -> tuple[Rules, list[Violation]]:
    """The first Markdown table after <!-- arrows:MARKER --> as Rules."""
    rules, problems = Rules(), []
    lines = text.splitlines()
    tag = f"<!-- arrows:{marker} -->"
    start = next((i for i, l in enumerate(lines) if l.strip() == tag), None)
    if start is None:
        return rules, [Violation(page, 1, f"no table after {tag}")]
    i = start + 1
    while i < len(lines) and not lines[i].lstrip().startswith("|"):
        i += 1
    header = True
    while i < len(lines) and lines[i].lstrip().startswith("|"):
        row = _cells(lines[i])
        if header or set(lines[i].replace("|", "").strip()) <= set("-: "):
            header = False
            i += 1
            continue
        if len(row) < 3:
            problems.append(Violation(page, i + 1, "a rule row needs: unit | holds | may use"))
            i += 1
            continue
        units, uses = _ticked(row[0]), set(_ticked(row[-1]))
        for unit in units:
            if unit in rules.allowed:
                problems.append(Violation(page, i + 1, f"`{unit}` has two rows"))
            rules.allowed[unit] = set(uses)
            rules.line[unit] = i + 1
            if FACE_MARK in row[1]:
                rules.faces.add(unit)
        i += 1
    for unit, uses in rules.allowed.items():
        for u in sorted(uses - set(rules.allowed)):
            problems.append(Violation(page, rules.line[unit],
                                      f"`{unit}` may use `{u}`, which has no row"))
    cycle = _find_cycle({u: {v for v in uses if v != u} for u, uses in rules.allowed.items()})
    if cycle:
        problems.append(Violation(page, rules.line[cycle[0]],
                                  "the allowed arrows form a circle: " + " -> ".join(cycle)))
    return rules, problems


def _find_cycle(graph: dict[str, set[str]]) -> list[str] | None:
    """One cycle of the directed graph (as a closed list of nodes), or None."""
    color: dict[str, int] = {}
    stack: list[str] = []

    def visit(n: str) -> list[str] | None:
        color[n] = 1
        stack.append(n)
        for m in sorted(graph.get(n, ())):
            if color.get(m) == 1:
                return stack[stack.index(m):] + [m]
            if m not in color:
                found = visit(m)
                if found:
                    return found
        stack.pop()
        color[n] = 2
        return None

    for n in sorted(graph):
        if n not in color:
            found = visit(n)
            if found:
                return found
    return None


def _circles(graph: dict[str, set[str]]) -> list[tuple[list[str], list[str]]]:
    """One cycle through each strongly connected component of more than one node (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    comps: list[set[str]] = []

    def strong(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                strong(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = set()
            while True:
                w = stack.pop()
                on.discard(w)
                comp.add(w)
                if w == v:
                    break
            if len(comp) > 1:
                comps.append(comp)

    for v in sorted(graph):
        if v not in index:
            strong(v)
    cycles = []
    for comp in sorted(comps, key=min):
        sub = {v: graph[v] & comp for v in comp}
        cycle = _find_cycle(sub)
        if cycle:
            cycles.append((cycle, sorted(comp - set(cycle))))
    return cycles


# --------------------------------------------------------------------------- Fortran
_MODULE = re.compile(r"^\s*module\s+([a-z_][a-z0-9_]*)\s*(?:!.*)?$", re.I)
_USE = re.compile(r"^\s*use\b\s*(?:,\s*(?:non_)?intrinsic\s*)?(?:::)?\s*([a-z_][a-z0-9_]*)",
                  re.I)
_CONTAINS = re.compile(r"^\s*contains\s*(?:!.*)?$", re.I)
_FORTRAN = (".f90", ".F90", ".f90.in", ".F90.in")


def _stem(rel: str) -> str:
    for ext in sorted(_FORTRAN, key=len, reverse=True):
        if rel.endswith(ext):
            return rel[:-len(ext)]
    return rel


def _kernel_unit(rel: str, rules: Rules) -> str | None:
    """The table row of a kernel file: its own (by path), else its folder's, else that of the
    nearest folder above it with a row (contact/aft/moment.f90 belongs to contact)."""
    if rel in rules.allowed:
        return rel
    if rel.endswith(".in") and rel[:-3] in rules.allowed:
        return rel[:-3]
    parts = rel.split("/")[:-1]
    while parts:
        folder = "/".join(parts)
        if folder in rules.allowed:
            return folder
        parts.pop()
    return None


def check_kernel(root: Path, rules: Rules) -> list[Violation]:
    src = root / KERNEL
    if not src.is_dir():
        return [Violation(str(KERNEL), 0, "no kernel source folder")]
    files = sorted(p for p in src.rglob("*") if p.is_file() and p.name.endswith(_FORTRAN))
    defined: dict[str, str] = {}          # module name (lower case) -> file (relative to src)
    uses: list[tuple[str, int, str]] = []
    out: list[Violation] = []
    for path in files:
        rel = path.relative_to(src).as_posix()
        shown = (KERNEL / rel).as_posix()
        expected = "udmap" if rel == "udmap.f90" else "udmap_" + _stem(rel).replace("/", "_")
        has_contains = False
        for n, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            m = _MODULE.match(line)
            if m and m.group(1).lower() != "procedure":
                name = m.group(1).lower()
                defined[name] = rel
                if name != expected.lower():
                    out.append(Violation(shown, n, f"module {name} does not follow its path "
                                                   f"(expected {expected.lower()})"))
            m = _USE.match(line)
            if m:
                uses.append((rel, n, m.group(1).lower()))
            if _CONTAINS.match(line):
                has_contains = has_contains or n
        unit = _kernel_unit(rel, rules)
        if unit is None:
            folder = rel.rsplit("/", 1)[0] if "/" in rel else "(kernel/src itself)"
            out.append(Violation(shown, 1, f"folder {folder} has no row in {PAGE} (nor has "
                                           "any folder above it)"))
        elif unit in rules.faces and has_contains:
            out.append(Violation(shown, has_contains,
                                 f"{unit} is a face (re-exports only) but holds procedures"))
    for rel, n, name in uses:
        target = defined.get(name)
        if target is None:
            continue                    # not a kernel module (iso_c_binding, MUMPS, ...)
        a, b = _kernel_unit(rel, rules), _kernel_unit(target, rules)
        if a is None or b is None or a == b:
            continue
        if b not in rules.allowed[a]:
            out.append(Violation((KERNEL / rel).as_posix(), n,
                                 f"{a} -> {b} (use {name}): not allowed by {PAGE}"))
    return out


# --------------------------------------------------------------------------- Python
@dataclass
class Import:
    line: int
    target: str                 # dotted module imported (udmap....)
    names: tuple[str, ...]      # names taken from it (from-imports); () for plain imports
    typing_only: bool


def _module_name(rel: Path) -> str:
    parts = list(rel.with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join([PACKAGE] + parts)


def _python_unit(module: str) -> str:
    parts = module.split(".")
    return "__init__" if len(parts) == 1 else parts[1]


def _is_private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__")) \
        and not name.endswith("_")


class _ModuleScan(ast.NodeVisitor):
    """Imports of one module, with the names that end up bound to udmap modules."""

    def __init__(self, module: str, is_package: bool, modules: set[str]):
        self.module, self.modules = module, modules
        self.package = module if is_package else module.rsplit(".", 1)[0]
        self.imports: list[Import] = []
        self.aliases: dict[str, str] = {}       # local name -> udmap module
        self.typing = 0

    def _resolve(self, level: int, mod: str | None) -> str | None:
        if level == 0:
            return mod
        base = self.package.split(".")
        if level - 1 > 0:
            base = base[:-(level - 1)]
        return ".".join(base + ([mod] if mod else []))

    def visit_If(self, node: ast.If) -> None:
        test = node.test
        typing = (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
            isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")
        self.typing += typing
        for child in node.body:
            self.visit(child)
        self.typing -= typing
        for child in node.orelse:
            self.visit(child)
        self.visit(node.test)

    def visit_Import(self, node: ast.Import) -> None:
        for alias in node.names:
            if alias.name == PACKAGE or alias.name.startswith(PACKAGE + "."):
                self.imports.append(Import(node.lineno, alias.name, (), self.typing > 0))
                if alias.asname:
                    self.aliases[alias.asname] = alias.name
                else:
                    self.aliases[alias.name.split(".")[0]] = PACKAGE

    def visit_ImportFrom(self, node: ast.ImportFrom) -> None:
        target = self._resolve(node.level, node.module)
        if target is None or not (target == PACKAGE or target.startswith(PACKAGE + ".")):
            return
        names = tuple(a.name for a in node.names)
        self.imports.append(Import(node.lineno, target, names, self.typing > 0))
        for a in node.names:
            if f"{target}.{a.name}" in self.modules:
                self.aliases[a.asname or a.name] = f"{target}.{a.name}"


def _defined_private(tree: ast.AST) -> set[str]:
    """Private names this module defines itself: functions, classes, attributes, assignments."""
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            names.add(node.id)
        elif isinstance(node, ast.Attribute) and isinstance(node.ctx, (ast.Store, ast.Del)):
            names.add(node.attr)
        elif isinstance(node, ast.arg):
            names.add(node.arg)
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            if re.fullmatch(r"_[A-Za-z0-9_]+", node.value):   # __slots__, ctypes _fields_
                names.add(node.value)
        elif isinstance(node, ast.keyword) and node.arg:
            names.add(node.arg)
    return {n for n in names if n.startswith("_")}


def _dotted(node: ast.AST) -> list[str] | None:
    parts: list[str] = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if isinstance(node, ast.Name):
        return [node.id] + parts[::-1]
    return None


def _private_owner(module: str) -> str | None:
    """The package a private module belongs to (udmap.fe._text -> udmap.fe), or None."""
    parts = module.split(".")
    for i in range(1, len(parts)):
        if _is_private(parts[i]):
            return ".".join(parts[:i])
    return None


def check_python(root: Path, rules: Rules) -> list[Violation]:
    pkg = root / PYTHON
    if not pkg.is_dir():
        return [Violation(str(PYTHON), 0, "no Python package folder")]
    files = sorted(p for p in pkg.rglob("*.py") if "__pycache__" not in p.parts)
    modules = {_module_name(p.relative_to(pkg)): p for p in files}
    names = set(modules)
    out: list[Violation] = []
    graph: dict[str, dict[str, int]] = {m: {} for m in modules}
    for module, path in modules.items():
        shown = path.relative_to(root).as_posix()
        try:
            tree = ast.parse(path.read_text(), filename=str(path))
        except SyntaxError as exc:
            out.append(Violation(shown, exc.lineno or 0, f"cannot parse: {exc.msg}"))
            continue
        scan = _ModuleScan(module, path.name == "__init__.py", names)
        scan.visit(tree)
        unit = _python_unit(module)
        if unit not in rules.allowed:
            out.append(Violation(shown, 1, f"module {unit} has no row in {PAGE}"))
        for imp in scan.imports:
            # the modules this import reaches: the target, or its submodules named in the import
            reached = []
            for name in imp.names or ("",):
                sub = f"{imp.target}.{name}" if name else imp.target
                if name and sub in names:
                    reached.append((sub, None))
                else:
                    reached.append((imp.target, name or None))
            for target, name in reached:
                if target not in names:
                    out.append(Violation(shown, imp.line, f"{module} imports {target}, which "
                                                          "does not exist"))
                    continue
                if not imp.typing_only and target != module:
                    graph[module].setdefault(target, imp.line)
                owner = _private_owner(target)
                if owner is not None and not (module == owner or module.startswith(owner + ".")):
                    out.append(Violation(shown, imp.line, f"{module} -> {target}: private module "
                                                          f"of {owner}"))
                if name and _is_private(name):
                    out.append(Violation(shown, imp.line, f"{module} -> {target}.{name}: private "
                                                          "name of another module"))
                b = _python_unit(target)
                if unit in rules.allowed and b in rules.allowed and b != unit \
                        and b not in rules.allowed[unit]:
                    what = f"{target}.{name}" if name else target
                    out.append(Violation(shown, imp.line, f"{unit} -> {b} ({what}): not allowed "
                                                          f"by {PAGE}"))
        # attribute access: module._x, or obj._x with _x not defined here
        own = _defined_private(tree)
        for node in ast.walk(tree):
            if not isinstance(node, ast.Attribute) or not _is_private(node.attr):
                continue
            chain = _dotted(node)
            if chain and chain[0] in scan.aliases:
                mod = scan.aliases[chain[0]]
                for part in chain[1:-1]:
                    if f"{mod}.{part}" in names:
                        mod = f"{mod}.{part}"
                    else:
                        break
                else:
                    if f"{mod}.{node.attr}" not in names:
                        out.append(Violation(shown, node.lineno, f"{module} -> {mod}.{node.attr}:"
                                                                 " private name of another module"))
                    continue
            base = node.value
            if isinstance(base, ast.Name) and base.id in ("self", "cls"):
                continue
            if node.attr in own or node.attr in FOREIGN_PRIVATE:
                continue
            what = ast.unparse(node) if hasattr(ast, "unparse") else node.attr
            out.append(Violation(shown, node.lineno, f"{module} uses {what}: private attribute "
                                                     "not defined in this module"))
    for cycle, more in _circles({m: set(t) for m, t in graph.items()}):
        a, b = cycle[0], cycle[1]
        path = modules[a].relative_to(root).as_posix()
        also = f" (the same circle also runs through {', '.join(more)})" if more else ""
        out.append(Violation(path, graph[a][b], "import circle: " + " -> ".join(cycle) + also))
    return out


# --------------------------------------------------------------------------- main
def check(root: Path) -> list[Violation]:
    page = root / PAGE
    if not page.is_file():
        return [Violation(str(PAGE), 0, "missing")]
    text = page.read_text()
    kernel_rules, p1 = parse_page(text, "kernel", str(PAGE))
    python_rules, p2 = parse_page(text, "python", str(PAGE))
    return p1 + p2 + check_kernel(root, kernel_rules) + check_python(root, python_rules)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", type=Path, default=Path(__file__).resolve().parents[2],
                    help="the tree to check (default: this checkout)")
    ap.add_argument("--quiet", action="store_true", help="only the count")
    args = ap.parse_args(argv)
    violations = sorted(check(args.root.resolve()), key=lambda v: (v.path, v.line, v.message))
    if not args.quiet:
        for v in violations:
            print(v)
    if violations:
        print(f"check_arrows: {len(violations)} violation(s) of {PAGE}")
        return 1
    print(f"check_arrows: every arrow is allowed by {PAGE}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
