#!/usr/bin/python3
"""Generates the field tables of the IDL message types (framework/fields/field_table.hpp) from an IDL file.

    gen_fields.py IDL OUT.cpp

Reads the modules, constants, enums and structs of the IDL (the subset gdnav uses) and writes, for every struct whose
members are all supported, a table of its fields: dotted name (nested structs are flattened: "stamp.t_s"), kind,
element count and accessors into the fastddsgen-generated C++ class (whose getters return references:
`double& h_m()`, `std::array<double, 3>& v_n_mps()`, `SampleStamp& stamp()`, `fixed_string<N>& name()`).
Supported members: double, boolean, octet, unsigned long, unsigned long long (scalars or one-dimensional arrays of
them), bounded strings, enums and structs of supported members. A struct with any other member (a sequence, a
long, ...) gets no table; it is listed in a comment of the output. Errors name the IDL line.
"""
import re
import sys

PRIMITIVES = {"double": "F64", "boolean": "Bool", "octet": "U8", "unsigned long": "U32", "unsigned long long": "U64"}
TOKEN = re.compile(r"\s*(::|[A-Za-z_][A-Za-z_0-9]*|\d+|[{}<>\[\];,=()\"-]|\S)")


class IdlError(Exception):
    pass


def tokenize(text):
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    out = []
    for line_no, line in enumerate(text.splitlines(), 1):
        line = line.split("//", 1)[0]
        out += [(t, line_no) for t in TOKEN.findall(line) if t.strip()]
    return out


class Parser:
    def __init__(self, tokens):
        self.toks, self.i = tokens, 0
        self.structs, self.enums, self.order = {}, {}, []  # qualified name -> members / values

    def peek(self, ahead=0):
        j = self.i + ahead
        return self.toks[j][0] if j < len(self.toks) else None

    def line(self):
        return self.toks[min(self.i, len(self.toks) - 1)][1] if self.toks else 0

    def take(self, expected=None):
        if self.i >= len(self.toks):
            raise IdlError(f"unexpected end of file (expected {expected or 'more'})")
        tok = self.toks[self.i][0]
        if expected is not None and tok != expected:
            raise IdlError(f"line {self.line()}: expected '{expected}', got '{tok}'")
        self.i += 1
        return tok

    def skip_to(self, tok):
        while self.take() != tok:
            pass

    def definitions(self, scope, end):
        while self.peek() != end:
            kw = self.take()
            if kw == "module":
                name = self.take()
                self.take("{")
                self.definitions(scope + [name], "}")
                self.take("}")
                self.take(";")
            elif kw == "struct":
                self.struct(scope)
            elif kw == "enum":
                name = self.take()
                self.take("{")
                values = [self.take()]
                while self.take() == ",":
                    values.append(self.take())
                self.take(";")
                self.enums["::".join(scope + [name])] = values
            elif kw in ("const", "typedef"):
                self.skip_to(";")
            elif kw is None:
                raise IdlError("unexpected end of file")
            else:
                raise IdlError(f"line {self.line()}: unsupported IDL construct '{kw}'")

    def type_name(self):
        words = [self.take()]
        if words[0] == "unsigned":
            words.append(self.take())
            if self.peek() == "long":
                words.append(self.take())
        elif words[0] == "long" and self.peek() == "long":
            words.append(self.take())
        elif words[0] in ("string", "sequence") and self.peek() == "<":
            depth, inner = 0, []
            while True:
                tok = self.take()
                depth += tok == "<"
                depth -= tok == ">"
                inner.append(tok)
                if depth == 0:
                    break
            return words[0] + "".join(inner)
        while self.peek() == "::":
            words[-1] += self.take() + self.take()
        return " ".join(words)

    def struct(self, scope):
        name = self.take()
        self.take("{")
        members = []
        while self.peek() != "}":
            line = self.line()
            t = self.type_name()
            member = self.take()
            count = None
            if self.peek() == "[":
                self.take("[")
                count = int(self.take())
                self.take("]")
                if self.peek() == "[":
                    t = "<multi-dimensional array>"
                    self.skip_to(";")
                    members.append((t, member, count, line))
                    continue
            self.take(";")
            members.append((t, member, count, line))
        self.take("}")
        self.take(";")
        qualified = "::".join(scope + [name])
        self.structs[qualified] = (scope, members)
        self.order.append(qualified)


def resolve(parser, scope, name, table):
    """Finds `name` as seen from `scope` in `table` (innermost scope first)."""
    name = name.lstrip(":")
    for n in range(len(scope), -1, -1):
        candidate = "::".join(scope[:n] + [name])
        if candidate in table:
            return candidate
    return None


