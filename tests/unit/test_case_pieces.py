"""Checks and providers receive the pieces of the case they name (issue 33: only resolvers and entry points take a
whole Case): :func:`thermogear.case.pieces.call_with_pieces` hands each parameter its piece."""

from __future__ import annotations

import pytest

from thermogear import composition
from thermogear.case import Case, load_case
from thermogear.case.pieces import LATER, WHOLE_CASE, call_with_pieces, piece_names

PLUG_INS = [*composition.TEMPERATURE_PROVIDERS.values(), *composition.X_TE_PROVIDERS.values(),
            *composition.DRIVETRAIN_HEAT.values(), *composition.CASE_CHECKS, *composition.TEMPERATURE_MODELS.values(),
            *(target for target, _ in composition.CASE_PIECES.values()), *composition.CHOSEN_PIECES.values()]


@pytest.mark.parametrize("target", PLUG_INS)
def test_every_builtin_plug_in_names_pieces_of_a_case(target):
    import dataclasses

    parts = {field.name for field in dataclasses.fields(Case)} | {
        name for name, value in vars(Case).items() if isinstance(value, property)}
    pieces = parts | set(composition.CASE_PIECES) | set(composition.CHOSEN_PIECES)
    allowed = pieces | {piece + LATER for piece in pieces} | {WHOLE_CASE}
    plug_in = composition.resolve(target)
    # a memoised resolver is called with the case; the function it memoises names its pieces
    assert set(piece_names(getattr(plug_in, "__wrapped__", plug_in))) <= allowed


def test_the_checks_and_providers_take_no_whole_case():
    # only the resolvers (mesh table, the gearbox's temperature model, the piece resolvers) may ask for the case
    takers = [target for target in [*composition.TEMPERATURE_PROVIDERS.values(), *composition.X_TE_PROVIDERS.values(),
                                    *composition.DRIVETRAIN_HEAT.values(), *composition.CASE_CHECKS]
              if WHOLE_CASE in piece_names(composition.resolve(target))]
    assert takers == ["thermogear.mesh.table_file:check_mesh_table"]


def test_each_parameter_receives_its_piece():
    case = load_case("luo2019")
    seen = call_with_pieces(lambda gear_pair, damping, normal_load, case: (gear_pair, damping, normal_load, case),
                            case)
    assert seen == (case.gear_pair, case.damping, case.normal_load, case)
    # a derived piece comes from its resolver; an optional one is None where its section is absent
    from thermogear.lubricant import lubricant_from_case

    assert call_with_pieces(lambda oil: oil, case) is lubricant_from_case(case)
    assert case.gearbox is None and call_with_pieces(lambda gearbox_model: gearbox_model, case) is None


def test_a_parameter_that_names_no_piece_is_refused():
    case = load_case("luo2019")
    with pytest.raises(TypeError, match="'speed' is not a piece of a case"):
        call_with_pieces(lambda speed: speed, case)
    with pytest.raises(TypeError, match="names no piece"):
        call_with_pieces(lambda *pieces: pieces, case)


def test_a_piece_asked_for_later_is_resolved_only_when_asked():
    from thermogear.errors import ThermogearError
    from thermogear.temperature.source import temperature_field_from_case

    case = load_case("luo2019")  # a tabulated field: no provider is chosen, and asking for one is an error
    later = call_with_pieces(lambda provided_temperature_field_of: provided_temperature_field_of, case)
    with pytest.raises(ThermogearError, match="temperature.model = 'tabulated'"):
        later()
    assert call_with_pieces(lambda temperature_field_of: temperature_field_of, case)() is \
        temperature_field_from_case(case)


def test_a_chosen_piece_is_the_answer_of_the_plug_in_its_section_names(monkeypatch):
    # the chooser picks the plug-in by the section's name; the plug-in receives the pieces it names
    import dataclasses
    import types

    from thermogear.temperature import source as temperature_source

    @dataclasses.dataclass(frozen=True)
    class Pieces:
        temperature: object
        material: object

    probe = Pieces(temperature=types.SimpleNamespace(model="probe"), material="steel")
    monkeypatch.setitem(temperature_source._PROVIDERS, "probe", lambda material, temperature: (material,
                                                                                               temperature.model))
    assert call_with_pieces(lambda provided_temperature_field: provided_temperature_field, probe) == ("steel", "probe")
