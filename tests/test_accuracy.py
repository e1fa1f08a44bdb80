"""The accuracy report: its Pareto front, and a small sweep end to end."""

from __future__ import annotations

import csv

from polygolf.engine.physics.presets import PRESETS, Knobs
from polygolf.game.tools import accuracy


def test_pareto_front_keeps_only_undominated_settings():
    rows = [accuracy.Row(Knobs(substeps=s), error, cost, {}) for s, error, cost in
            [(1, 0.5, 1.0), (2, 0.2, 2.0), (3, 0.3, 3.0), (4, 0.1, 4.0), (6, 0.1, 5.0), (8, 0.05, 9.0)]]
    accuracy.mark_front(rows)
    assert [r.knobs.substeps for r in rows if r.on_front] == [1, 2, 4, 8]


def test_case_error_counts_escape_and_overlap_as_failures():
    case = accuracy.Case("c", "reference", 1.0, run=None)
    ok = accuracy.Outcome(1.0, 0.0, 0.0, 0, 0, 0, 0.5, 0.0, 0.0, False)
    assert accuracy.case_error(case, ok, ok) == 0.0
    far = accuracy.Outcome(2.25, 0.0, 0.0, 0, 0, 0, 0.5, 0.0, 0.0, False)
    assert accuracy.case_error(case, far, ok) == 0.5  # 1.25 m off is half of 5 radii
    deep = accuracy.Outcome(1.0, 0.0, 0.0, 0, 0, 0, 0.5, 0.25, 0.0, False)
    assert accuracy.case_error(case, deep, ok) == 1.0
    gone = accuracy.Outcome(1.0, 0.0, 0.0, 0, 0, 0, 0.5, 0.0, 0.0, True)
    assert accuracy.case_error(case, gone, ok) == 1.0


def test_small_sweep_writes_table_csv_and_plot(tmp_path):
    settings = [PRESETS["fast"], Knobs(substeps=1, iterations=1, ccd=False)]
    rows = accuracy.measure(settings, repeats=1, workers=1, quick=True, progress=False)
    fast = next(r for r in rows if r.preset == "fast")
    crude = next(r for r in rows if not r.preset)
    assert fast.errors["flat-wall"] < 0.01 and fast.errors["vertex-hit"] < 0.02  # closed forms
    assert crude.errors["thin-wall"] == 1.0  # no continuous collision: it goes through
    assert fast.error < crude.error and fast.cost_us > 0
    paths = accuracy.write_report(rows, accuracy.all_cases(quick=True), tmp_path, {"integrate": 10.0})
    with paths["csv"].open() as f:
        table = list(csv.DictReader(f))
    assert len(table) == 2 and {t["preset"] for t in table} == {"fast", ""}
    assert paths["png"].stat().st_size > 10_000
    text = paths["md"].read_text()
    assert "| fast | 2x4 split |" in text and "![error against cost](accuracy.png)" in text
    assert "| integrate | 10.0 |" in text