def fields_of(parser, qualified, path=(), seen=()):
    """[(dotted name, kind, count, accessor path, extra)] or raises IdlError naming the unsupported member."""
    if qualified in seen:
        raise IdlError(f"struct {qualified} contains itself")
    scope, members = parser.structs[qualified]
    out = []
    for t, member, count, line in members:
        here = path + (member,)
        dotted = ".".join(here)
        m = re.fullmatch(r"string<(\d+)>", t)
        if t in PRIMITIVES:
            out.append((dotted, PRIMITIVES[t], count or 1, here, count is not None))
        elif m and count is None:
            out.append((dotted, "String", int(m.group(1)), here, False))
        elif (e := resolve(parser, scope, t, parser.enums)) and count is None:
            out.append((dotted, "Enum", 1, here, ",".join(parser.enums[e])))
        elif (s := resolve(parser, scope, t, parser.structs)) and count is None:
            out += fields_of(parser, s, here, seen + (qualified,))
        else:
            what = f"{t}[{count}]" if count is not None else t
            raise IdlError(f"member '{dotted}' ({what}, line {line}) is not supported")
    return out


def cxx(qualified):
    return "::" + qualified


def emit(parser, idl_name):
    tables, skipped = [], []
    for q in parser.order:
        try:
            tables.append((q, fields_of(parser, q)))
        except IdlError as e:
            skipped.append(f"{q}: {e}")
    out = [f"// Generated by common/client/python/gen_fields.py from {idl_name}. Do not edit.",
           "// Structs without a table (a member the bindings do not support):"]
    out += [f"//   {s}" for s in skipped] or ["//   none"]
    out += ["#include <array>", "#include <string>", "#include <string_view>", "#include <type_traits>", "",
            '#include "framework/fields/field_table.hpp"', f'#include "{idl_name.rsplit(".", 1)[0]}.h"', "",
            "namespace gdnav::framework::fields {", "namespace {", ""]
    for q, fields in tables:
        T = cxx(q)
        ident = q.replace("::", "_")
        out.append(f"const Field k_{ident}[] = {{")
        for dotted, kind, count, acc, extra in fields:
            expr = f"static_cast<{T}*>(m)->" + "().".join(acc) + "()"
            cexpr = f"static_cast<const {T}*>(m)->" + "().".join(acc) + "()"
            if kind == "String":
                get = "[](const void* m) { return " + cexpr + ".to_string(); }"
                put = "[](void* m, const std::string& s) { " + expr + " = s.c_str(); }"
                line = f'{{"{dotted}", Kind::String, {count}, nullptr, {get}, {put}, nullptr}},'
            else:
                ptr = ("[](void* m) -> void* { return " + expr + ".data(); }") if extra is True else \
                      ("[](void* m) -> void* { return &" + expr + "; }")
                values = f'"{extra}"' if kind == "Enum" else "nullptr"
                line = f'{{"{dotted}", Kind::{kind}, {count}, {ptr}, nullptr, nullptr, {values}}},'
            out.append("    " + line)
        out.append("};")
        for dotted, kind, count, acc, extra in fields:
            if extra is True:  # arrays: the IDL length is the generated std::array's
                getter = "().".join(acc) + "()"
                out.append(f"static_assert(std::tuple_size_v<std::remove_reference_t<decltype(std::declval<{T}&>()."
                           f"{getter})>> == {count});")
        out.append("")
    out += ["}  // namespace", "", "const TypeFields* find_type_fields(std::string_view type_name) {",
            "    static const TypeFields all[] = {"]
    for q, fields in tables:
        out.append(f'        {{"{q}", k_{q.replace("::", "_")}, std::size(k_{q.replace("::", "_")})}},')
    out += ["    };", "    for (const TypeFields& t : all)", "        if (type_name == t.type_name) return &t;",
            "    return nullptr;", "}", "", "}  // namespace gdnav::framework::fields", ""]
    return "\n".join(out)


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    idl, dest = argv[1], argv[2]
    try:
        with open(idl, encoding="utf-8") as f:
            parser = Parser(tokenize(f.read()))
        parser.definitions([], None)
        text = emit(parser, idl.replace("\\", "/").rsplit("/", 1)[-1])
    except (IdlError, OSError, ValueError) as e:
        sys.stderr.write(f"gen_fields.py: {idl}: {e}\n")
        return 1
    with open(dest, "w", encoding="utf-8") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
