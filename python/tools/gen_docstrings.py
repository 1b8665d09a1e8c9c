#!/usr/bin/env python3
"""Extracts the `///` doc comments of poinsot's public headers into one C++ header of string constants.

The Python bindings take their docstrings from that generated header (``POINSOT_DOC(key)``), so the C++ docs
are the one source of both: nothing is kept twice by hand. CMake runs this script at build time whenever a
header changes; a binding that names a key no header documents fails to compile.

Keys: the qualified name without ``poinsot::`` and with ``::`` replaced by ``_``, e.g.
``dynamics_RigidBody_from_principal_moments``; the n-th overload (n >= 2) of a name gets ``_n``; a file's
``/// @file`` block is ``file_<layer>_<stem>``; a documented class or struct is ``<ns>_<Class>``; members
documented with a trailing ``///<`` are keys too (``dynamics_IntegratorOptions_dt``).

Usage: gen_docstrings.py --out docstrings.hpp --root include/poinsot HEADER...
       (also importable: ``extract(paths, root)`` returns {key: text}).
"""
from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

_IDENT = r"[A-Za-z_][A-Za-z_0-9]*"
_SCOPE_RE = re.compile(rf"^\s*(?:template\s*<[^>]*>\s*)?(namespace|class|struct)\s+({_IDENT}(?:::{_IDENT})*)")
_USING_RE = re.compile(rf"^\s*using\s+({_IDENT})\s*=")
_CALL_RE = re.compile(rf"(~?{_IDENT}|operator\S+)\s*\(")
_VAR_RE = re.compile(rf"({_IDENT})\s*(?:=[^;]*|\{{[^}}]*\}})?;")
_SKIP_WORDS = {"if", "for", "while", "switch", "return", "sizeof", "static_assert", "decltype", "alignof"}


def _code_part(line: str) -> str:
    """The line without its // comment (string literals in headers do not contain //)."""
    i = line.find("//")
    return line if i < 0 else line[:i]


def _decl_name(decl: str) -> str | None:
    """The name a declaration introduces: function, constructor, using-alias, class or variable."""
    m = _USING_RE.match(decl)
    if m:
        return m.group(1)
    m = _SCOPE_RE.match(decl)
    if m and m.group(1) != "namespace":
        return m.group(2)
    eq, paren = decl.find("="), decl.find("(")
    if eq >= 0 and (paren < 0 or eq < paren) and "operator" not in decl[:eq]:
        m = re.search(rf"({_IDENT})\s*$", decl[:eq])
        return m.group(1) if m else None
    head = decl.split("{")[0] if "(" not in decl.split("{")[0] and "{" in decl else decl
    for m in _CALL_RE.finditer(head):
        if m.group(1) not in _SKIP_WORDS:
            return m.group(1)
    m = _VAR_RE.search(decl)
    return m.group(1) if m else None


class _Extractor:
    def __init__(self) -> None:
        self.docs: dict[str, str] = {}
        self.counts: dict[str, int] = {}

    def add(self, scope: list[str], name: str, text: str) -> None:
        parts = [s.removeprefix("poinsot::") for s in scope if s and s != "poinsot"] + [name]
        key = "_".join(p.replace("::", "_") for p in parts).replace("~", "destructor_")
        key = re.sub(r"\W", "_", key)  # operators and anything else that is not an identifier
        n = self.counts.get(key, 0) + 1
        self.counts[key] = n
        if n > 1:
            key = f"{key}_{n}"
        self.docs[key] = text.rstrip()

    def file(self, path: Path, root: Path) -> None:
        rel = path.relative_to(root)
        lines = path.read_text(encoding="utf-8").splitlines()
        # scope stack entries: (name or "", brace depth at which it opened)
        stack: list[tuple[str, int]] = []
        depth = 0
        pending: list[str] = []
        decl_buf: list[str] = []
        last_name: str | None = None
        i = 0
        while i < len(lines):
            line = lines[i]
            stripped = line.strip()
            if stripped.startswith("/// @file"):
                block = []
                i += 1
                while i < len(lines) and lines[i].strip().startswith("///"):
                    body = lines[i].strip()[3:]
                    block.append(body[1:] if body.startswith(" ") else body)
                    i += 1
                if block:
                    self.add([], f"file_{'_'.join(rel.with_suffix('').parts)}", "\n".join(block).strip())
                continue
            if stripped.startswith("///") and not stripped.startswith("///<"):
                body = stripped[3:]
                pending.append(body[1:] if body.startswith(" ") else body)
                i += 1
                continue
            code = _code_part(line)
            scope_names = [s for s, _ in stack if s]
            in_named_scope = not stack or bool(stack[-1][0])
            if pending and code.strip():
                decl_buf.append(code.strip())
                joined = " ".join(decl_buf)
                if ";" in joined or "{" in joined or (")" in joined and joined.count("(") == joined.count(")")):
                    name = _decl_name(joined)
                    if name:
                        self.add(scope_names, name, "\n".join(pending))
                        last_name = name
                    pending, decl_buf = [], []
            elif code.strip():
                name = _decl_name(code.strip())
                if name and in_named_scope and not code.strip().startswith("}"):
                    last_name = name
            trailing = line.find("///<")
            if trailing >= 0:
                text = line[trailing + 4 :].strip()
                code_here = line[:trailing].strip()
                name = _decl_name(code_here) if code_here and not code_here.startswith("}") else last_name
                if name:
                    self.add(scope_names, name, text)
            # scopes opened and closed on this line
            m = _SCOPE_RE.match(code)
            opens, closes = code.count("{"), code.count("}")
            if m and opens and not code.rstrip().endswith(";"):
                stack.append((m.group(2), depth))
                depth += 1
                opens -= 1
            for _ in range(opens):
                stack.append(("", depth))
                depth += 1
            for _ in range(closes):
                if stack:
                    stack.pop()
                depth = max(0, depth - 1)
            i += 1


def extract(paths: list[Path], root: Path) -> dict[str, str]:
    ex = _Extractor()
    for p in sorted(paths):
        ex.file(Path(p), Path(root))
    return ex.docs


def render(docs: dict[str, str]) -> str:
    out = [
        "#pragma once",
        "// Generated by python/tools/gen_docstrings.py from the /// comments of include/poinsot/**/*.hpp.",
        "// Do not edit: change the header's doc comment instead.",
        "",
        "namespace poinsot::python::doc {",
    ]
    for key in sorted(docs):
        text = docs[key]
        if ')doc"' in text:
            text = text.replace(')doc"', ') doc"')
        out.append(f'inline constexpr const char* {key} = R"doc({text})doc";')
    out += ["}  // namespace poinsot::python::doc", "", "#define POINSOT_DOC(key) ::poinsot::python::doc::key", ""]
    return "\n".join(out)


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--root", required=True, help="include/poinsot")
    ap.add_argument("headers", nargs="+")
    a = ap.parse_args(argv)
    text = render(extract([Path(h) for h in a.headers], Path(a.root)))
    out = Path(a.out)
    if not out.exists() or out.read_text(encoding="utf-8") != text:
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_text(text, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
