"""``apbot report DIR``: a benchmark run as Markdown and as one self-contained HTML page.

The page is meant to be mailed or attached as a single file, so it carries everything inline:
CSS, figures as SVG data URIs, the task details and traces as one compressed data block, and
one small script (``viewer.js``) that draws a task when it is opened and filters the list. A
Content-Security-Policy forbids anything from outside the page and any script but that one
(allowed by its hash). Model, instruction and trace text is untrusted input: it is escaped in
the HTML and reaches the viewer's tables as text only. Apart from the generation timestamp the
output depends only on the run directory, so two reports of the same run can be diffed.

One module per job: :mod:`.snapshot` reads a run directory once and derives everything from
that read (with :mod:`.selection`, what the run set out to do), :mod:`.content` says what the
tables and facts hold, :mod:`.text` turns values into safe text, :mod:`.figures` draws them,
:mod:`.markdown` and :mod:`.page` render the two formats, :mod:`.traces` lists the tasks and
:mod:`.viewer` packs their details for ``viewer.js``, and :mod:`.write` writes the files.
"""

from apbot.bench.report.content import Progress, progress
from apbot.bench.report.figures import ReportFigure, make_figures
from apbot.bench.report.markdown import md_text, render_markdown
from apbot.bench.report.page import render_html
from apbot.bench.report.snapshot import ReportError, RunData, load_run
from apbot.bench.report.text import category_label, esc, failure_reason, value_text
from apbot.bench.report.write import write_files, write_report

__all__ = [
    "Progress",
    "ReportError",
    "ReportFigure",
    "RunData",
    "category_label",
    "esc",
    "failure_reason",
    "load_run",
    "make_figures",
    "md_text",
    "progress",
    "render_html",
    "render_markdown",
    "value_text",
    "write_files",
    "write_report",
]
