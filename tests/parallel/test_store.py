"""The resumable store: records resume without loss or duplicate, a torn last line is dropped, a directory of
another run is refused with a clear error, appends reach the file at once and fsync is batched."""

from __future__ import annotations

import dataclasses
import json
import os
from pathlib import Path
from typing import Any

import pytest

import seafast.parallel.store as store_module
from seafast.parallel.errors import ForeignStoreError
from seafast.parallel.store import DICT_RECORDS, RecordStore, StoreLayout


def _record(i: int) -> dict[str, Any]:
    return {"index": i, "value": i * i}


def test_records_resume_without_duplicates_and_a_torn_line_is_dropped(tmp_path: Path):
    with RecordStore(tmp_path, "aaa", {"what": "test"}, DICT_RECORDS) as store:
        assert store.pending(3) == [0, 1, 2]
        assert store.append([_record(0), _record(1)]) == 2
        assert store.append([_record(1), _record(2), _record(2)]) == 1  # stored once, whatever is offered
    with open(tmp_path / "records.jsonl", "ab") as fh:
        fh.write(b'{"run":"aaa","index":3,"rec')  # torn by a kill
    with RecordStore(tmp_path, "aaa", {}, DICT_RECORDS) as store:
        assert store.completed == {0: _record(0), 1: _record(1), 2: _record(2)}
        assert store.pending(5) == [3, 4]
        store.append([_record(3)])
    lines = (tmp_path / "records.jsonl").read_text().splitlines()
    assert lines[0] == '{"run":"aaa","index":0,"record":{"index":0,"value":0}}'  # the Monte Carlo's format, byte for byte
    assert [json.loads(line)["index"] for line in lines] == [0, 1, 2, 3]  # the torn line is gone
    assert json.loads((tmp_path / "manifest.json").read_text()) == {"fingerprint": "aaa", "what": "test"}


def test_a_damaged_line_is_skipped_and_its_task_recomputed(tmp_path: Path):
    (tmp_path / "manifest.json").write_text('{"fingerprint": "aaa"}')
    good = [json.dumps({"run": "aaa", "index": i, "record": _record(i)}) for i in (0, 2)]
    (tmp_path / "records.jsonl").write_text(f"{good[0]}\n{{not json\n\n{good[1]}\n")
    with RecordStore(tmp_path, "aaa", {}, DICT_RECORDS) as store:
        assert sorted(store.completed) == [0, 2] and store.pending(3) == [1]


def test_a_directory_of_another_run_is_refused_clearly(tmp_path: Path):
    with RecordStore(tmp_path, "aaa", {"name": "first"}, DICT_RECORDS) as store:
        store.append([_record(0)])
    with pytest.raises(ForeignStoreError) as refused:
        RecordStore(tmp_path, "bbb", {}, DICT_RECORDS)
    message = str(refused.value)
    assert str(tmp_path) in message and "fingerprint aaa" in message and "this run bbb" in message
    assert "allowed: the same run (to resume) or an empty directory; choose another -o DIR" in message
    assert refused.value.held == {"fingerprint": "aaa", "name": "first"} and refused.value.path == tmp_path / "manifest.json"
    assert refused.value.fingerprint == "bbb"
    # a record line of another run behind a matching manifest (a file copied in by hand)
    with open(tmp_path / "records.jsonl", "a") as fh:
        fh.write(json.dumps({"run": "ccc", "index": 1, "record": _record(1)}) + "\n")
    with pytest.raises(ForeignStoreError, match="records of another run \\(fingerprint ccc, this run aaa\\)") as line:
        RecordStore(tmp_path, "aaa", {}, DICT_RECORDS)
    assert line.value.path == tmp_path / "records.jsonl"
    # an unreadable manifest is another run's too: nothing is overwritten
    other = tmp_path / "other"
    other.mkdir()
    (other / "manifest.json").write_text("[1, 2")
    with pytest.raises(ForeignStoreError, match="fingerprint \\?"):
        RecordStore(other, "aaa", {}, DICT_RECORDS)
    assert (other / "manifest.json").read_text() == "[1, 2"


@pytest.mark.parametrize("layout", ["records", "own"])
def test_a_record_the_layout_does_not_accept_is_recomputed(tmp_path: Path, layout: str):
    def decode(line: dict[str, Any]) -> dict[str, Any] | None:
        record = line["record"]
        return record if "value" in record else None  # e.g. written by a version that stored less

    own = StoreLayout("run.json", "done.jsonl", "id", DICT_RECORDS.index, DICT_RECORDS.encode, decode)
    chosen = own if layout == "own" else dataclasses.replace(DICT_RECORDS, decode=decode)
    with RecordStore(tmp_path, "aaa", {}, chosen) as store:
        store.append([{"index": 0}, _record(1)])  # index 0 stored without its value
    with RecordStore(tmp_path, "aaa", {}, chosen) as store:
        assert sorted(store.completed) == [1] and store.rejected == 1 and store.pending(2) == [0]
        assert store.append([_record(0)]) == 1  # recomputed and stored again
    with RecordStore(tmp_path, "aaa", {}, chosen) as store:
        assert store.completed == {0: _record(0), 1: _record(1)} and store.rejected == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([chosen.manifest, chosen.records])
    assert json.loads((tmp_path / chosen.records).read_text().splitlines()[0])[chosen.fingerprint_key] == "aaa"


def test_appends_reach_the_file_at_once_and_fsync_is_batched(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    syncs: list[int] = []
    real_fsync = os.fsync
    monkeypatch.setattr(store_module.os, "fsync", lambda fd: (syncs.append(fd), real_fsync(fd))[1])
    store = RecordStore(tmp_path, "aaa", {}, DICT_RECORDS, fsync_interval_s=3600.0)
    for i in range(6):
        store.append([_record(i)])
        # kill safety: what append returned is in the file for any other reader (a resumed run)
        with RecordStore(tmp_path, "aaa", {}, DICT_RECORDS) as reader:
            assert i in reader.completed
    assert syncs == []  # durability against a machine crash is batched ...
    store.close()
    assert len(syncs) == 1  # ... and completed when the store closes
    every = RecordStore(tmp_path / "every", "aaa", {}, DICT_RECORDS, fsync_interval_s=0.0)
    for i in range(3):
        every.append([_record(i)])
    every.close()
    assert len(syncs) == 1 + 3
