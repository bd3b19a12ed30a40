"""Sphinx directive `.. c-prose::`: one comment of polyccd.h rendered as prose.

The header's comments are plain text laid out for a terminal: paragraphs, "- " bullet
lists, and aligned two-column lists ("points[1][0][2]        point 1, axis 0 ..."),
continued on deeper-indented lines. This directive turns them into paragraphs, bullet
lists and definition lists (docutils nodes built directly, so no character of the
comment is read as reStructuredText markup and nothing is shown as code), with names of
the API (pccd_*, PCCD_*) and `quoted` text as inline literals. c_header.py puts each
declaration's comment into one.
"""
import re
from dataclasses import dataclass, field
from typing import List

from docutils import nodes
from docutils.parsers.rst import Directive

BULLET = re.compile(r"^[-*] +")
# A row of an aligned list: a term (no run of two spaces inside), two or more spaces,
# then its description.
ROW = re.compile(r"^(\S(?:\S| (?! ))*?) {2,}(\S.*)$")
MAX_TERM = 40   # longer "terms" are prose with two spaces in it
LITERAL = re.compile(r"`([^`]+)`|\b((?:pccd|PCCD)_\w+(?:\(\))?)")


@dataclass
class Entry:
    kind: str                 # "para", "item" or "row"
    indent: int
    text: List[str]
    term: str = ""
    children: List["Entry"] = field(default_factory=list)


def _inline(text):
    """Text nodes, with API names and `quoted` text as literals."""
    out, pos = [], 0
    for m in LITERAL.finditer(text):
        if m.start() > pos:
            out.append(nodes.Text(text[pos:m.start()]))
        out.append(nodes.literal(text=m.group(1) or m.group(2)))
        pos = m.end()
    if pos < len(text):
        out.append(nodes.Text(text[pos:]))
    return out


def _paragraph(lines):
    return nodes.paragraph("", "", *_inline(" ".join(ln.strip() for ln in lines)))


def _entries(block):
    """The entries of one blank-line-separated block; an entry indented deeper than an
    item or row before it is its child (a nested list), a deeper plain line continues
    it."""
    top: List[Entry] = []
    for line in block:
        indent, text = len(line) - len(line.lstrip()), line.strip()
        owner = next((e for e in reversed(_open(top)) if e.indent < indent), None)
        bullet, row = BULLET.match(text), ROW.match(text)
        if bullet:
            entry = Entry("item", indent, [text[bullet.end():]])
        elif row and len(row.group(1)) <= MAX_TERM and not (owner and owner.kind == "para"):
            entry = Entry("row", indent, [row.group(2)], term=row.group(1))
        elif owner is not None and owner.kind in ("item", "row"):
            owner.text.append(text)
            continue
        elif top and top[-1].kind == "para" and indent >= top[-1].indent:
            top[-1].text.append(text)
            continue
        else:
            entry = Entry("para", indent, [text])
        (owner.children if owner is not None and owner.kind != "para" else top).append(entry)
    return top


def _open(top):
    """The entries a new line may belong to: the last one at each nesting level."""
    chain, level = [], top
    while level:
        chain.append(level[-1])
        level = level[-1].children
    return chain


def _render(entries):
    """docutils nodes of a list of sibling entries: runs of items become a bullet list,
    runs of rows a definition list."""
    out = []
    for e in entries:
        kind = {"item": nodes.bullet_list, "row": nodes.definition_list}.get(e.kind)
        if kind is None:
            out.append(_paragraph(e.text))
            continue
        if not out or not isinstance(out[-1], kind):
            out.append(kind(bullet="-") if e.kind == "item" else kind())
        body = [_paragraph(e.text)] + _render(e.children)
        if e.kind == "item":
            out[-1] += nodes.list_item("", *body)
        else:
            term = nodes.term("", "", nodes.literal(text=e.term))
            out[-1] += nodes.definition_list_item("", term, nodes.definition("", *body))
    return out


def prose(lines):
    """The nodes of a comment's lines (blank lines separate blocks)."""
    out, block = [], []
    for line in list(lines) + [""]:
        if line.strip():
            block.append(line.rstrip())
        elif block:
            out += _render(_entries(block))
            block = []
    return out


class CProse(Directive):
    has_content = True

    def run(self):
        return prose(self.content)
