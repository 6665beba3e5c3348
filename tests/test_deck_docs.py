"""The schema, its generated documentation and the decks' provenance agree."""

from __future__ import annotations

from pathlib import Path

from pyadore.deck import read_deck
from pyadore.deck.docgen import generate
from pyadore.deck.provenance import DECK_FILES, PROVENANCE, SOURCES
from pyadore.deck.records import RECORDS
from pyadore.deck.schema import check_schema, record_spec

ROOT = Path(__file__).resolve().parents[1]


def test_schema_is_consistent():
    check_schema()
    ids = [s.rid for s in RECORDS]
    assert len(ids) == len(set(ids))
    for spec in RECORDS:
        names = [f.name for f in spec.fields]
        assert len(names) == len(set(names)), spec.rid
        for f in spec.fields:
            assert f.name == f.name.lower() and " " not in f.name
            assert f.unit and f.meaning
            if f.default is not None:
                assert f.kind == "text" or f.in_range(f.default) or f.name.startswith("rec"), (spec.rid, f.name)


def test_checked_in_doc_is_generated():
    assert (ROOT / "docs" / "deck-format.md").read_text() == generate()


def test_doc_mentions_every_record_and_field():
    doc = generate()
    for spec in RECORDS:
        assert f"## Rec {spec.rid}:" in doc
        for f in spec.fields:
            assert f"`{f.name}`" in doc


def test_provenance_covers_every_record_and_names_real_fields():
    for name, rows in PROVENANCE.items():
        deck = read_deck(ROOT / DECK_FILES[name])
        covered = {rid for rid, field, _, _ in rows if field is None}
        for rec in deck.records:
            assert rec.rid in covered or all(
                any(r == rec.rid and f == fname for r, f, _, _ in rows) for fname in rec.fields), (name, rec.rid)
        for rid, field, src, note in rows:
            assert src in SOURCES and note
            rec = deck.record(rid)
            assert rec is not None, (name, rid)
            if field is not None:
                assert field in rec.fields, (name, rid, field)


def test_inferred_values_are_marked():
    """Every record whose listing line is lost is marked echo or inference, never listing."""
    lost = {"appendix_c_ball": {"2.7", "3.1", "3.3"}, "appendix_d_roller": {"4", "5B", "10.0", "10.1B"}}
    for name, rids in lost.items():
        for rid, field, src, _ in PROVENANCE[name]:
            if rid in rids:
                assert src in ("echo", "inference"), (name, rid, field)


def test_unknown_fields_are_named_honestly():
    for spec in RECORDS:
        for f in spec.fields:
            if f.evidence == "unknown":
                assert f.name.startswith("rec") and "unknown" in f.meaning
            assert record_spec(spec.occurrence_id(1)) is spec
