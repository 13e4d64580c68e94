"""References of the methods thermogear uses, and a registry of the ones a run actually used.

Each method registers its source with :func:`cite` when it is used; a report ends with :func:`citations_used`.
The table below holds the full references; a key not in it is refused (a typo must not silently drop a source).
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Reference", "REFERENCES", "cite", "cited_in", "citations_used", "clear_citations", "reference"]


@dataclass(frozen=True)
class Reference:
    """One bibliographic reference."""

    key: str
    text: str
    doi: str = ""
    used_for: str = ""

    def formatted(self) -> str:
        """The reference as one line of text (with its DOI where it has one)."""
        return f"{self.text} doi:{self.doi}" if self.doi else self.text


_TABLE: tuple[Reference, ...] = (
    Reference("luo2020", "B. Luo, W. Li, Investigation on the influence of heat on the dynamic characteristics of a "
              "gear transmission system, Engineering Failure Analysis 108 (2020) 104724.",
              "10.1016/j.engfailanal.2020.104724",
              "thermal mesh stiffness (Eqs. 7-23), space-time mapping (Eqs. 24-25), friction damping (Eqs. 26-28), "
              "dynamic load factor (Eq. 29), the luo2019 case"),
    Reference("iso6336_1", "ISO 6336-1:2019, Calculation of load capacity of spur and helical gears - Part 1: Basic "
              "principles, introduction and general influence factors. International Organization for "
              "Standardization, Geneva, 2019.", "", "single-stiffness and mesh-stiffness cross-check (Method B)"),
    Reference("iso_tr13989_1", "ISO/TR 13989-1:2000, Calculation of scuffing load capacity of cylindrical, bevel and "
              "hypoid gears - Part 1: Flash temperature method; and DIN 3990-4:1987, Tragfähigkeitsberechnung von "
              "Stirnrädern - Teil 4: Berechnung der Freßtragfähigkeit.", "", "mean coefficient of friction (Eq. 27)"),
    Reference("astm_d341", "ASTM D341-20, Standard Practice for Viscosity-Temperature Equations and Charts for "
              "Liquid Petroleum or Hydrocarbon Products. ASTM International, West Conshohocken, 2020.", "",
              "viscosity-temperature law of the lubricant (Walther)"),
    Reference("sainsot2004", "P. Sainsot, P. Velex, O. Duverger, Contribution of gear body to tooth deflections - a "
              "new bidimensional analytical formula, Journal of Mechanical Design 126 (2004) 748-752.",
              "10.1115/1.1758252", "fillet-foundation compliance"),
    Reference("yang1987", "D.C.H. Yang, J.Y. Lin, Hertzian damping, tooth friction and bending elasticity in gear "
              "impact dynamics, Journal of Mechanisms, Transmissions, and Automation in Design 109 (1987) 189-196.",
              "10.1115/1.3267437", "potential energy method: bending and Hertzian contact energy"),
    Reference("tian2004", "X. Tian, Dynamic simulation for system response of gearbox including localized gear "
              "faults, MSc thesis, University of Alberta, Edmonton, 2004.", "",
              "potential energy method: bending, shear and axial compressive compliance of the tooth"),
    Reference("chaari2009", "F. Chaari, T. Fakhfakh, M. Haddar, Analytical modelling of spur gear tooth crack and "
              "influence on gearmesh stiffness, European Journal of Mechanics A/Solids 28 (2009) 461-468.",
              "10.1016/j.euromechsol.2008.07.007", "tooth as a non-uniform cantilever, mesh stiffness over the cycle"),
    Reference("timoshenko1951", "S. Timoshenko, J.N. Goodier, Theory of Elasticity, 2nd ed., McGraw-Hill, New York, "
              "1951.", "", "thermal expansion of a disc (base-circle expansion of Eq. 10), plane elasticity"),
    Reference("blok1937", "H. Blok, Theoretical study of temperature rise at surfaces of actual contact under oiliness "
              "lubricating conditions, Proceedings of the General Discussion on Lubrication and Lubricants, "
              "Institution of Mechanical Engineers, London, 1937, Vol. 2, pp. 222-235.", "",
              "flash temperature of sliding contacts"),
    Reference("iso14635_1", "ISO 14635-1:2000, Gears - FZG test procedures - Part 1: FZG test method A/8,3/90 for "
              "relative scuffing load-carrying capacity of oils. International Organization for Standardization, "
              "Geneva, 2000.", "", "FZG type C/A test gears and load stages (fzg_type_c case)"),
    Reference("den_hartog1931", "J.P. Den Hartog, Forced vibrations with combined Coulomb and viscous friction, "
              "Transactions of the ASME 53 (1931) APM-53-9, 107-115.", "",
              "equivalent viscous damping of Coulomb friction (Eq. 26)"),
    Reference("floquet1883", "G. Floquet, Sur les équations différentielles linéaires à coefficients périodiques, "
              "Annales scientifiques de l'École Normale Supérieure 12 (1883) 47-88.", "10.24033/asens.220",
              "periodic steady state and stability from the monodromy matrix"),
    Reference("rk4", "E. Hairer, S.P. Nørsett, G. Wanner, Solving Ordinary Differential Equations I: Nonstiff "
              "Problems, 2nd ed., Springer, Berlin, 1993.", "10.1007/978-3-540-78862-1",
              "fixed-step Runge-Kutta integration of the start-up transient"),
    Reference("iso21771", "ISO 21771:2007, Gears - Cylindrical involute gears and gear pairs - Concepts and geometry. "
              "International Organization for Standardization, Geneva, 2007.", "", "involute gear-pair geometry"),
    Reference("iso53", "ISO 53:1998, Cylindrical gears for general and heavy engineering - Standard basic rack tooth "
              "profile. International Organization for Standardization, Geneva, 1998.", "", "basic rack profile"),
    Reference("scikit_fem", "T. Gustafsson, G.D. McBain, scikit-fem: A Python package for finite element assembly, "
              "Journal of Open Source Software 5 (52) (2020) 2369.", "10.21105/joss.02369",
              "finite-element verification"),
    Reference("fernandes_gearpie", "C.M.C.G. Fernandes, GEARpie: gear power loss and efficiency calculation "
              "(software, GEAR_LIBRARY C14 gear data). https://github.com/CarlosFernandes/GEARpie", "",
              "FZG type C gear data"),
)

#: Every known reference by key.
REFERENCES: dict[str, Reference] = {ref.key: ref for ref in _TABLE}

_used: dict[str, None] = {}  # insertion-ordered set of the keys used in this process


def reference(key: str) -> Reference:
    """The full reference of ``key``; an unknown key raises ``KeyError`` naming the closest known one."""
    try:
        return REFERENCES[key]
    except KeyError:
        from thermogear.errors import closest_key

        suggestion = closest_key(key, list(REFERENCES))
        hint = f" (did you mean '{suggestion}'?)" if suggestion else ""
        raise KeyError(f"unknown reference key '{key}'{hint}") from None


def cited_in(text: str | None, key: str) -> bool:
    """True when ``text`` (a case's ``[case] citation``) names the reference ``key`` by its DOI (DOIs compare
    without regard to case, as the DOI Handbook §2.4 specifies). A reference without a DOI is never recognised
    in a text: a title or an author list is too easily quoted by a case that is not that source's data."""
    doi = reference(key).doi
    return bool(doi) and bool(text) and doi.lower() in str(text).lower()


def cite(*keys: str) -> None:
    """Register that the running computation uses the methods of ``keys`` (order of first use is kept)."""
    for key in keys:
        reference(key)
        _used.setdefault(key, None)


def citations_used() -> list[Reference]:
    """The references registered by :func:`cite` since the last :func:`clear_citations`, in order of first use."""
    return [REFERENCES[key] for key in _used]


def clear_citations() -> None:
    """Forget the registered references (start of a new run)."""
    _used.clear()
