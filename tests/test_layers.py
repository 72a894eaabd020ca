"""The house: stage subpackages, the layers contract, no import cycle, a small public root.

The contract itself is in pyproject.toml (``[tool.importlinter]``); import-linter checks it, and
this file checks what a layers contract does not: cycles between the modules of one package
(imports inside functions counted), the size of the root, and each stage's stated imports.
"""
from __future__ import annotations

import ast
import subprocess
import sys
import warnings
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "derive"


def _modules() -> dict[str, Path]:
    out = {}
    for path in PACKAGE.rglob("*.py"):
        rel = path.relative_to(ROOT).with_suffix("")
        if "baselines" in rel.parts:  # the bench's rivals: data it loads, not modules of derive
            continue
        name = ".".join(rel.parts[:-1] if rel.name == "__init__" else rel.parts)
        out[name] = path
    return out


def _imports(modules: dict[str, Path]) -> dict[str, set[str]]:
    """Every derive module each module imports, at module level or inside a function."""
    graph = {}
    for name, path in modules.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        found = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    parts = package.split(".")[: len(package.split(".")) - node.level + 1]
                    base = ".".join(parts + ([node.module] if node.module else []))
                for alias in node.names:
                    full = f"{base}.{alias.name}"
                    found.add(full if full in modules else base)
            elif isinstance(node, ast.Import):
                found.update(a.name for a in node.names)
        graph[name] = {m for m in found if m in modules and m != name}
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
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
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def _imports_by_grimp(modules: dict[str, Path]) -> dict[str, set[str]] | None:
    """:func:`_imports` as grimp (import-linter's graph builder) reads them: every import
    statement, inside functions too, parsed by its compiled parser; None without grimp or
    when the ``derive`` it would find is not this checkout's."""
    import derive

    try:
        import grimp
    except ImportError:
        return None
    if Path(derive.__file__).resolve().parent != PACKAGE.resolve():
        return None
    built = grimp.build_graph("derive", cache_dir=None)
    return {name: {m for m in built.find_modules_directly_imported_by(name) if m in modules and m != name}
            for name in modules}


@pytest.fixture(scope="module")
def graph() -> dict[str, set[str]]:
    """derive's import graph (every module read once for the tests that read it)."""
    modules = _modules()
    return _imports_by_grimp(modules) or _imports(modules)


def test_grimp_counts_an_import_inside_a_function(tmp_path, monkeypatch):
    """The graph grimp builds holds an import made inside a function, as :func:`_imports` does
    (the cycles such an import closes are the ones a layers contract does not see)."""
    grimp = pytest.importorskip("grimp")
    package = tmp_path / "toy_layers"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "a.py").write_text("def f():\n    from toy_layers import b\n    return b\n")
    (package / "b.py").write_text("import toy_layers.a\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    built = grimp.build_graph("toy_layers", cache_dir=None)
    assert built.find_modules_directly_imported_by("toy_layers.a") == {"toy_layers.b"}
    modules = {"toy_layers.a": package / "a.py", "toy_layers.b": package / "b.py"}
    assert _cycles(_imports(modules)) == [["toy_layers.a", "toy_layers.b"]]


def test_no_import_cycle_counting_imports_inside_functions(graph):
    assert len(graph) > 40
    assert _cycles(graph) == []


def test_the_cycle_check_finds_a_cycle_hidden_in_a_function():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert _cycles(graph) == [["a", "b", "c"]]


def test_the_layers_contract_is_kept():
    pytest.importorskip("importlinter")
    r = subprocess.run([sys.executable, "-c", "import sys; from importlinter.cli import lint_imports; "
                        "sys.exit(lint_imports())"], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-2000:]
    assert "1 kept, 0 broken" in r.stdout


def test_the_root_keeps_the_public_face_only():
    root = sorted(p.name for p in PACKAGE.glob("*.py"))
    assert len(root) <= 12, root
    stages = sorted(p.parent.name for p in PACKAGE.glob("*/__init__.py"))
    assert {"symbolic", "methods", "codegen", "runtime", "sim", "sweeps", "lecture", "bench",
            "reference"} <= set(stages)


def test_each_stage_says_what_it_may_import():
    for init in sorted(PACKAGE.glob("*/__init__.py")):
        doc = ast.get_docstring(ast.parse(init.read_text(encoding="utf-8"))) or ""
        assert "May import" in doc, init


def test_nothing_outside_the_bench_imports_it_but_the_command_line(graph):
    users = sorted(m for m, deps in graph.items() if not m.startswith("derive.bench")
                   and any(d.startswith("derive.bench") for d in deps))
    assert users == ["derive.cli"]


def test_every_module_compiles_without_a_warning():
    # an invalid escape in a docstring (``\i`` for ``\\i``) is a warning today and an error in a later Python
    for name, path in _modules().items():
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            compile(path.read_text(encoding="utf-8"), str(path), "exec")
