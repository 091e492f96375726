#!/usr/bin/env python3
"""The layering rule of docs/architecture.md, checked on the source tree: a layer includes and links only the layers
it stands on. Usage: check_layers.py SOURCE_DIR [GENERATED_INCLUDE_DIR]. Prints every violation, exits 1 on any.

Layers, by folder (lowest first; a layer may use those listed for it):
  core        common/core                 -
  msgs        idl                         -
  framework   common/framework            core msgs
  models      components/*/model          core models
  dds         common/dds                  framework core msgs
  io          common/io                   framework core msgs
  launch      common/launch               dds io framework core msgs
  client      common/client               dds framework core msgs
  components  components/* (wrappers)     io framework core msgs models components
  scenarios   scenarios                   framework core msgs models
  app         app                         everything above
Within the models and components layers, a component's files include and link only their own component's (its
folder under components/) and the rooms every component shares (SHARED_ROOMS); the GNC types two components both
use live in the core (common/core/gnc). Also: framework/component.hpp (what every component includes) compiles
without any Fast DDS header.

Namespaces (docs/architecture.md, "Namespaces"): every `namespace gdnav...` a product file declares is its folder's
(expected_namespaces), with three documented exceptions: the compatibility namespace gdnav::runtime of existing
external members (COMPAT_FILES), the aliases `namespace gdnav { namespace X = core::X; }` of the core headers, and
blocks of using-declarations only in common/core/gnc that keep the shared GNC types' names in the components'
namespaces. No other product code names gdnav::runtime."""
import os
import re
import subprocess
import sys

ALLOWED = {
    'core': set(),
    'msgs': set(),
    'framework': {'core', 'msgs'},
    'models': {'core'},
    'dds': {'framework', 'core', 'msgs'},
    'io': {'framework', 'core', 'msgs'},
    'launch': {'dds', 'io', 'framework', 'core', 'msgs'},
    'client': {'dds', 'framework', 'core', 'msgs'},
    'components': {'io', 'framework', 'core', 'msgs', 'models'},
    'scenarios': {'framework', 'core', 'msgs', 'models'},
    'app': {'launch', 'client', 'dds', 'io', 'framework', 'core', 'msgs', 'models', 'components', 'scenarios'},
}
# Folders under components/ that are shared rooms, not components: their files may be included by any component.
SHARED_ROOMS = {'gnc_inputs'}
# Files generated at build time from the IDL (fastddsgen, cmake/GdnavIdl.cmake): the message layer.
GENERATED = re.compile(r'^[A-Za-z_]+(PubSubTypes)?\.h$')
SOURCE_EXT = ('.cpp', '.hpp', '.h')
# The namespace of each component, by its folder under components/ (gdnav::<folder> unless listed).
COMPONENT_NAMESPACES = {'flight_physics': 'physics', 'gnc_inputs': 'guidance'}
# The namespaces of the core's folders (gdnav::core::<folder> unless listed) and of the launcher's rooms.
CORE_NAMESPACES = {'atmosphere': 'atm', 'random': 'rnd'}
LAUNCH_NAMESPACES = {'plan': 'deploy'}
# The files that declare the compatibility namespace gdnav::runtime (docs/external.md, "Namespaces").
COMPAT_FILES = {'common/framework/compat.hpp', 'common/dds/compat.hpp', 'idl/msgs/message_ops.hpp'}


def layer_of(rel):
    parts = rel.split('/')
    if parts[0] == 'idl':
        return 'msgs'
    if parts[0] == 'common' and len(parts) > 2:
        return {'core': 'core', 'framework': 'framework', 'dds': 'dds', 'io': 'io', 'launch': 'launch',
                'client': 'client'}.get(parts[1])
    if parts[0] == 'components' and len(parts) > 2:
        return 'models' if parts[2] == 'model' else 'components'
    if parts[0] in ('scenarios', 'app'):
        return parts[0]
    return None


def component_of(rel):
    """The folder under components/ of a file there (a component or a shared room), None elsewhere."""
    parts = rel.split('/')
    return parts[1] if parts[0] == 'components' and len(parts) >= 3 else None


def crosses(mine, theirs):
    """A file or target of folder MINE using one of folder THEIRS: refused between two folders under components/,
    unless THEIRS is a shared room."""
    return bool(mine and theirs and mine != theirs and theirs not in SHARED_ROOMS)


def product_files(root):
    for top in ('idl', 'common', 'components', 'scenarios', 'app'):
        for dp, _, fn in os.walk(os.path.join(root, top)):
            for f in fn:
                if f.endswith(SOURCE_EXT):
                    yield os.path.relpath(os.path.join(dp, f), root)


