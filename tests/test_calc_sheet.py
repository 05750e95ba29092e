"""The calculation sheet: a real PDF whose text carries every check and its status, whose
pages and images are what the design produced, and which shows a failure when there is one."""

import json
import re

import pytest

pytest.importorskip("cadquery")
pypdf = pytest.importorskip("pypdf")

from hdcad.cli import main  # noqa: E402
from hdcad.report.format import check_label, status_text  # noqa: E402

FAILING_DUTY = """
cycle:
  - {phase: start, torque_Nm: 900, time_s: 0.3, speed_rpm: 7}
  - {phase: steady, torque_Nm: 800, time_s: 3.0, speed_rpm: 14}
  - {phase: stop, torque_Nm: 900, time_s: 0.4, speed_rpm: 7}
  - {phase: rest, torque_Nm: 0, time_s: 0.2, speed_rpm: 0}
max_output_speed_rpm: 14
max_input_speed_rpm: 1800
required_life_h: 7000
lubrication: grease
"""


def _design(tmp, model, duty):
    code = main(["design", model, "--duty", str(duty), "--out", str(tmp)])
    folder = tmp / model
    return code, folder, json.loads((folder / "results.json").read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def gh_sheet(tmp_path_factory):
    from hdcad.resources import examples_dir
    return _design(tmp_path_factory.mktemp("gh"), "CSF-45-120-GH",
                   examples_dir() / "duty_seed_example.yaml")


@pytest.fixture(scope="module")
def failing_sheet(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fail")
    duty = tmp / "overload.yaml"
    duty.write_text(FAILING_DUTY)
    return _design(tmp, "CSF-45-120-GH", duty)


def _page_text(page):
    # WeasyPrint encodes its regular font through an embedded CMap that pypdf reads as
    # one-byte codes: each character comes out right but behind a NUL byte
    return page.extract_text().replace("\x00", "")


def _text(folder):
    reader = pypdf.PdfReader(str(folder / "calc_sheet.pdf"))
    return reader, "\n".join(_page_text(page) for page in reader.pages)


def _summary_lines(text):
    """Lines of the check-summary table on the cover (check label then its status)."""
    table = text.split("Check summary", 1)[1].split("1 Inputs", 1)[0]
    return [line for line in table.splitlines() if line.strip()]


def _assert_summary_rows(lines, result):
    """Every check has its row, with its status, among the summary's ``lines``."""
    for check in result["checks"]:
        label = check_label(check["id"], check["details"], criterion=False)
        status = status_text(check["status"])
        at = [i for i, line in enumerate(lines) if line.startswith(label + " ")
              or line.startswith(label + "\t") or line == label]
        assert at, f"{label} missing from the summary table"
        # a governing criterion is printed under the label, the status then follows it
        row = " ".join(lines[at[0]:at[0] + (3 if check["details"].get("governing") else 1)])
        assert status in row, (label, row)


def test_sheet_names_the_model_and_every_check_with_its_status(gh_sheet):
    code, folder, result = gh_sheet
    assert code == 0  # the shipped example passes (README command 1)
    reader, text = _text(folder)
    assert "CSF-45-120-GH" in text and result["catalog_revision"] in text
    _assert_summary_rows(_summary_lines(text), result)


def test_every_page_has_the_header_and_a_page_number(gh_sheet):
    _, folder, result = gh_sheet
    reader, _ = _text(folder)
    n = len(reader.pages)
    assert n == result["calc_sheet"]["pages"]  # what WeasyPrint laid out is what was written
    for i, page in enumerate(reader.pages, start=1):
        page_text = _page_text(page)
        assert "CSF-45-120-GH" in page_text and f"page {i} of {n}" in page_text


def _xobject_count(reader):
    """Images and SVG forms drawn on the pages (WeasyPrint embeds SVG as form XObjects)."""
    count = 0
    for page in reader.pages:
        resources = page.get("/Resources") or {}
        xobjects = resources.get("/XObject")
        if xobjects:
            count += len(xobjects.get_object())
    return count


def test_the_images_in_the_pdf_are_the_files_the_design_wrote(gh_sheet):
    _, folder, result = gh_sheet
    images = result["calc_sheet"]["images"]
    for name in images:
        assert (folder / name).is_file() and (folder / name).stat().st_size > 1000
    html = (folder / "calc_sheet.html").read_text(encoding="utf-8")
    assert sorted(re.findall(r'<img src="([^"]+)"', html)) == sorted(images)
    # one drawing per part and the four plot kinds (life is not evaluated without base life)
    assert {f"drawings/{p['name']}.svg" for p in result["parts"]} <= set(images)
    assert "figures/duty_cycle.svg" in images
    reader, _ = _text(folder)
    assert _xobject_count(reader) >= len(images)


def test_bill_of_materials_lists_screws_and_lubricant(gh_sheet):
    _, folder, result = gh_sheet
    items = {row["item"] for row in result["bill_of_materials"]}
    assert {"screws", "lubricant"} <= items
    _, text = _text(folder)
    assert "Bill of materials" in text and "grease (factory fill)" in text


def test_a_failing_design_gets_a_sheet_that_shows_the_failure(failing_sheet):
    code, folder, result = failing_sheet
    assert code == 1
    failed = [check_label(c["id"], c["details"]) for c in result["checks"] if c["status"] == "fail"]
    assert "avg_torque" in failed
    _, text = _text(folder)
    cover = text.split("1 Inputs")[0]
    assert re.search(rf"{len(failed)} check\(s\) fail", cover)
    assert "Failing checks:" in cover and all(label in cover for label in failed)
    html = (folder / "calc_sheet.html").read_text(encoding="utf-8")
    assert html.count('<tr class="fail">') >= len(failed)  # the rows are highlighted


def test_cover_names_each_check_not_evaluated_with_its_reason(gh_sheet):
    _, folder, result = gh_sheet
    reader, _ = _text(folder)
    cover = _page_text(reader.pages[0])
    missing = [c for c in result["checks"] if c["status"] == "not_evaluated"]
    assert missing  # the GH example leaves main_bearing, input_bore … open
    for c in missing:
        assert check_label(c["id"], c["details"]) in cover
    assert "external_load" in cover  # main_bearing's reason: the duty has no external load


def test_notes_printed_are_those_of_the_tables_and_size_used(gh_sheet):
    _, folder, _ = gh_sheet
    _, text = _text(folder)
    flat = " ".join(text.split())
    # CSF-45-120-GH takes its motor flange from table 064-1 and greases itself: the FD oil
    # level table, the CSG-GH flange tables 055-1/056-1 and size 65 do not bear on it
    assert "fd_oil_level_315-1.csv" not in flat
    assert "056-1: the type-I block" not in flat and "Size 65 starts at ratio 80" not in flat
    # the notes that do bear on it stay: how 064-1's columns are read, the K2 correction
    assert "064-1: A(H7)=pilot" in flat
    assert "seed prints 2.0" in flat


def test_sheet_spells_speed_units_one_way(gh_sheet):
    _, folder, _ = gh_sheet
    _, text = _text(folder)
    assert "r/min" in text and not re.search(r"\brpm\b", text)


def test_the_summary_keeps_its_last_rows_together_and_plots_follow_the_checks(gh_sheet):
    """The shipped example's cover holds the whole check summary, and the plots begin on the
    page of the last check's box (each once stood alone on a page of its own)."""
    _, folder, result = gh_sheet
    reader, _ = _text(folder)
    pages = [_page_text(page) for page in reader.pages]
    _assert_summary_rows(_summary_lines(pages[0] + "1 Inputs"), result)
    plots = next(i for i, text in enumerate(pages) if "3 Plots" in text)
    assert "review_assembly — Review assembly" in pages[plots]
