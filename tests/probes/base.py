"""The handle of the test-only extension pyadore._probes; statuses checked as pyadore._core does."""

from __future__ import annotations

from pyadore._core.base import _text, check  # noqa: F401  (one status check for both extensions)
from pyadore.errors import AdoreEngineError


def _probes():
    try:
        from pyadore import _probes as probes
    except ImportError as exc:  # installed without the test-only extension (meson option probes)
        raise AdoreEngineError(
            "the test-only extension pyadore._probes is not built: install with `make setup` "
            "(pip install -Csetup-args=-Dprobes=true -e .)"
        ) from exc
    return probes