def include_roots(root):
    roots = ['common/core', 'common', 'idl', 'components', 'scenarios', 'app', 'common/client/include']
    roots += [os.path.join('components', d) for d in sorted(os.listdir(os.path.join(root, 'components')))]
    return roots


def resolve(root, rel, inc, roots):
    for base in [os.path.dirname(rel)] + roots:
        cand = os.path.normpath(os.path.join(base, inc))
        if os.path.isfile(os.path.join(root, cand)):
            return cand
    return None


def check_includes(root):
    errors = []
    roots = include_roots(root)
    for rel in product_files(root):
        me = layer_of(rel)
        if me is None:
            continue
        with open(os.path.join(root, rel), encoding='utf-8') as f:
            for n, line in enumerate(f, 1):
                m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
                if not m:
                    continue
                inc = m.group(1)
                target = resolve(root, rel, inc, roots)
                if target is None:
                    if GENERATED.match(os.path.basename(inc)):
                        other = 'msgs'
                    else:
                        errors.append(f'{rel}:{n}: cannot resolve #include "{inc}"')
                        continue
                else:
                    other = layer_of(target)
                    mine, theirs = component_of(rel), component_of(target)
                    if crosses(mine, theirs):
                        errors.append(f'{rel}:{n}: components/{mine} includes components/{theirs} ("{inc}")')
                        continue
                if other is None or other == me:
                    continue
                if other not in ALLOWED[me]:
                    errors.append(f'{rel}:{n}: {me} includes {other} ("{inc}")')
    return errors


def cmake_targets(root):
    """target -> layer, target -> [linked names], target -> component folder, from add_library/add_executable and
    target_link_libraries."""
    defined, links, folder = {}, {}, {}
    for rel in product_files_cmake(root):
        text = open(os.path.join(root, rel), encoding='utf-8').read()
        text = re.sub(r'#[^\n]*', '', text)
        layer = layer_of(os.path.dirname(rel) + '/CMakeLists.txt') if os.path.dirname(rel) else None
        for m in re.finditer(r'(?:add_library|add_executable|gdnav_idl_library)\(\s*([A-Za-z0-9_]+)', text):
            defined[m.group(1)] = layer
            folder[m.group(1)] = component_of(rel)
        for m in re.finditer(r'target_link_libraries\(\s*([A-Za-z0-9_]+)([^)]*)\)', text):
            names = [w for w in m.group(2).split() if w.startswith('gdnav_')]
            links.setdefault(m.group(1), []).extend(names)
    return defined, links, folder


def product_files_cmake(root):
    for top in ('idl', 'common', 'components', 'scenarios', 'app'):
        for dp, _, fn in os.walk(os.path.join(root, top)):
            if 'CMakeLists.txt' in fn:
                yield os.path.relpath(os.path.join(dp, 'CMakeLists.txt'), root)


def check_links(root):
    errors = []
    defined, links, folder = cmake_targets(root)
    for target, names in sorted(links.items()):
        me = defined.get(target)
        if me is None:
            continue
        for name in names:
            if crosses(folder.get(target), folder.get(name)):
                errors.append(f'CMake: {target} (components/{folder[target]}) links {name} (components/{folder[name]})')
                continue
            other = defined.get(name)
            if other is None or other == me:
                continue
            if other not in ALLOWED[me]:
                errors.append(f'CMake: {target} ({me}) links {name} ({other})')
    return errors


def check_component_header(root, generated):
    cmd = ['c++', '-std=c++20', '-M', '-x', 'c++', '-I', os.path.join(root, 'common/core'), '-I',
           os.path.join(root, 'common'), '-I', os.path.join(root, 'idl'), '-isystem', '/usr/include/eigen3']
    if generated:
        cmd += ['-isystem', generated]
    cmd.append(os.path.join(root, 'common/framework/component.hpp'))
    out = subprocess.run(cmd, capture_output=True, text=True)
    if out.returncode != 0:
        return ['framework/component.hpp does not compile on its own: ' + out.stderr.strip().splitlines()[0]]
    dds = [w for w in out.stdout.split() if '/fastdds/' in w or '/fastrtps/' in w]
    return [f'framework/component.hpp pulls Fast DDS headers: {dds[0]} ...'] if dds else []


