"""The class report's content, read back from the HTML with lxml (the browser test renders it)."""

from __future__ import annotations

import json

from lxml import html

from pkgtool.grade.report import render
from pkgtool.grade.report.html import BINS, histogram, rules_broken
from tests.grade.class_results import HOSTILE, RUBRIC, results


def _page() -> html.HtmlElement:
    return html.fromstring(render("html", results(), rubric=RUBRIC))


def _bins_from_json() -> list[int]:
    document = json.loads(render("json", results(), rubric=RUBRIC))
    counts = [0] * BINS
    for submission in document["submissions"]:
        share = submission["score"] / document["max_score"]
        counts[min(BINS - 1, int(share * BINS))] += 1
    return counts


def test_the_histogram_bars_count_the_json_scores() -> None:
    bars = _page().xpath("//*[local-name()='rect'][@class='bar']")
    assert [int(bar.get("data-count")) for bar in bars] == _bins_from_json()
    assert sum(_bins_from_json()) == len(results())
    assert histogram(results(), RUBRIC.max_score) == _bins_from_json()


def test_each_criterion_has_its_pass_rate_over_graded_submissions() -> None:
    rows = [[cell.text_content() for cell in row.xpath("td")]
            for row in _page().xpath("//table[@id='criteria']/tr[td]")]
    graded = [r for r in results() if r.error is None]
    expected = {c.name: sum(r.criteria[i].passed for r in graded)
                for i, c in enumerate(RUBRIC.criteria)}
    assert {row[0]: row[2] for row in rows} == {
        name: f"{passed} / {len(graded)}" for name, passed in expected.items()}


def test_the_rules_most_often_broken_are_counted_per_student_and_per_finding() -> None:
    assert rules_broken(results()) == [("DEP001", 2, 3), ("MAN004", 2, 2), ("SET008", 1, 1)]
    rows = [[cell.text for cell in row.xpath("td")]
            for row in _page().xpath("//table[@id='rules']/tr[td]")]
    assert rows == [["DEP001", "2", "3"], ["MAN004", "2", "2"], ["SET008", "1", "1"]]


def test_every_student_row_links_to_that_student_s_feedback() -> None:
    page = _page()
    links = page.xpath("//table[@id='students']//a/@href")
    assert len(links) == len(results())
    for link, result in zip(links, results()):
        section = page.get_element_by_id(link[1:])
        assert section.tag == "section"
        assert section.xpath("h3")[0].text_content().startswith(
            result.label.replace("\x1b", "\\x1b").replace("\u202e", "\\u202e"))


def test_student_text_cannot_add_markup_or_control_characters() -> None:
    text = render("html", results(), rubric=RUBRIC)
    assert "<script" not in text and "<img" not in text and "\x1b" not in text
    assert "\u202e" not in text
    page = _page()
    assert not page.xpath("//script|//img|//*[@onerror]")
    assert HOSTILE.split("<script>")[0].replace("</pre>", "") == ""  # the payload starts at once
    assert "<script>alert(1)</script>" in page.text_content()  # shown as text, visibly


def test_the_page_needs_nothing_from_outside() -> None:
    page = _page()
    assert not page.xpath("//script|//link|//iframe|//*[@src]")
    policy = page.xpath("//meta[@http-equiv='Content-Security-Policy']/@content")[0]
    assert "default-src 'none'" in policy


def test_an_empty_batch_still_gives_a_page() -> None:
    page = html.fromstring(render("html", [], rubric=RUBRIC))
    assert page.get_element_by_id("summary").text == "no submissions"
