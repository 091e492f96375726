#!/usr/bin/env python3
"""Size of the product code, as issue-level budgets read it: lines of C++ per layer, the largest files and the
longest functions. Usage: tools/dev/code_size.py [--max-file N] [--max-function N] [ROOT]
A function's length runs from the line of its opening brace back to the start of its signature, to its closing
brace; lambdas and class bodies inside count toward the function that holds them. Exits 1 when a file or a function
is over its bound, so it can gate a change."""
import argparse
import os
import re
import sys

PRODUCT = ('idl', 'common', 'components', 'scenarios', 'app')
EXT = ('.cpp', '.hpp', '.h')
SIG = re.compile(r'^[A-Za-z_~][\w:<>,*&\s~\[\]]*\b([\w:~]+)\s*\([^;{}]*\)\s*(const)?\s*(noexcept)?\s*(override)?\s*'
                 r'(->\s*[\w:<>&*\s]+)?\s*(:[^;{]*)?\{\s*$')


def product_files(root):
    for top in PRODUCT:
        for dp, _, fn in os.walk(os.path.join(root, top)):
            for f in sorted(fn):
                if f.endswith(EXT):
                    yield os.path.join(dp, f)


def strip(line):
    line = re.sub(r'"(\\.|[^"\\])*"', '""', line)
    line = re.sub(r"'(\\.|[^'\\])*'", "''", line)
    return line.split('//', 1)[0]


def functions(path):
    """(name, first line, length) of every top-level or namespace-level function definition."""
    lines = open(path, encoding='utf-8').read().split('\n')
    out, depth, i = [], 0, 0
    scope = []  # kinds of open braces: 'ns', 'class', 'fn', 'other'
    while i < len(lines):
        text = strip(lines[i])
        # A definition's head may span lines: join up to 4 lines ending at an opening brace.
        opens = text.count('{')
        if opens and all(k in ('ns', 'class') for k in scope):
            head = ' '.join(strip(l).strip() for l in lines[max(0, i - 4):i + 1])
            head = head[head.rfind(';') + 1:] if ';' in head else head
            head = head[head.rfind('}') + 1:] if '}' in head else head
            m = SIG.search(head.strip())
            if m and not re.match(r'\s*(if|for|while|switch|catch|namespace|class|struct|enum)\b', head.strip()):
                start = i
                d = 0
                j = i
                while j < len(lines):
                    t = strip(lines[j])
                    d += t.count('{') - t.count('}')
                    if d <= 0 and j > i or (d == 0 and j == i and '}' in t):
                        break
                    j += 1
                sig_start = start
                while sig_start > 0 and strip(lines[sig_start - 1]).strip() and not strip(lines[sig_start - 1]).rstrip().endswith((';', '}', '{')) and start - sig_start < 4:
                    sig_start -= 1
                out.append((m.group(1), sig_start + 1, j - sig_start + 1))
                i = j + 1
                continue
        for ch in text:
            if ch == '{':
                kind = 'other'
                if re.search(r'\bnamespace\b', text):
                    kind = 'ns'
                elif re.search(r'\b(class|struct)\b', text) and '(' not in text.split('{')[0].split('struct')[-1]:
                    kind = 'class'
                scope.append(kind)
            elif ch == '}' and scope:
                scope.pop()
        i += 1
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('root', nargs='?', default=os.path.join(os.path.dirname(__file__), '..', '..'))
    ap.add_argument('--max-file', type=int, default=400)
    ap.add_argument('--max-function', type=int, default=80)
    ap.add_argument('--top', type=int, default=10)
    a = ap.parse_args()
    root = os.path.abspath(a.root)
    per_layer, files, funcs = {}, [], []
    for p in product_files(root):
        rel = os.path.relpath(p, root)
        n = sum(1 for _ in open(p, encoding='utf-8'))
        parts = rel.split('/')
        layer = '/'.join(parts[:2]) if parts[0] in ('common', 'components') else parts[0]
        per_layer[layer] = per_layer.get(layer, 0) + n
        files.append((n, rel))
        funcs += [(length, f'{rel}:{line}', name) for name, line, length in functions(p)]
    total = sum(per_layer.values())
    print(f'product C++: {total} lines in {len(files)} files')
    for layer, n in sorted(per_layer.items()):
        print(f'  {layer:32s} {n:6d}')
    files.sort(reverse=True)
    funcs.sort(reverse=True)
    print(f'largest files (bound {a.max_file}):')
    for n, rel in files[:a.top]:
        print(f'  {n:5d} {rel}')
    print(f'longest functions (bound {a.max_function}):')
    for n, where, name in funcs[:a.top]:
        print(f'  {n:5d} {where} {name}')
    over = [f for f in files if f[0] > a.max_file] + [f for f in funcs if f[0] > a.max_function]
    print(f'over the bounds: {len(over)}')
    return 1 if over else 0


if __name__ == '__main__':
    sys.exit(main())
