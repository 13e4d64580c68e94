"""Shafts as segments, and the finite-element nodes of a shaft: segment ends, attachment points, refinement.

A shaft lies along +z from its first end (position 0). Each segment has a length [m], a cross-section and a
material. The nodes are the segment ends and every position where something is attached (gear, disk, bearing,
coupling); each piece between two such points is divided into equal elements no longer than the shaft's
``maximum_element_length`` [m].
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.drivetrain.section import CrossSection, Material
from thermogear.drivetrain.shaft_element import ShaftElement
from thermogear.errors import CaseError

__all__ = ["ShaftSegment", "Shaft", "shaft_mesh"]

_POSITION_TOLERANCE = 1e-9  # [m]: two points closer than this are one node (far below any machining tolerance)


@dataclass(frozen=True)
class ShaftSegment:
    """A uniform piece of shaft: length [m], section (outer, inner diameter [m]) and material."""

    length: float
    section: CrossSection
    material: Material

    def __post_init__(self) -> None:
        if not math.isfinite(float(self.length)) or self.length <= 0.0:
            raise CaseError("segment.length", self.length, "> 0 m", "a shaft segment needs a positive length")


@dataclass(frozen=True)
class Shaft:
    """A shaft: name, segments from its first end, the element length limit [m] and the element options.

    ``shear_coefficient`` None takes Cowper's κ per segment; ``shear_deformation`` False gives Euler–Bernoulli
    elements; ``rotary_inertia`` False drops rotary and spin inertia of the shaft (not of disks).
    ``material_damping`` β [s] adds stiffness-proportional damping β·K_shaft (internal damping of the shaft
    material; it damps every elastic mode of the shaft, ζ = βω/2, and leaves rigid motions free).
    """

    name: str
    segments: tuple[ShaftSegment, ...]
    maximum_element_length: float
    shear_coefficient: float | None = None
    shear_deformation: bool = True
    rotary_inertia: bool = True
    material_damping: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "segments", tuple(self.segments))
        if not math.isfinite(float(self.material_damping)) or self.material_damping < 0.0:
            raise CaseError(f"{self.name}.material_damping", self.material_damping, ">= 0 s",
                            "stiffness-proportional damping β must not inject energy")
        if not self.segments:
            raise CaseError(f"{self.name}.segments", [], "at least one segment", "a shaft needs a length")
        if not math.isfinite(float(self.maximum_element_length)) or self.maximum_element_length <= 0.0:
            raise CaseError(f"{self.name}.maximum_element_length", self.maximum_element_length, "> 0 m",
                            "the element length limit sets the mesh refinement")

    @property
    def length(self) -> float:
        """Total length [m]."""
        return float(sum(segment.length for segment in self.segments))

    @property
    def segment_ends(self) -> np.ndarray:
        """Positions [m] of the segment boundaries, from 0 to the length."""
        return np.concatenate([[0.0], np.cumsum([segment.length for segment in self.segments])])


def _merged(points: np.ndarray) -> np.ndarray:
    points = np.sort(points)
    keep = np.concatenate([[True], np.diff(points) > _POSITION_TOLERANCE])
    return points[keep]


def shaft_mesh(shaft: Shaft, attachments: list[float]) -> tuple[np.ndarray, list[ShaftElement]]:
    """Node positions [m] (ascending) and the elements between consecutive nodes of one shaft."""
    ends = shaft.segment_ends
    for position in attachments:
        if position > ends[-1] + _POSITION_TOLERANCE:
            raise CaseError(f"{shaft.name}.position", position, f"[0, {ends[-1]:.6g}] m",
                            "an attachment must lie on the shaft")
    breaks = _merged(np.concatenate([ends, np.asarray(attachments, dtype=float)]))
    nodes = [breaks[0]]
    for start, stop in zip(breaks[:-1], breaks[1:]):
        count = max(1, math.ceil((stop - start) / shaft.maximum_element_length - 1e-9))
        nodes.extend(np.linspace(start, stop, count + 1)[1:])
    nodes = np.array(nodes)
    elements = []
    for start, stop in zip(nodes[:-1], nodes[1:]):
        index = min(int(np.searchsorted(ends, 0.5 * (start + stop))) - 1, len(shaft.segments) - 1)
        segment = shaft.segments[max(index, 0)]
        elements.append(ShaftElement(stop - start, segment.section, segment.material, shaft.shear_coefficient,
                                     shaft.shear_deformation, shaft.rotary_inertia))
    return nodes, elements


def node_index(nodes: np.ndarray, shaft: str, position: float) -> int:
    """Index of the node at a position [m] of a shaft (its attachments are nodes by construction)."""
    index = int(np.argmin(np.abs(nodes - position)))
    if abs(nodes[index] - position) > _POSITION_TOLERANCE:
        raise CaseError(f"{shaft}.position", position, "a node of the shaft", "attachments are nodes")
    return index
