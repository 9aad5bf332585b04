"""Governor types: a registry from ``governor.type`` to the module that models it.

Each module supplies a :class:`~govopt.governors.base.Governor` subclass (its spec schema and the
seam of :mod:`govopt.governors.base`). Adding a type is one module plus one line here; nothing
outside a type's own module branches on the type.
"""

from __future__ import annotations

import importlib

from .base import Governor, Terms

#: governor.type -> "module:Class" (imported when first used, so a CLI run loads only its type)
REGISTRY: dict[str, str] = {
    "shaft": "shaft:ShaftGovernor",
    "watt": "watt:WattGovernor",
    "porter": "porter:PorterGovernor",
    "proell": "proell:ProellGovernor",
    "hartnell": "hartnell:HartnellGovernor",
    "spring_loaded": "spring_loaded:SpringLoadedGovernor",
    "spring_gravity": "spring_gravity:SpringGravityGovernor",
    "traction_coil": "traction_coil:TractionCoilGovernor",
    "traction_leaf": "traction_leaf:TractionLeafGovernor",
    "force_line": "force_line:ForceLineGovernor",
}


def governor_class(type_name: str) -> type[Governor]:
    """The class modelling ``type_name`` (a key of :data:`REGISTRY`), imported when first used.

    Each class states its own method and sources: the shaft governor [hamabe]; the Watt, Porter,
    Proell, Hartnell, spring-loaded and spring-and-gravity governors [textbook-ch3], sections 3.4
    and 3.5; the coil- and leaf-spring traction governors [traction-article].

    Parameters
    ----------
    type_name : str [-]
        The spec's ``governor.type``.

    Returns
    -------
    type [-]
        A :class:`~govopt.governors.base.Governor` subclass (SI inside).

    References
    ----------
    [textbook-ch3] section 3.4(b) for the example below.

    Examples
    --------
    >>> governor_class("porter").title
    'Porter governor (textbook ch. 3, section 3.4(b), Figs. 3.1(b), 3.4-3.7)'
    """
    module, cls = REGISTRY[type_name].split(":")
    return getattr(importlib.import_module(f"{__name__}.{module}"), cls)


__all__ = ["REGISTRY", "Governor", "Terms", "governor_class"]
