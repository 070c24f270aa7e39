"""One self-contained HTML page: inline style, figures embedded as base64 PNG, no links out.

The page is built from :class:`Section` objects holding paragraphs, tables and figures;
every figure carries a caption (what it shows, in which units) and is numbered.
"""

from __future__ import annotations

import base64
import datetime
import html
from dataclasses import dataclass, field

STYLE = """
body { font-family: "DejaVu Sans", Arial, sans-serif; margin: 2em auto; max-width: 1100px;
       color: #1a1a1a; line-height: 1.4; padding: 0 1em; }
h1 { font-size: 1.6em; border-bottom: 2px solid #345; padding-bottom: .2em; }
h2 { font-size: 1.25em; margin-top: 1.8em; color: #234; border-bottom: 1px solid #ccd; }
table { border-collapse: collapse; margin: .6em 0 1.2em 0; font-size: .85em; }
th, td { border: 1px solid #bbc; padding: .2em .5em; text-align: left; vertical-align: top; }
th { background: #eef1f6; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
figure { margin: 1em 0 1.6em 0; page-break-inside: avoid; }
figure img { max-width: 100%; border: 1px solid #dde; }
figcaption { font-size: .88em; color: #333; margin-top: .3em; }
section.two figure { display: inline-block; width: 48.5%; vertical-align: top;
                     margin-right: 1%; }
div.wide { overflow-x: auto; }
p.meta { color: #555; font-size: .85em; }
caption { caption-side: bottom; text-align: left; font-size: .85em; color: #333; }
.failed { color: #a00; }
div.notice { border: 2px solid #b85c00; background: #fff3e0; padding: .4em 1em;
             margin: .8em 0; }
div.notice.ok { border-color: #2e7d32; background: #edf7ee; }
div.notice h3 { margin: .2em 0; font-size: 1.05em; }
div.notice li { margin: .2em 0; }
table.headline td:first-child { font-weight: bold; white-space: nowrap; }
"""


@dataclass
class Table:
    """A table: column names, rows of cell texts, a caption; ``numeric`` columns align right."""

    columns: list[str]
    rows: list[list[str]]
    caption: str = ""
    numeric: tuple[str, ...] = ()
    css_class: str = ""


@dataclass
class Image:
    """A figure: title, caption (what and in which units), PNG bytes."""

    title: str
    caption: str
    png: bytes


@dataclass
class Notice:
    """A box at the top of a section: a title and its items (warnings, say); ``ok`` draws it
    green (nothing to warn about)."""

    title: str
    items: list[str]
    ok: bool = False


@dataclass
class Section:
    """A titled part of the report."""

    title: str
    blocks: list[str | Table | Image | Notice] = field(default_factory=list)
    two_columns: bool = False


def render_page(title: str, subtitle: str, sections: list[Section]) -> str:
    """The whole page as one HTML string."""
    counter = [0]
    body = "".join(_section(s, counter) for s in sections)
    stamp = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC")
    return (
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
        f"<title>{html.escape(title)}</title><style>{STYLE}</style></head><body>"
        f"<h1>{html.escape(title)}</h1><p class=\"meta\">{html.escape(subtitle)} — "
        f"report written {stamp}</p>{body}</body></html>\n"
    )


def _section(section: Section, counter: list[int]) -> str:
    kind = " class=\"two\"" if section.two_columns else ""
    parts = [f"<section{kind}><h2>{html.escape(section.title)}</h2>"]
    for block in section.blocks:
        if isinstance(block, Table):
            parts.append(_table(block))
        elif isinstance(block, Notice):
            parts.append(_notice(block))
        elif isinstance(block, Image):
            counter[0] += 1
            parts.append(_figure(block, counter[0]))
        else:
            parts.append(f"<p>{html.escape(block)}</p>")
    parts.append("</section>")
    return "".join(parts)


def _notice(notice: Notice) -> str:
    kind = "notice ok" if notice.ok else "notice"
    items = "".join(f"<li>{html.escape(item)}</li>" for item in notice.items)
    body = f"<ul>{items}</ul>" if items else ""
    return f"<div class=\"{kind}\"><h3>{html.escape(notice.title)}</h3>{body}</div>"


def _table(table: Table) -> str:
    head = "".join(f"<th>{_breakable(c)}</th>" for c in table.columns)
    rows = []
    for row in table.rows:
        cells = "".join(
            f"<td class=\"num\">{html.escape(cell)}</td>" if column in table.numeric
            else f"<td>{html.escape(cell)}</td>"
            for column, cell in zip(table.columns, row, strict=True))
        rows.append(f"<tr>{cells}</tr>")
    caption = f"<caption>{html.escape(table.caption)}</caption>" if table.caption else ""
    kind = f" class=\"{table.css_class}\"" if table.css_class else ""
    thead = f"<thead><tr>{head}</tr></thead>" if any(table.columns) else ""
    return (f"<div class=\"wide\"><table{kind}>{caption}{thead}"
            f"<tbody>{''.join(rows)}</tbody></table></div>")


def _breakable(name: str) -> str:
    """A column name that may wrap after '_' and '.' (long names with units)."""
    return html.escape(name).replace("_", "_<wbr>").replace(".", ".<wbr>")


def _figure(image: Image, number: int) -> str:
    data = base64.b64encode(image.png).decode("ascii")
    alt = html.escape(image.title)
    return (f"<figure><img src=\"data:image/png;base64,{data}\" alt=\"{alt}\">"
            f"<figcaption><b>Figure {number}. {alt}.</b> {html.escape(image.caption)}"
            "</figcaption></figure>")
