"""No two modules of physink_tui import each other, directly or round a longer loop (function-level imports count).

grimp (installed with import-linter) builds the import graph from the source, nested imports included; the
strongly connected components of that graph with more than one module are the cycles. STYLE.md: "two files that
import each other are one design decision waiting to be made".
"""

from __future__ import annotations

import grimp

ALLOWED_CYCLE_MODULES: frozenset[str] = frozenset()  # no module may take part in an import cycle
"""Modules a cycle may run through for now; a cycle with any module outside this set fails the test."""


def strongly_connected(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan's algorithm, without recursion)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    for root in sorted(graph):
        if root in index:
            continue
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        work = [(root, iter(sorted(graph[root])))]
        while work:
            node, edges = work[-1]
            for nxt in edges:
                if nxt not in graph:
                    continue
                if nxt not in index:
                    index[nxt] = low[nxt] = len(index)
                    stack.append(nxt)
                    on_stack.add(nxt)
                    work.append((nxt, iter(sorted(graph[nxt]))))
                    break
                if nxt in on_stack:
                    low[node] = min(low[node], index[nxt])
            else:
                work.pop()
                if work:
                    parent = work[-1][0]
                    low[parent] = min(low[parent], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    if len(component) > 1:
                        found.append(sorted(component))
    return found


def test_strongly_connected_finds_loops_and_only_loops() -> None:
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": {"f"}, "f": {"e", "x"}}
    assert sorted(strongly_connected(graph)) == [["a", "b", "c"], ["e", "f"]]
    assert strongly_connected({"a": {"b"}, "b": set()}) == []


def test_no_module_import_cycles() -> None:
    graph = grimp.build_graph("physink_tui")
    edges = {m: set(graph.find_modules_directly_imported_by(m)) for m in graph.modules}
    cycles = [c for c in strongly_connected(edges) if not set(c) <= ALLOWED_CYCLE_MODULES]
    described = []
    for component in cycles:
        chain = graph.find_shortest_chain(importer=component[0], imported=component[1]) or ()
        back = graph.find_shortest_chain(importer=component[1], imported=component[0]) or ()
        described.append(f"{component}: {' -> '.join(chain)} and {' -> '.join(back)}")
    assert not cycles, "modules importing each other:\n" + "\n".join(described)
