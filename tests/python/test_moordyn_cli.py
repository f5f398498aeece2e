"""MoorDyn decks on the command line (docs/moordyn.md): `tangle run DECK`, `tangle convert`, `tangle check`.

Run through ctest (it sets TANGLE_CLI), or by hand:
    TANGLE_CLI=build/ci/tangle /usr/bin/python3 -m pytest -q tests/python/test_moordyn_cli.py

- A deck runs as it is, and the model `tangle convert` writes from it runs to the same static results, digit
  for digit: the published chain (fixed and coupled points) and a deck with every kind of free point
  (two lines joined at a buoy, a clump weight on a free end, two lines at one coupled point, seabed friction).
- The results folder of a deck run holds the deck and the model it became (model.yaml, what a re-run reads).
- A deck tangle cannot represent is refused by the CLI with exit code 1, naming the deck, its line and the entry.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CLI = os.environ.get("TANGLE_CLI", str(ROOT / "build" / "ci" / "tangle"))
DATA = ROOT / "tests" / "data" / "moordyn"


def tangle(*args) -> subprocess.CompletedProcess:
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=300)


@pytest.mark.parametrize("deck", ["WD0050_Chain.txt", "buoy_and_clump.txt", "lowe_langley_jumper.txt"])
def test_deck_and_converted_model_give_the_same_statics(tmp_path: Path, deck: str) -> None:
    direct = tangle("run", DATA / deck, "-o", tmp_path / "direct", "--no-plots", "--no-report", "-q")
    assert direct.returncode == 0, direct.stderr
    converted = tmp_path / "model.yaml"
    conversion = tangle("convert", DATA / deck, "-o", converted)
    assert conversion.returncode == 0, conversion.stderr
    again = tangle("run", converted, "-o", tmp_path / "converted", "--no-plots", "--no-report", "-q")
    assert again.returncode == 0, again.stderr
    files = sorted(p.name for p in (tmp_path / "direct" / "statics").glob("*.csv"))
    assert files and files == sorted(p.name for p in (tmp_path / "converted" / "statics").glob("*.csv"))
    for name in files:
        assert (tmp_path / "direct" / "statics" / name).read_text() == \
            (tmp_path / "converted" / "statics" / name).read_text(), name
    # The folder keeps the deck and the model it became.
    assert (tmp_path / "direct" / f"moordyn_{deck}").read_text() == (DATA / deck).read_text()
    assert (tmp_path / "direct" / "model.yaml").read_text() == converted.read_text()


def test_joined_lines_and_free_points_hang_as_their_weights_say(tmp_path: Path) -> None:
    """The clump weight (2000 kg, 0.2 m^3) hangs from a free end: its line's end tension there is its
    submerged weight, (2000 - 1025 x 0.2) x 9.80665 N (the statics' exact end force)."""
    result = tangle("run", DATA / "buoy_and_clump.txt", "-o", tmp_path / "r", "--no-plots", "--no-report", "-q")
    assert result.returncode == 0, result.stderr
    rows = (tmp_path / "r" / "statics" / "line3.csv").read_text().splitlines()
    header = rows[0].split(",")
    tension = float(rows[-1].split(",")[header.index("effective_tension_N")])
    assert tension == pytest.approx((2000 - 1025 * 0.2) * 9.80665, rel=1e-6)
    assert (tmp_path / "r" / "statics" / "line1-line2.csv").exists()


def test_check_reads_a_deck() -> None:
    result = tangle("check", DATA / "lines.txt")
    assert result.returncode == 0, result.stderr
    assert "line1" in result.stdout and "model is valid" in result.stdout


def test_unsupported_entry_is_refused_with_file_line_and_name(tmp_path: Path) -> None:
    deck = tmp_path / "loads.txt"
    text = (DATA / "WD0050_Chain.txt").read_text().replace(
        "---------------------- POINT PROPERTIES",
        "---------------------- EXTERNAL LOADS --------------------------------\nID Object\n(#) (-)\n"
        "---------------------- POINT PROPERTIES")
    deck.write_text(text)
    line = text.splitlines().index("---------------------- EXTERNAL LOADS --------------------------------") + 1
    result = tangle("run", deck, "-o", tmp_path / "r", "-q")
    assert result.returncode == 1
    assert f"loads.txt:{line}" in result.stderr and "external loads" in result.stderr
    assert not (tmp_path / "r").exists()  # refused before anything is written


def test_convert_keeps_an_existing_file_unless_told(tmp_path: Path) -> None:
    out = tmp_path / "model.yaml"
    out.write_text("mine\n")
    refused = tangle("convert", DATA / "lines.txt", "-o", out)
    assert refused.returncode == 1 and "--overwrite" in refused.stderr
    assert out.read_text() == "mine\n"
    assert tangle("convert", DATA / "lines.txt", "-o", out, "--overwrite").returncode == 0
    assert out.read_text().startswith("# tangle model converted from the MoorDyn input file")
