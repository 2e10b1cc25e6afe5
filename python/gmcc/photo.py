"""The photo layer (gmcc/photo/; docs/architecture.md "Layers", docs/photographs.md): canonical
gamuts learned from images with measured lights (2-D and 3-D), and 3-D gamut mapping on pixel
colours with max-volume, centroid and max-trace (Forsyth 1990 §3).

Everything here is the extension's, re-exported as it is (signatures, defaults and docstrings in
python/src/).
"""

from __future__ import annotations

from ._core import (  # noqa: F401  (re-exported)
    Canonical3,
    CanonicalLearner2,
    CanonicalLearner3,
    Estimate3,
    ImageSelection3,
    estimate_3d,
    prepare_canonical_3d,
)

__all__ = ["Canonical3", "CanonicalLearner2", "CanonicalLearner3", "Estimate3", "ImageSelection3",
           "prepare_canonical_3d", "estimate_3d"]