def expected_namespaces(rel):
    """The namespaces (each with those nested in it) a product file REL may declare; None: not checked."""
    parts = rel.split('/')
    sub = parts[2] if len(parts) > 3 else None  # the room: common/<layer>/<room>/<file>
    if parts[0] == 'common':
        layer = parts[1]
        if layer == 'core':
            return [f'gdnav::core::{CORE_NAMESPACES.get(sub, sub)}'] if sub else ['gdnav::core']
        if layer in ('framework', 'dds'):
            return [f'gdnav::{layer}']
        if layer == 'io':
            return [f'gdnav::io::{sub}'] if sub else ['gdnav::io']
        if layer == 'launch':
            return [f'gdnav::launch::{LAUNCH_NAMESPACES.get(sub, sub)}'] if sub else ['gdnav::launch']
        if layer == 'client':
            return [f'gdnav::client::{sub}'] if sub in ('python', 'embed') else ['gdnav::client']
        return None
    if parts[0] == 'components' and len(parts) > 2:
        return [f'gdnav::{COMPONENT_NAMESPACES.get(parts[1], parts[1])}']
    return {'idl': ['gdnav::msg', 'gdnav::topics'], 'scenarios': ['gdnav::scenario'], 'app': ['gdnav::cli']}.get(parts[0])


def code_only(text):
    """TEXT with comments and string literals blanked (line numbers kept)."""
    pat = re.compile(r"""//[^\n]*|/\*.*?\*/|R"([^(\s]*)\(.*?\)\1"|"(?:\\.|[^"\\\n])*"|'(?:\\.|[^'\\\n])+'""", re.S)
    return pat.sub(lambda m: re.sub(r'[^\n]', ' ', m.group(0)), text)


CORE_ALIAS = re.compile(r'namespace\s+gdnav\s*\{\s*namespace\s+(\w+)\s*=\s*core::(\w+)\s*;\s*\}')


def declared_namespaces(text):
    """(line, full name, body) of every named namespace block of TEXT (code only), nested names joined."""
    out, stack = [], []
    for m in re.finditer(r'\bnamespace\s+((?:::)?\w+(?:\s*::\s*\w+)*)\s*\{|\{|\}', text):
        tok = m.group(0)
        if m.group(1):
            name = re.sub(r'\s+', '', m.group(1)).lstrip(':')
            full = '::'.join([f for f in stack if f] + [name])
            stack.append(name)
            out.append([text.count('\n', 0, m.start()) + 1, full, m.end(), None])
        elif tok == '{':
            stack.append(None)
        elif stack:
            name = stack.pop()
            if name is not None:
                for entry in reversed(out):
                    if entry[3] is None and entry[1].endswith(name):
                        entry[3] = text[entry[2]:m.start()]
                        break
    return [(line, full, body or '') for line, full, _, body in out]


def check_namespaces(root):
    errors = []
    for rel in product_files(root):
        allowed = expected_namespaces(rel)
        if allowed is None:
            continue
        with open(os.path.join(root, rel), encoding='utf-8') as f:
            text = code_only(f.read())
        for m in CORE_ALIAS.finditer(text):
            if not rel.startswith('common/core/') or m.group(1) != m.group(2):
                errors.append(f'{rel}: namespace alias gdnav::{m.group(1)}: only the core headers keep short names')
        text = CORE_ALIAS.sub(lambda m: re.sub(r'[^\n]', ' ', m.group(0)), text)
        for line, full, body in declared_namespaces(text):
            if full != 'gdnav' and not full.startswith('gdnav::'):
                continue
            if full == 'gdnav::runtime' or full.startswith('gdnav::runtime::'):
                if rel not in COMPAT_FILES:
                    errors.append(f'{rel}:{line}: namespace {full}: only the compatibility headers declare it')
                continue
            if rel.startswith('common/core/gnc/') and body.strip() and \
                    all(s.strip().startswith('using ') for s in body.split(';') if s.strip()):
                continue  # the shared GNC types' names in a component's namespace
            if not any(full == a or full.startswith(a + '::') or (a.startswith(full + '::') and body.strip() == '')
                       for a in allowed):
                errors.append(f'{rel}:{line}: namespace {full} is not of its folder (expected {" or ".join(allowed)})')
        for n, line in enumerate(text.splitlines(), 1):
            if rel not in COMPAT_FILES and re.search(r'(?<![\w:])(?:::)?(?:gdnav::runtime\b|runtime::)', line):
                errors.append(f'{rel}:{n}: names gdnav::runtime (kept for existing external members only)')
    return errors


def main():
    root = os.path.abspath(sys.argv[1])
    generated = sys.argv[2] if len(sys.argv) > 2 else None
    errors = check_includes(root) + check_links(root) + check_component_header(root, generated) + \
        check_namespaces(root)
    for e in errors:
        print(e)
    n_files = sum(1 for _ in product_files(root))
    print(f'layers: {n_files} product files, {len(errors)} violation(s)')
    return 1 if errors else 0


if __name__ == '__main__':
    sys.exit(main())
