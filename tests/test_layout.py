"""The package's layout stays livable: no import cycle, no private name imported across modules,
no module over 400 lines without a sentence at its top saying why.

Read from the source with :mod:`ast` (nothing is imported). An import counts wherever it is
written (module level or inside a function: a lazy import that dodges a cycle is still a
cycle). ``from a.b import c`` is an edge to the module ``a.b.c`` when that is a module, else to
``a.b``; importing a submodule does not count as importing its parent package's
``__init__`` (Python runs it, but it is not a design dependency).
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src" / "seafast"
ARCHITECTURE = Path(__file__).resolve().parents[1] / "docs" / "architecture.md"
LAYER_TABLE_START = "| floor | rooms |"
MAX_LINES = 400
SIZE_MARKER = "Size:"
# Over MAX_LINES and being changed on other branches when the package was split: their
# owners add the "Size:" sentence or split them; this list must only shrink. Empty since
# excitation/hydrodynamics.py and studies/spec.py became packages.
SIZE_PENDING: set[str] = set()


def _modules() -> dict[str, tuple[Path, bool]]:
    out = {}
    for path in sorted(SRC.rglob("*.py")):
        parts = list(path.relative_to(SRC.parent).with_suffix("").parts)
        is_package = parts[-1] == "__init__"
        if is_package:
            parts = parts[:-1]
        out[".".join(parts)] = (path, is_package)
    return out


MODULES = _modules()


def _imports(name: str, source: str | None = None) -> tuple[set[str], list[tuple[str, str]]]:
    """Modules ``name`` imports, and the (module, private name) pairs it imports from others."""
    path, is_package = MODULES[name]
    tree = ast.parse(path.read_text(encoding="utf-8") if source is None else source)
    package = name if is_package else name.rpartition(".")[0]
    edges: set[str] = set()
    private: list[tuple[str, str]] = []
    aliases: dict[str, str] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name in MODULES:
                    edges.add(alias.name)
                    aliases[alias.asname or alias.name] = alias.name
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                base = ".".join(parts + ([node.module] if node.module else []))
            if base.split(".")[0] != "seafast":
                continue
            for alias in node.names:
                full = f"{base}.{alias.name}"
                if full in MODULES:
                    edges.add(full)
                    aliases[alias.asname or alias.name] = full
                else:
                    edges.add(base)
                    if alias.name.startswith("_") and not alias.name.startswith("__"):
                        private.append((base, alias.name))
    for node in ast.walk(tree):
        # module._name through an imported module
        if (
            isinstance(node, ast.Attribute)
            and isinstance(node.value, ast.Name)
            and node.value.id in aliases
            and node.attr.startswith("_")
            and not node.attr.startswith("__")
        ):
            private.append((aliases[node.value.id], node.attr))
    return edges - {name}, private


GRAPH = {name: _imports(name) for name in MODULES}


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in graph:
        if v not in index:
            visit(v)
    return found


def test_the_checker_sees_the_package():
    """Guards the checks below against passing vacuously (a wrong path, a parser that sees nothing)."""
    assert len(MODULES) > 50 and "seafast.solvers.hbm.fixed" in MODULES
    edges, _ = GRAPH["seafast.solvers.hbm.fixed"]
    assert {"seafast.solvers.hbm.condensed", "seafast.fourier", "seafast.solvers.periodic"} <= edges
    # a planted cycle and planted private imports are found
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    planted = "from ..hbm.condensed import _static_contact_compressions\nfrom seafast import fourier as f\nf._x\n"
    assert _imports("seafast.solvers.hbm.solve", planted)[1] == [
        ("seafast.solvers.hbm.condensed", "_static_contact_compressions"),
        ("seafast.fourier", "_x"),
    ]


def test_no_import_cycle():
    cycles = _cycles({name: edges & MODULES.keys() for name, (edges, _) in GRAPH.items()})
    assert cycles == [], f"import cycles: {cycles}"


def test_no_private_name_imported_from_another_module():
    offences = [f"{name} imports {mod}.{attr}" for name, (_, private) in GRAPH.items() for mod, attr in private]
    assert offences == []


def test_fourier_is_the_lowest_layer():
    edges, _ = GRAPH["seafast.fourier"]
    assert edges == set()


def test_parallel_imports_nothing_else_of_seafast():
    """The shared machinery (store, executor, thread pinning, progress) sits beside fourier.py at the bottom."""
    modules = [name for name in MODULES if name == "seafast.parallel" or name.startswith("seafast.parallel.")]
    assert len(modules) >= 6
    outside = {name: sorted(e for e in GRAPH[name][0] if not e.startswith("seafast.parallel")) for name in modules}
    assert {name: edges for name, edges in outside.items() if edges} == {}


def test_long_modules_say_why():
    unexplained = {}
    for name, (path, _) in MODULES.items():
        text = path.read_text(encoding="utf-8")
        lines = len(text.splitlines())
        if lines > MAX_LINES and SIZE_MARKER not in (ast.get_docstring(ast.parse(text)) or ""):
            unexplained[name] = lines
    assert set(unexplained) - SIZE_PENDING == set(), f"over {MAX_LINES} lines with no '{SIZE_MARKER} ...' sentence: {unexplained}"
    # a module that no longer needs its exemption leaves the list
    assert SIZE_PENDING <= set(unexplained), f"remove from SIZE_PENDING: {SIZE_PENDING - set(unexplained)}"


def test_every_dft_goes_through_fourier():
    """One Fourier vocabulary: no module but seafast.fourier calls numpy's FFT itself."""
    calls = []
    for name, (path, _) in MODULES.items():
        if name == "seafast.fourier":
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Attribute) and node.value.attr == "fft":
                calls.append(f"{name}:{node.lineno} {node.attr}")
    assert calls == []


