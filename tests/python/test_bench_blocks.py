"""The measured blocks that `make bench` writes into the guides (bench/doc_block.py): only the
text between a guide's markers changes, a guide without them is left alone, and the FMU's
force-range block says whether its goals hold."""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "bench"))

import bench_fmu  # noqa: E402
from doc_block import replace_block  # noqa: E402


def test_only_the_block_changes(tmp_path):
    guide = tmp_path / "guide.md"
    guide.write_text("# Guide\nbefore\n<!-- x:begin -->\nold\nrows\n<!-- x:end -->\nafter\n")
    assert replace_block(guide, "x", ["", "| a |", ""])
    assert guide.read_text() == ("# Guide\nbefore\n<!-- x:begin -->\n\n| a |\n\n"
                                 "<!-- x:end -->\nafter\n")
    # again: the same text (the block is replaced, not appended to)
    assert replace_block(guide, "x", ["", "| a |", ""])
    assert guide.read_text().count("| a |") == 1


def test_a_guide_without_the_markers_is_left_alone(tmp_path):
    guide = tmp_path / "guide.md"
    text = "# Guide\n<!-- y:begin -->\nold\n<!-- y:end -->\n"
    guide.write_text(text)
    assert not replace_block(guide, "x", ["new"])
    assert guide.read_text() == text


def _step(setting, H, median, worst, over=0, retimed=0.0, engine_order=0):
    return {"setting": setting, "harmonics": H, "engine_order": engine_order,
            "init_seconds": 0.08, "seconds_median": median, "fmi3_seconds_median": median,
            "seconds_p999": 3e-5, "seconds_max": worst, "steps_over_1ms": over,
            "seconds_max_retimed": retimed, "error_gamma_P": 1.7e-9}


def test_force_range_block_rows_and_goals():
    records = [_step("gg10_H3", 3, 5e-6, 2e-3, over=1),  # not a force-range run
               _step("random_H1", 1, 3.6e-6, 4.1e-5),
               _step("random_auto", "auto", 6.1e-6, 2e-2, over=1, retimed=5e-6),
               _step("random_H1_EO1of24", 1, 1e-6, 4e-2, over=75, engine_order=1)]
    lines = bench_fmu.force_range_block(records)
    rows = [line for line in lines if line.startswith("| ") and line[2] not in "h-"]
    assert [row.split(" | ")[0] for row in rows] == ["| 1", "| auto"]
    assert "| 1 | 0.005 ms | 1.7e-09 |" in rows[1]
    # the slow step was the machine's (5 us timed again): the goals hold
    assert lines[-1].startswith("Every step stays below 1 ms (0.04 ms at most), and every "
                                "median is below 10 us (6.1 us at most)")
    records[2]["seconds_max_retimed"] = 1.5e-3
    records[1]["seconds_median"] = 12e-6
    lines = bench_fmu.force_range_block(records)
    assert lines[-1].startswith("Some step takes 1 ms or more (1.50 ms at most), and some "
                                "median is 10 us or more (12.0 us at most)")
