"""Render a jinja2 template from ``templates/`` to HTML, and HTML to PDF with WeasyPrint.

WeasyPrint is imported lazily: commands that write no PDF stay fast and do not need it.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import jinja2

from ..resources import templates_dir


def environment() -> jinja2.Environment:
    """The template environment: autoescaping on, undefined names are errors."""
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(str(templates_dir())),
                             autoescape=jinja2.select_autoescape(["html", "j2"]),
                             undefined=jinja2.StrictUndefined, trim_blocks=True,
                             lstrip_blocks=True)
    return env


def render_html(template_name: str, context: dict[str, Any]) -> str:
    """HTML text of ``templates/<template_name>`` rendered with ``context``."""
    return environment().get_template(template_name).render(**context)


def write_pdf(html: str, pdf_path: Path, base_url: Path) -> int:
    """Write ``html`` as a PDF; relative links (images) resolve against ``base_url``.

    Returns the number of pages.
    """
    from weasyprint import HTML
    document = HTML(string=html, base_url=str(base_url)).render()
    document.write_pdf(str(pdf_path))
    return len(document.pages)