def _is_compiled(node: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    return any("njit" in ast.unparse(d) or "numba" in ast.unparse(d) for d in node.decorator_list)


def test_no_function_over_100_lines_and_no_module_over_600():
    """Compiled (numba) kernels excepted: a kernel's loop is kept whole so its arrays stay in registers."""
    long_functions, long_modules = [], []
    for name, (path, _) in MODULES.items():
        text = path.read_text(encoding="utf-8")
        if len(text.splitlines()) > 600:
            long_modules.append(name)
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and not _is_compiled(node):
                if node.end_lineno is not None and node.end_lineno - node.lineno + 1 > 100:
                    long_functions.append(f"{name}.{node.name}")
    assert long_functions == [] and long_modules == []


def _declared_floors() -> dict[str, int]:
    """The layer order, read from docs/architecture.md (the one place it is declared): package -> floor."""
    text = ARCHITECTURE.read_text(encoding="utf-8")
    table = text[text.index(LAYER_TABLE_START) :]
    floors: dict[str, int] = {}
    for line in table.splitlines()[2:]:
        if not line.startswith("|"):
            break
        cells = [c.strip() for c in line.strip("|").split("|")]
        for package in re.findall(r"`(\w+)/?`", cells[1]):
            floors[package] = int(cells[0])
    return floors


FLOORS = _declared_floors()


def _room(module: str) -> str:
    """The package (room) a module lives in: ``seafast.solvers.hbm.solve`` -> ``solvers``; the root -> ``seafast``."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "seafast"


def test_every_room_has_a_floor():
    rooms = {_room(name) for name in MODULES} - {"seafast"}
    assert rooms == set(FLOORS), f"rooms without a floor: {rooms - set(FLOORS)}; floors without a room: {set(FLOORS) - rooms}"


def _upward(name: str, edges: set[str]) -> list[str]:
    """The imports of module ``name`` from its own floor or above (its own room and the package root excepted)."""
    here = _room(name)
    out = []
    for target in sorted(edges):
        there = _room(target)
        if here == "seafast" or there in (here, "seafast"):
            continue
        if FLOORS[there] >= FLOORS[here]:
            out.append(f"{name} (floor {FLOORS[here]}) imports {target} (floor {FLOORS[there]})")
    return out


def test_no_import_from_a_higher_floor_or_a_sibling():
    """Each room imports only from rooms on lower floors (the package root, a lazy facade, excepted)."""
    offences = [line for name, (edges, _) in GRAPH.items() for line in _upward(name, edges)]
    assert offences == [], "\n".join(offences)


def test_the_floor_table_is_read_and_has_teeth():
    """Guards the check against passing vacuously: the table is parsed, and a planted upward import is found."""
    assert FLOORS["fourier"] == 0 and FLOORS["cli"] == max(FLOORS.values()) and FLOORS["model"] == FLOORS["vessel"]
    assert _upward("seafast.solvers.linear", {"seafast.results.dataset"}) == [
        "seafast.solvers.linear (floor 5) imports seafast.results.dataset (floor 7)"
    ]
    assert _upward("seafast.model.beam", {"seafast.vessel.loading"})  # a sibling on the same floor
    assert _upward("seafast.cli.run", {"seafast.analyses.run", "seafast", "seafast.cli.common"}) == []
