"""Sphinx directive `.. c-header:: PATH`: the C API reference, read from polyccd.h itself.

polyccd.h documents every declaration in the comment just above it (its contract, the
status codes it returns, the degenerate cases). This directive turns the header into
Sphinx's C domain entries, so the reference can never drift from the header:

- a comment `/* ---- Title ---- */` starts a section;
- a comment followed directly by declarations documents them: functions
  (`PCCD_API ret name(args);`), opaque handles (`typedef struct X X;`), structs with
  their members and enums with their enumerators (each with its trailing comment), and
  `#define` constants;
- comment text is rendered as prose (c_prose.py: paragraphs, bullet and aligned lists);
- a section's title is the banner's first words (up to a colon or full stop), the rest
  of the banner its introduction, so the sidebar lists short titles.
"""
import re
from pathlib import Path

from docutils import nodes
from docutils.parsers.rst import Directive
from docutils.statemachine import StringList
from sphinx.util.nodes import nested_parse_with_titles

from c_prose import CProse

SKIP_DEFINES = {"POLYCCD_H", "PCCD_API"}


def _comment_text(raw):
    """The text of a /* ... */ comment, without the delimiters and leading stars."""
    body = raw.strip()[2:-2]
    lines = [re.sub(r"^\s*\* ?", "", ln) if ln.lstrip().startswith("*") else ln.strip()
             for ln in body.splitlines()]
    while lines and not lines[0].strip():
        lines.pop(0)
    while lines and not lines[-1].strip():
        lines.pop()
    return lines


def _blocks(text):
    """The header as a list of ("comment", lines) and ("code", text) items, in order;
    a blank line ends a code item."""
    items, pos = [], 0
    for m in re.finditer(r"/\*.*?\*/", text, re.S):
        before = text[pos:m.start()]
        items += [("code", c) for c in re.split(r"\n\s*\n", before) if c.strip()]
        line_start = text.rfind("\n", 0, m.start()) + 1
        if text[line_start:m.start()].strip():      # a trailing comment of a code line
            items.append(("trailing", m.group(0)))
        else:
            items.append(("comment", _comment_text(m.group(0))))
        pos = m.end()
    items += [("code", c) for c in re.split(r"\n\s*\n", text[pos:]) if c.strip()]
    return items


def _squash(s):
    return re.sub(r"\s+", " ", s).strip()


def _members(body, sep):
    """(declaration, comment lines) of each member of a struct (sep ";") or enum (sep
    ","); a comment documents the member before it. `double *lo, *hi;` gives two."""
    out, pos = [], 0
    for m in list(re.finditer(r"/\*.*?\*/", body, re.S)) + [None]:
        code = body[pos:m.start() if m else len(body)]
        for piece in code.split(sep):
            if piece.strip():
                out.append((_squash(piece), []))
        if m:
            out[-1][1].extend(_comment_text(m.group(0)))
            pos = m.end()
    if sep == ",":
        return out
    split = []
    for decl, comment in out:
        first, *more = [d.strip() for d in decl.split(",")]
        base = re.match(r"(.*?)[\s*]*\w+(\[\w*\])?$", first).group(1).strip()
        split.append((first, comment))
        split += [(f"{base} {d}", []) for d in more]
    return split


def _rst(path):
    text = Path(path).read_text(encoding="utf-8")
    text = text[text.index("#endif", text.index("#define PCCD_API")) + len("#endif"):]
    text = text[:text.rindex("#ifdef __cplusplus")]
    # Trailing comments stay glued to their code line: mark them so _blocks keeps them.
    out, doc = [], []

    def prose(comment, indent):
        out.extend([f"{indent}.. c-prose::", ""] + [f"{indent}   {ln}" if ln.strip() else ""
                                                    for ln in comment])

    def emit(directive, sig, comment, indent=""):
        out.extend(["", f"{indent}.. c:{directive}:: {sig}", ""])
        if comment:
            prose(comment, indent + "   ")

    for kind, item in _blocks_with_trailing(text):
        if kind == "comment":
            section = _section(item)
            if section:
                title, intro = section
                out.extend(["", title, "-" * len(title), ""])
                if intro:
                    prose(intro, "")
                doc = []
            else:
                doc = item
            continue
        _code(item, doc, emit)
        doc = []
    return out


