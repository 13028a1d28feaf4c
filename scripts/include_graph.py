#!/usr/bin/env python3
"""Folder-level include graph of include/gaitsynth/, and the cycles in it.

Every `#include "gaitsynth/..."` line of include/gaitsynth/**/*.hpp is an edge from the including
file's top folder (rollout, io, viz, ...) to the included file's top folder. A file directly in
include/gaitsynth/ (error.hpp, the umbrella gaitsynth.hpp) is a node of its own name, so the
umbrella headers do not tie every folder together.

    python3 scripts/include_graph.py            # prints the cycles; exit status 1 if there is one
    python3 scripts/include_graph.py --edges    # also prints every folder edge with one example
    python3 scripts/include_graph.py --dot      # the folder graph in Graphviz dot
    python3 scripts/include_graph.py --allow-cycle objectives,rollout   # tolerate a known one

A cycle is reported as a strongly connected component of two or more folders, with every include
line that makes an edge inside it, so it is clear which lines to move. --allow-cycle A,B,... (may
be repeated) tolerates a component whose folders are all in that list: a known cycle waiting for
its owners. Any other cycle, or a known one that has grown, still fails; a known one that has
gone is mentioned, so that its --allow-cycle can be dropped.
"""
import argparse
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"gaitsynth/([^"]+)"')


def node_of(rel):
    """Top folder of a path relative to include/gaitsynth/, or the file name at the top level."""
    parts = rel.split("/")
    return parts[0] if len(parts) > 1 else parts[0]


def read_edges(root):
    """{(from_folder, to_folder): [(file, line_number, included), ...]} for folder-crossing lines."""
    edges = {}
    nodes = set()
    for path in sorted(root.rglob("*.hpp")):
        rel = path.relative_to(root).as_posix()
        src = node_of(rel)
        nodes.add(src)
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            dst = node_of(m.group(1))
            nodes.add(dst)
            if dst != src:
                edges.setdefault((src, dst), []).append((rel, number, m.group(1)))
    return nodes, edges


def strongly_connected(nodes, edges):
    """Tarjan's algorithm; returns the components of two or more nodes, each sorted."""
    succ = {n: sorted({d for (s, d) in edges if s == n}) for n in nodes}
    index, low, on_stack, stack, out = {}, {}, set(), [], []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        for w in succ[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for n in sorted(nodes):
        if n not in index:
            visit(n)
    return sorted(out)


def main():
    here = pathlib.Path(__file__).resolve().parent.parent
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", type=pathlib.Path, default=here / "include" / "gaitsynth",
                    help="the include/gaitsynth folder (default: this checkout's)")
    ap.add_argument("--edges", action="store_true", help="print every folder edge")
    ap.add_argument("--dot", action="store_true", help="print the folder graph as Graphviz dot")
    ap.add_argument("--allow-cycle", action="append", default=[], metavar="A,B,...",
                    help="tolerate a cycle among these folders (repeatable)")
    args = ap.parse_args()
    allowed = [set(a.split(",")) for a in args.allow_cycle]

    nodes, edges = read_edges(args.root)
    if args.dot:
        print("digraph gaitsynth {")
        for (s, d) in sorted(edges):
            print(f'  "{s}" -> "{d}";')
        print("}")
        return 0
    if args.edges:
        for (s, d), lines in sorted(edges.items()):
            f, n, inc = lines[0]
            print(f"{s} -> {d}  ({len(lines)} lines, e.g. {f}:{n} includes {inc})")

    cycles = strongly_connected(nodes, edges)
    failed = False
    for comp in cycles:
        members = set(comp)
        known = any(members <= a for a in allowed)
        failed = failed or not known
        print(("known (allowed) include cycle between folders: " if known else
               "include cycle between folders: ") + ", ".join(comp))
        mutual = [f"{a} <-> {b}" for a in comp for b in comp if a < b and (a, b) in edges
                  and (b, a) in edges]
        if mutual:
            print("  folders that include each other: " + ", ".join(mutual))
        for (s, d), lines in sorted(edges.items()):
            if s in members and d in members:
                for f, n, inc in lines:
                    print(f"  {s} -> {d}: {f}:{n} includes gaitsynth/{inc}")
    for a in allowed:
        if not any(set(comp) & a for comp in cycles):
            print("note: the allowed cycle " + ",".join(sorted(a)) + " is gone; drop its --allow-cycle")
    if not failed:
        print(f"no folder-level include cycles ({len(nodes)} nodes, {len(edges)} folder edges)"
              + (", apart from the allowed ones" if cycles else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
