"""Source citations as a reviewer reads them, and as a machine reads them.

Checks and catalog tables cite the seed documents tersely (``seed 003_6ee0….txt table
050-1/058-1 (p.050/058)``, ``seed 000 p.014``). ``source_text`` turns each seed reference
into the document's title from ``catalog/SEEDS.yaml`` ("Harmonic Drive catalog, CSG-GH /
CSF-GH gear heads, table 050-1/058-1, p.050/058"); ``source_refs`` gives the same citations
as records ``{document, table, page, line}`` for results.json. Standards (ISO, VDI, EN) are
cited by name already and pass through unchanged.
"""

from __future__ import annotations

import re
from functools import lru_cache

import yaml

from .resources import catalog_dir

# "seed 003_6ee0d78a9c55c7e4.txt", "seed 000", or a bare "000 table 012-1"
SEED = re.compile(r"\bseed (\d{3})(?:_[0-9a-f]+\.txt)?|\b(\d{3})(?= tables? \d{3}-\d)")
TABLES = re.compile(r"^,? *tables? (\d{3}-\d(?:[/, ]+\d{3}-\d)*)")
PAGES = re.compile(r"^,? *\(?pp?\.(\d{3}(?:[-/–]\d{3})*)\)?")
LINE = re.compile(r"\blines? (\d+)")


@lru_cache(maxsize=1)
def seed_titles() -> dict[str, dict]:
    """Seed number ("000") → {file, title, pages} from catalog/SEEDS.yaml."""
    data = yaml.safe_load((catalog_dir() / "SEEDS.yaml").read_text(encoding="utf-8"))
    return {str(k): v for k, v in data.items()}


def source_text(text: str) -> str:
    """``text`` with every seed reference replaced by its document title.

    ``seed 003_….txt table 050-1 (p.050)`` → ``Harmonic Drive catalog, CSG-GH / CSF-GH gear
    heads, table 050-1, p.050``; ``seed 000 p.014`` → ``…, Engineering Data, p.014``.
    """
    if not text:
        return text
    titles = seed_titles()

    def title(match: re.Match) -> str:
        seed = match.group(1) or match.group(2)
        doc = titles.get(seed)
        return f"{doc['title']}," if doc else match.group(0)

    out = SEED.sub(title, text)
    out = re.sub(r", (tables? \d{3}-\d[\d/, -]*?) \((pp?\.[\d/–-]+)\)", r", \1, \2", out)
    return re.sub(r",( ?)(pp?\.)", r", \2", out).replace(",,", ",")


def source_refs(text: str) -> list[dict]:
    """Machine-readable citations of ``text``: one {document, table, page, line} per seed
    reference (table, page, line None where the text gives none)."""
    titles = seed_titles()
    refs = []
    for match in SEED.finditer(text or ""):
        seed = match.group(1) or match.group(2)
        rest = text[match.end():]
        tables, pages = TABLES.match(rest), None
        after = rest[tables.end():] if tables else rest
        pages = PAGES.match(after.lstrip(" ("))
        line = LINE.search(rest.split(";")[0])
        doc = titles.get(seed, {})
        refs.append({"document": doc.get("title", f"seed {seed}"), "seed_file": doc.get("file"),
                     "table": tables.group(1) if tables else None,
                     "page": pages.group(1) if pages else None,
                     "line": int(line.group(1)) if line else None})
    return refs