def _section(lines):
    """(title, introduction lines) of a section banner, `/* ---- Title ---- */` or a
    comment framed by lines of dashes whose first sentence names the section; None for
    any other comment."""
    short = re.match(r"^-{2,}\s*(.*?)\s*-{2,}$", " ".join(lines).strip())
    if len(lines) == 1 and short:
        return short.group(1), []
    if len(lines) < 3 or not re.fullmatch(r"-{4,}", lines[0].strip()) \
            or not re.fullmatch(r"-{4,}", lines[-1].strip()):
        return None
    body = lines[1:-1]
    m = re.match(r"\s*(.+?)[:.](\s+|$)(.*)$", body[0])
    title, rest = (m.group(1), m.group(3)) if m else (body[0].strip(), "")
    aside = re.match(r"(.+?) (\(.*\))$", title)   # "Title (the paper's section 3)"
    if aside:
        title, rest = aside.group(1), f"{aside.group(2)[1:-1].capitalize()}: {rest}"
    return title, ([rest] if rest.strip() else []) + body[1:]


def _blocks_with_trailing(text):
    """_blocks, with trailing comments put back into the code item they belong to."""
    merged = []
    for kind, item in _blocks(text):
        if kind == "trailing" or (kind == "code" and merged and merged[-1][0] == "code"
                                  and merged[-1][1].endswith("*/")):
            merged[-1] = ("code", merged[-1][1] + (item if kind == "trailing" else "\n" + item))
        else:
            merged.append((kind, item))
    return merged


def _code(code, doc, emit):
    """The entries of one code item (documented by doc, the comment just above it)."""
    rest = code
    first = True
    while rest.strip():
        rest = rest.lstrip()
        comment = doc if first else []
        first = False
        m = re.match(r"typedef\s+(struct|enum)\s+(\w+)\s*\{(.*?)\}\s*(\w+)\s*;", rest, re.S)
        if m:
            what, name, body = m.group(1), m.group(4), m.group(3)
            emit("struct" if what == "struct" else "enum", name, comment)
            for decl, c in _members(body, ";" if what == "struct" else ","):
                emit("member" if what == "struct" else "enumerator", decl, c, "   ")
            rest = rest[m.end():]
            continue
        m = re.match(r"typedef\s+struct\s+(\w+)\s+(\w+)\s*;", rest)
        if m:
            emit("type", m.group(2), comment)
            rest = rest[m.end():]
            continue
        m = re.match(r"PCCD_API\s+(.*?\));", rest, re.S)
        if m:
            emit("function", _squash(m.group(1)), comment)
            rest = rest[m.end():]
            continue
        m = re.match(r"#define\s+(\w+)\s+(.*?)(/\*.*?\*/)?\s*(?:\n|$)", rest, re.S)
        if m:
            if m.group(1) not in SKIP_DEFINES:
                c = comment + (_comment_text(m.group(3)) if m.group(3) else [])
                emit("macro", m.group(1), [f"{m.group(1)} = {m.group(2).strip()}", ""] + c)
            rest = rest[m.end():]
            continue
        m = re.match(r"/\*.*?\*/", rest, re.S)   # a trailing comment already shown
        if m:
            rest = rest[m.end():]
            continue
        raise ValueError(f"c-header: cannot read the declaration {rest[:80]!r}")


class CHeader(Directive):
    required_arguments = 1

    def run(self):
        env = self.state.document.settings.env
        path = (Path(env.srcdir) / self.arguments[0]).resolve()
        env.note_dependency(str(path))
        content = StringList(_rst(path), source=str(path))
        node = nodes.section()
        node.document = self.state.document
        nested_parse_with_titles(self.state, content, node)
        return node.children


def setup(app):
    app.add_directive("c-header", CHeader)
    app.add_directive("c-prose", CProse)
    return {"parallel_read_safe": True, "version": "1"}
