"""noiselab.results on the committed results/quick/ folders."""
import csv
import os

import numpy as np
import pytest

from conftest import ROOT
import noiselab.results as nr

QUICK = os.path.join(ROOT, "results", "quick")


def rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.reader(f, delimiter="\t"))


def test_s3_tables_are_the_files():
    """Every table of S3, every cell, against Python's own reading of the
    text: numbers to the bit, text as written."""
    folder = os.path.join(QUICK, "s3_fbm")
    r = nr.load(folder)
    assert r.manifest["experiment"] == "s3_fbm" and r.manifest["seed"] == 1
    assert "size=128" in r.manifest["param"]
    names = sorted(f[:-4] for f in os.listdir(folder)
                   if f.endswith(".tsv") and f not in ("manifest.tsv", "verdicts.tsv"))
    assert sorted(r.tables) == names
    for name in names + ["verdicts"]:
        t = r.verdicts if name == "verdicts" else r.tables[name]
        text = rows(os.path.join(folder, name + ".tsv"))
        assert list(t.dtype.names) == text[0] and len(t) == len(text) - 1
        for j, col in enumerate(text[0]):
            cells = [row[j] for row in text[1:]]
            if t.dtype[col].kind == "f":
                assert np.array_equal(t[col], np.array([float(c) for c in cells])), (name, col)
            else:   # text as written; a number among text as the harness writes it
                for got, cell in zip(t[col].tolist(), cells):
                    assert got == cell or float(got) == float(cell), (name, col, got, cell)


def test_checks_and_run():
    """.checks are checks.tsv's rows; .run is run.tsv's keys, or empty when
    the folder has none (the committed results carry no times)."""
    folder = os.path.join(QUICK, "s3_fbm")
    r = nr.load(folder)
    text = rows(os.path.join(folder, "checks.tsv"))
    assert list(r.checks.dtype.names) == ["table", "column", "rule"]
    assert r.checks["rule"].tolist() == [row[2] for row in text[1:]]
    if os.path.exists(os.path.join(folder, "run.tsv")):
        assert {"started", "seconds", "cpu_seconds", "peak_rss_mb"} <= set(r.run)
    else:
        assert r.run == {}


def test_report_is_the_verdict_rows():
    folder = os.path.join(QUICK, "s3_fbm")
    v = nr.report(folder)
    text = rows(os.path.join(folder, "verdicts.tsv"))
    assert v["verdict"].tolist() == [row[text[0].index("verdict")] for row in text[1:]]
    assert {"quantity", "paper", "ours", "verdict", "reason"} <= set(v.dtype.names)


def test_every_quick_folder_loads():
    n = 0
    for e in sorted(os.listdir(QUICK)):
        folder = os.path.join(QUICK, e)
        if os.path.isdir(folder):
            r = nr.load(folder)
            assert r.manifest["experiment"] == e and len(r.verdicts) >= 1, e
            n += 1
    assert n >= 20


def test_frame():
    pd = pytest.importorskip("pandas")
    r = nr.load(os.path.join(QUICK, "s3_fbm"))
    f = r.frame("gain_distribution")
    assert isinstance(f, pd.DataFrame)
    assert np.array_equal(f["sd"], r.tables["gain_distribution"]["sd"])


def test_bad_folders(tmp_path):
    with pytest.raises(FileNotFoundError, match="no such experiment folder"):
        nr.load(tmp_path / "missing")
    with pytest.raises(FileNotFoundError, match="no manifest.tsv"):
        nr.load(tmp_path)
    (tmp_path / "manifest.tsv").write_text("key\tvalue\nexperiment\tx\n")
    (tmp_path / "bad.tsv").write_text("a\tb\n1\t2\n3\n")
    with pytest.raises(ValueError) as e:
        nr.load(tmp_path)
    assert "bad.tsv:3:" in str(e.value) and "\n" not in str(e.value)
    assert sorted(os.listdir(tmp_path)) == ["bad.tsv", "manifest.tsv"]   # nothing written
