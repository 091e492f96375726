#!/usr/bin/python3
"""The installed package's client closure (docs/external.md): everything a member author's target links through
gdnav::client, read from the installed CMake package files, holds no OpenSSL, launch layer, Python or MPI, and the
package's config asks for none of them.

  tests/integration/external/client_closure.py PREFIX

PREFIX is a `cmake --install` prefix (the ExamplesPackage fixture's <build>/install). Prints the closure; exits 1
naming what is forbidden, 2 on bad input."""
import os
import re
import sys

FORBIDDEN = re.compile(r'ssl|crypto|launch|python|mpi', re.IGNORECASE)


def fail(msg, code=1):
    print(f"client_closure: {msg}", file=sys.stderr)
    sys.exit(code)


def link_libraries(text):
    """Target name -> the items of its INTERFACE_LINK_LIBRARIES (and IMPORTED_LINK_* lists) in the targets files."""
    deps = {}
    for m in re.finditer(r'set_target_properties\((\S+) PROPERTIES(.*?)\n\)', text, re.S):
        items = []
        for prop in re.finditer(r'(INTERFACE_LINK_LIBRARIES|IMPORTED_LINK_\w+)\s+"([^"]*)"', m.group(2)):
            items += [i for i in prop.group(2).split(';') if i]
        deps.setdefault(m.group(1), []).extend(items)
    return deps


def closure(deps, root):
    seen, todo = [], [root]
    while todo:
        t = todo.pop()
        if t in seen:
            continue
        seen.append(t)
        for item in deps.get(t, []):
            inner = re.sub(r'^\$<LINK_ONLY:(.*)>$', r'\1', item)
            todo.append(inner)
    return seen


def main():
    if len(sys.argv) != 2:
        fail("usage: client_closure.py PREFIX", 2)
    pkg = os.path.join(sys.argv[1], 'lib', 'cmake', 'gdnav')
    if not os.path.isdir(pkg):
        fail(f"'{pkg}' not found (not a gdnav install prefix)", 2)
    text = ''
    for f in sorted(os.listdir(pkg)):
        if f.startswith('gdnavTargets') and f.endswith('.cmake'):
            with open(os.path.join(pkg, f)) as fh:
                text += fh.read() + '\n'
    deps = link_libraries(text)
    if 'gdnav::client' not in deps:
        fail(f"no gdnav::client in {pkg}", 2)
    items = closure(deps, 'gdnav::client')
    print('gdnav::client links: ' + ', '.join(items[1:]))
    bad = [i for i in items if FORBIDDEN.search(i)]
    with open(os.path.join(pkg, 'gdnavConfig.cmake')) as fh:
        bad += [d for d in re.findall(r'find_dependency\((\w+)', fh.read()) if FORBIDDEN.search(d)]
    if bad:
        fail("the installed client needs " + ', '.join(bad) + " (none of OpenSSL, the launch layer, Python or MPI "
             "may reach a member author's link line)")
    print('client closure: no OpenSSL, launch, Python or MPI')


main()
