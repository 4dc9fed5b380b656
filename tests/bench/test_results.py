"""The results store: a torn last line is cut, bad lines are quarantined, no valid record is
ever lost, and nothing but a clear ResultsError comes out of it."""

from __future__ import annotations

import base64
import json
import os
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from apbot.bench.records import TaskRecord, record_key
from apbot.bench.results import QUARANTINE_FILE, RESULTS_FILE, ResultsError, ResultStore

FUZZ_EXAMPLES = int(os.environ.get("APBOT_FUZZ_EXAMPLES", "150"))


def record(number: int, success: bool = True) -> TaskRecord:
    task = f"t{number:02d}"
    return TaskRecord(
        key=record_key("oracle", "true", "kettle_1", task),
        method="oracle",
        belief="true",
        appliance="kettle_1",
        category="kettle",
        task=task,
        instruction="Heat the water to 80 degrees.",
        goal={"temperature": 80},
        goal_variables=1,
        success=success,
        claimed_success=success,
        reasoning_steps=1,
        execution_steps=3,
        optimal_steps=3,
        spl=1.0 if success else 0.0,
        trace=[{"kind": "action", "display": "TEMP 80°C"}],
    )


def line(item: TaskRecord) -> bytes:
    """A record as the store writes it."""
    text = json.dumps(item.model_dump(mode="json"), ensure_ascii=False, separators=(",", ":"))
    return text.encode("utf-8")


def quarantined(store: ResultStore) -> list[dict[str, object]]:
    if not store.quarantine.exists():
        return []
    return [json.loads(text) for text in store.quarantine.read_text().splitlines()]


def original_bytes(entry: dict[str, object]) -> bytes:
    if "text" in entry:
        return str(entry["text"]).encode("utf-8")
    return base64.b64decode(str(entry["base64"]))


def test_a_torn_last_line_is_cut_silently(tmp_path: Path) -> None:
    store = ResultStore(tmp_path / RESULTS_FILE)
    store.path.write_bytes(line(record(1)) + b"\n" + line(record(2))[:40])
    scan = store.recover()
    assert (list(scan.records), scan.torn, scan.bad) == ([record(1).key], True, [])
    assert store.path.read_bytes() == line(record(1)) + b"\n"
    assert not store.quarantine.exists()


def test_a_last_record_without_its_newline_is_kept(tmp_path: Path) -> None:
    store = ResultStore(tmp_path / RESULTS_FILE)
    store.path.write_bytes(line(record(1)) + b"\n" + line(record(2)))
    assert list(store.recover().records) == [record(1).key, record(2).key]
    store.append(record(3))
    assert list(store.load(repair=False)) == [record(n).key for n in (1, 2, 3)]


def test_bad_lines_are_quarantined_with_their_numbers_and_bytes(tmp_path: Path) -> None:
    store = ResultStore(tmp_path / RESULTS_FILE)
    wrong_key = line(record(3)).replace(b"kettle_1/t03", b"kettle_1/t09", 1)
    garbage = b"\xff\xfe not json"
    store.path.write_bytes(
        b"\n".join([line(record(1)), garbage, line(record(2)), wrong_key, b"{}"]) + b"\n"
    )
    with pytest.raises(ResultsError, match=rf"{RESULTS_FILE}:2: not a valid result record"):
        store.load(repair=False)  # only read: the report's way
    scan = store.recover()
    assert list(scan.records) == [record(1).key, record(2).key]
    entries = quarantined(store)
    assert [e["line"] for e in entries] == [2, 4, 5]
    assert [original_bytes(e) for e in entries] == [garbage, wrong_key, b"{}"]
    assert "does not match" in str(entries[1]["reason"])
    assert "Field required" in str(entries[2]["reason"])
    assert store.path.read_bytes() == line(record(1)) + b"\n" + line(record(2)) + b"\n"
    assert store.recover().bad == []  # done once, for good


def test_files_that_cannot_be_read_or_written_are_a_results_error(tmp_path: Path) -> None:
    (tmp_path / "a").mkdir()
    (tmp_path / "a" / RESULTS_FILE).mkdir()
    with pytest.raises(ResultsError, match=rf"{RESULTS_FILE}: cannot be read"):
        ResultStore(tmp_path / "a" / RESULTS_FILE).recover()
    store = ResultStore(tmp_path / RESULTS_FILE)
    store.path.write_bytes(b"garbage\n")
    store.quarantine.mkdir()
    with pytest.raises(ResultsError, match=rf"{QUARANTINE_FILE}: cannot be written to repair"):
        store.recover()
    assert store.path.read_bytes() == b"garbage\n"  # untouched until its lines are safe


# --- the fuzz ---------------------------------------------------------------------------------

POOL = [record(n, success=n % 2 == 0) for n in range(1, 7)]


def _valid(index: int) -> tuple[str, bytes]:
    return "valid", line(POOL[index])


pieces = st.one_of(
    st.integers(0, len(POOL) - 1).map(_valid),
    st.binary(max_size=60).map(lambda data: ("noise", data)),
    st.tuples(st.integers(0, len(POOL) - 1), st.floats(0, 1)).map(
        lambda t: ("noise", line(POOL[t[0]])[: int(len(line(POOL[t[0]])) * t[1])])
    ),
    st.tuples(st.integers(0, len(POOL) - 1), st.integers(0, len(POOL) - 1), st.floats(0, 1)).map(
        lambda t: ("noise", line(POOL[t[0]])[: int(60 * t[2])] + line(POOL[t[1]]))
    ),  # two writers interleaved
    st.sampled_from([b"", b"   ", b"\r", b"{}", b"null", b"[1,2]", b'{"key": 1}']).map(
        lambda data: ("noise", data)
    ),
)


@settings(
    max_examples=FUZZ_EXAMPLES,
    deadline=2000,  # a hang fails the example
    suppress_health_check=[HealthCheck.too_slow],
)
@given(st.lists(pieces, max_size=12), st.booleans())
def test_fuzz_the_store_never_crashes_nor_loses_a_valid_record(
    chunks: list[tuple[str, bytes]], final_newline: bool
) -> None:
    data = b"\n".join(data for _, data in chunks) + (b"\n" if final_newline and chunks else b"")
    valid: dict[
        str, TaskRecord
    ] = {}  # each valid record written whole, on a line of its own: first one per key
    for kind, data_ in chunks:
        if kind == "valid":
            item = TaskRecord.model_validate_json(data_)
            valid.setdefault(item.key, item)
    with tempfile.TemporaryDirectory() as directory:
        store = ResultStore(Path(directory) / RESULTS_FILE)
        store.path.write_bytes(data)
        try:
            scan = store.recover()
        except ResultsError:
            return
        assert scan.records.keys() >= valid.keys()
        assert all(scan.records[key] == item for key, item in valid.items())
        after = store.path.read_bytes()
        assert after == b"" or after.endswith(b"\n")
        again = store.load(repair=False)  # the file now reads cleanly, the same records
        assert again == scan.records
        entries = quarantined(store)
        assert len(entries) == len(scan.bad)
        lines = data.split(b"\n")
        assert all(lines[int(str(e["line"])) - 1] == original_bytes(e) for e in entries)
        assert (Path(directory) / QUARANTINE_FILE).exists() == bool(scan.bad)
