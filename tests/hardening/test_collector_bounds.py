"""Opening document after document must not let the frozen heap grow without end: each new
document moves the memory baseline, so after ``ANALYSES`` analyses without a collection one is
due at the next quiet moment whatever the growth says."""

from __future__ import annotations

import gc

from cncmacro.lsp.collector import ANALYSES, Collector


def test_a_clean_up_is_due_after_many_new_documents_and_resets_after_it() -> None:
    was_enabled = gc.isenabled()
    c = Collector()
    try:
        for _ in range(ANALYSES - 1):
            c.settle(new_documents=True)
        c.baseline = 1 << 62  # growth alone would never call for a clean-up
        assert not c.due()
        c.settle(new_documents=True)
        c.baseline = 1 << 62
        assert c.due()
        c.clean()
        c.baseline = 1 << 62
        assert not c.due()
    finally:
        gc.unfreeze()
        if was_enabled:
            gc.enable()
