"""The map of the code stays true: every module of `physink_tui` is named, by its file name, in the docstring of its
package or of a package around it (the tables `docs/ARCHITECTURE.md` points a newcomer to), or in ARCHITECTURE.md."""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "physink_tui"


def _docstrings() -> dict[Path, str]:
    return {init.parent: ast.get_docstring(ast.parse(init.read_text(encoding="utf-8"))) or ""
            for init in PACKAGE.rglob("__init__.py")}


def _named(module: Path, docs: dict[Path, str], architecture: str) -> bool:
    if module.relative_to(PACKAGE).as_posix() in architecture or module.name in architecture:
        return True
    for package in (module.parent, *module.parent.parents):
        doc = docs.get(package)
        if doc is None:
            continue
        if module.relative_to(package).as_posix() in doc:
            return True
        if package == module.parent and (f"`{module.stem}`" in doc or f"{module.stem}." in doc):
            return True
    return False


def test_every_module_is_named_where_a_newcomer_looks() -> None:
    docs = _docstrings()
    architecture = (ROOT / "docs" / "ARCHITECTURE.md").read_text(encoding="utf-8")
    modules = [m for m in sorted(PACKAGE.rglob("*.py")) if m.name != "__init__.py"]
    assert len(modules) > 250, "the package was not found where the test looks"
    unnamed = [m.relative_to(ROOT).as_posix() for m in modules if not _named(m, docs, architecture)]
    assert not unnamed, ("modules no package docstring (nor docs/ARCHITECTURE.md) names; add a line for each to its "
                         "package's __init__.py docstring: " + ", ".join(unnamed))


def test_the_check_notices_a_module_nobody_named() -> None:
    docs = _docstrings()
    stray = PACKAGE / "scene" / "recognition" / "a_module_nobody_wrote.py"
    assert not _named(stray, docs, "")
    assert _named(PACKAGE / "scene" / "recognition" / "recognize.py", docs, "")
