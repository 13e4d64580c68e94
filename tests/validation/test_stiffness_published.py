"""Published mesh-stiffness inputs and results that could be opened and cross-checked (docs/stiffness.md,
"Published comparisons").

What this file checks
---------------------
Sainsot, Velex & Duverger (2004), J. Mech. Des. 126:748–752, publish the fitted coefficients (A … F) of the
fillet-foundation factors L*, M*, P*, Q*(h_f, θ_f) as a table; thermogear's copy (``SAINSOT_COEFFICIENTS``) was
transcribed from ROSS (petrobras/ross, gear_element.py). The paper itself could not be opened in this session, so
the table is checked here against a second, independent public transcription: the spur-gear dynamic model of the
PHM laboratory of Ben-Gurion University (public MATLAB code, ``wheelInfo.coeffMtx4FilletStiff``, read with the
search tool's code index; its rows are A … F, its columns L, M, P, Q). Two independent transcriptions that agree
to every printed digit make a typo in thermogear's constants unlikely; a typo here would move the fillet
compliance — the largest single term at the pitch point — directly.

What this file does not check (and why)
---------------------------------------
No table or figure value of a published mesh-stiffness result (Cooley et al. 2016; Kiekbusch et al. 2011;
Tian 2004; Wu et al. 2008; Chaari et al. 2009; Ma et al. 2014) could be read in this session: the stored web pages
of those papers give only their first page, and no public repository quoted their numbers. Inventing or
recalling those numbers would make a test that measures memory, not the code, so none is written here. The
PEM is compared with ISO 6336-1 Method B in tests/validation/test_stiffness_literature.py.
"""

from __future__ import annotations

import pytest

from thermogear.stiffness.fillet_foundation import SAINSOT_COEFFICIENTS

# Independent transcription of Sainsot et al. (2004)'s coefficient table, as printed in the BGU PHM-lab model
# (rows A…F, columns L, M, P, Q), with the powers of ten that code applies to each row.
_BGU_ROWS = {
    "A": ([-5.574, 60.111, -50.952, -6.2042], 1e-5),
    "B": ([-1.9986, 28.100, 185.50, 9.0889], 1e-3),
    "C": ([-2.3015, -83.431, 0.0538, -4.0964], 1e-4),
    "D": ([4.77021, -9.9256, 53.300, 7.8297], 1e-3),
    "E": ([0.0271, 0.1624, 0.2895, -0.1472], 1.0),
    "F": ([6.8045, 0.9086, 0.9236, 0.6904], 1.0),
}
_FACTORS = ("L", "M", "P", "Q")
_CASES = [(factor, row, column) for column, factor in enumerate(_FACTORS) for row in "ABCDEF"]


@pytest.mark.parametrize("factor, row, column", _CASES, ids=[f"{f}*-{r}" for f, r, _ in _CASES])
def test_sainsot_coefficients_match_an_independent_transcription(factor, row, column):
    """Each of the 24 coefficients agrees with the independent copy to the digits both print.

    Tolerance 1e-4 relative: the two copies print 4–6 significant figures (e.g. D for L*: 4.7702e-3 here,
    4.77021e-3 there, 2e-5 apart); a transcription error (a swapped or dropped digit) is ≥ 1e-3 relative."""
    mantissas, scale = _BGU_ROWS[row]
    published = mantissas[column] * scale
    ours = SAINSOT_COEFFICIENTS[factor]["ABCDEF".index(row)]
    assert ours == pytest.approx(published, rel=1e-4, abs=0.0)
