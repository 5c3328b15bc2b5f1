"""The settings table (plugin/render/src/SettingsTable.cpp) from Python.

One table serves the command line, ParaView, the mapper, the explorer and
Python: the same keys (``light-intensity``, spelt ``light_intensity`` as a
keyword argument), ranges and one-line messages, raised as ValueError.
"""

import json
from typing import Any, Dict, List, NamedTuple, Tuple

from .shadinglabRenderVTK import vtkShadingLabSettings


class Setting(NamedTuple):
    """One row of the settings table."""

    key: str  #: the table's key, the command line's flag without "--"
    name: str  #: its keyword-argument spelling (``-`` as ``_``)
    label: str  #: as ParaView shows it
    group: str  #: render, material, lights or mesh
    kind: str  #: choice, real, integer, flag or text
    range: str  #: "[0, 1]", "flat | gouraud | ..."
    default: str  #: as typed on the command line
    metavar: str  #: the command line's name for the value
    doc: str  #: one line
    front_ends: Tuple[str, ...]  #: cli, paraview, mapper, explorer


_ROWS: List[Setting] = []


def settings() -> List[Setting]:
    """The settings table, in the order the front ends list it."""
    if not _ROWS:
        for row in json.loads(vtkShadingLabSettings.GetTableJson()):
            _ROWS.append(
                Setting(
                    key=row["key"],
                    name=row["key"].replace("-", "_"),
                    label=row["label"],
                    group=row["group"],
                    kind=row["kind"],
                    range=row["range"],
                    default=row["default"],
                    metavar=row["metavar"],
                    doc=row["doc"],
                    front_ends=tuple(row["front_ends"]),
                )
            )
    return list(_ROWS)


def _text(value: Any) -> str:
    """A Python value as the table's text: on/off, "a,b,c", a number, a name."""
    if isinstance(value, bool):
        return "on" if value else "off"
    if isinstance(value, (list, tuple)):
        return ",".join(_text(v) for v in value)
    if hasattr(value, "tolist"):  # a NumPy array or scalar
        return _text(value.tolist())
    return repr(value) if isinstance(value, float) else str(value)


def make_settings(**kwargs: Any) -> vtkShadingLabSettings:
    """A vtkShadingLabSettings with ``kwargs`` applied in order.

    Keys are the table's (``mode``, ``ks``, ``light_intensity``, ...); values
    are Python values or the command line's texts. Raises ValueError with
    the table's one-line message for an unknown key or a refused value.
    """
    made = vtkShadingLabSettings()
    apply(made, **kwargs)
    return made


def apply(made: vtkShadingLabSettings, **kwargs: Any) -> None:
    """Applies ``kwargs`` to ``made`` (see make_settings)."""
    for name, value in kwargs.items():
        if value is None:
            continue
        problem = made.Set(name.replace("_", "-"), _text(value))
        if problem:
            raise ValueError(problem)
    problem = made.Validate()
    if problem:
        raise ValueError(problem)


def help_text() -> str:
    """The keyword arguments, as the command line's --help lists its flags."""
    lines = []
    for row in settings():
        lines.append(f"  {row.name:<24} {row.range} (default {row.default or '-'})")
        lines.append(f"      {row.doc}")
    return "\n".join(lines)


def as_dict(made: vtkShadingLabSettings) -> Dict[str, str]:
    """Every setting's value as text, by keyword name."""
    return {row.name: made.Get(row.key) for row in settings()}
