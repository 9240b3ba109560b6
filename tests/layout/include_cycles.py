#!/usr/bin/env python3
"""Include cycles between units (issue 23): a unit is X.h with its X.cc; unit A depends on
unit B when A.h or A.cc includes "B.h". Prints every cycle (strongly connected set of more
than one unit) and fails if there is one. Run by .ci/run.
    python3 tests/layout/include_cycles.py"""
import os
import re
import subprocess
import sys

root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
files = subprocess.run(['git', 'ls-files', 'common', 'services', 'clients', 'tools'], cwd=root,
                       capture_output=True, text=True, check=True).stdout.split()
files = [f for f in files if f.endswith(('.h', '.cc'))]
include = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)

def unit(path):
    return os.path.splitext(path)[0]

headers = {f for f in files if f.endswith('.h')}
# "design/search/witness.h" is found as common/design/search/witness.h
by_include = {}
for h in headers:
    parts = h.split('/')
    for i in range(len(parts)):
        by_include.setdefault('/'.join(parts[i:]), h)

edges = {}
for f in files:
    with open(os.path.join(root, f), encoding='utf-8') as text:
        for name in include.findall(text.read()):
            target = by_include.get(name) or by_include.get(os.path.join(os.path.dirname(f), name))
            if target and unit(target) != unit(f):
                edges.setdefault(unit(f), set()).add(unit(target))

# Tarjan's strongly connected components, iteratively.
index, low, on_stack, stack, cycles, counter = {}, {}, set(), [], [], [0]
nodes = sorted(set(edges) | {b for bs in edges.values() for b in bs})
for start in nodes:
    if start in index:
        continue
    work = [(start, iter(sorted(edges.get(start, ()))))]
    index[start] = low[start] = counter[0]; counter[0] += 1
    stack.append(start); on_stack.add(start)
    while work:
        node, successors = work[-1]
        advanced = False
        for nxt in successors:
            if nxt not in index:
                index[nxt] = low[nxt] = counter[0]; counter[0] += 1
                stack.append(nxt); on_stack.add(nxt)
                work.append((nxt, iter(sorted(edges.get(nxt, ())))))
                advanced = True
                break
            if nxt in on_stack:
                low[node] = min(low[node], index[nxt])
        if advanced:
            continue
        work.pop()
        if work:
            low[work[-1][0]] = min(low[work[-1][0]], low[node])
        if low[node] == index[node]:
            component = []
            while True:
                top = stack.pop(); on_stack.discard(top); component.append(top)
                if top == node:
                    break
            if len(component) > 1:
                cycles.append(sorted(component))

if cycles:
    print('include cycles between units (X.h with X.cc):')
    for c in cycles:
        print('  ' + ' <-> '.join(c))
    sys.exit(1)
print(f'include cycles: none among {len(nodes)} units')
